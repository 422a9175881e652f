// Sensitivities checked against central finite differences of full re-solves, the adjoint
// against the direct mode, weakly active rows against one-sided differences, and the
// promise that no sensitivity solve factorizes anything.
#include "base/errors.h"
#include "constraints/contact/node_to_segment.h"
#include "constraints/contact/obstacle.h"
#include "feti/feti_problem.h"
#include "membrane_model.h"
#include "sens/sensitivity.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <functional>

namespace ffeti {
namespace {

}  // namespace

/// Shown by GoogleTest for a failing case (instead of a byte dump); found by ADL.
void PrintTo(FetiVariant variant, std::ostream* os) { *os << (variant == FetiVariant::feti1 ? "feti1" : "tfeti"); }

namespace {

using test::tight;

double norm(const std::vector<Vec>& u) {
  double sq = 0;
  for (const Vec& us : u) sq += us.squaredNorm();
  return std::sqrt(sq);
}

double relative_difference(const std::vector<Vec>& a, const std::vector<Vec>& b) {
  double sq = 0;
  for (size_t s = 0; s < a.size(); ++s) sq += (a[s] - b[s]).squaredNorm();
  return std::sqrt(sq) / norm(b);
}

std::vector<Vec> central_difference(const std::function<std::vector<Vec>(double)>& solve, double h) {
  const std::vector<Vec> plus = solve(h), minus = solve(-h);
  std::vector<Vec> d;
  for (size_t s = 0; s < plus.size(); ++s) d.push_back((plus[s] - minus[s]) / (2 * h));
  return d;
}

double dot(const std::vector<Vec>& a, const std::vector<Vec>& b) {
  double value = 0;
  for (size_t s = 0; s < a.size(); ++s) value += a[s].dot(b[s]);
  return value;
}

// ---- scalar membranes (FETI-1, body 1 floating): stiffness and load depend on alpha -----

/// Design alpha: K_s(alpha) = (1 + alpha w_s) K_s, f_s(alpha) = (1 + alpha v_s) f_s.
struct MembraneDesign {
  std::vector<SubdomainInput> base = test::membrane_subdomains(test::membrane_options(16, 2));
  std::vector<double> w, v;
  MembraneDesign() {
    for (size_t s = 0; s < base.size(); ++s) {
      w.push_back(0.3 + 0.1 * static_cast<double>(s));
      v.push_back(s % 3 == 0 ? 0.5 : -0.2);
    }
  }
  std::vector<SubdomainInput> at(double alpha) const {
    auto subs = base;
    for (size_t s = 0; s < subs.size(); ++s) {
      subs[s].K.edit() *= 1 + alpha * w[s];
      subs[s].f *= 1 + alpha * v[s];
    }
    return subs;
  }
  DesignDerivative derivative() const {
    DesignDerivative d;
    for (size_t s = 0; s < base.size(); ++s) {
      d.dK.push_back(base[s].K.get() * w[s]);
      d.df.push_back(base[s].f * v[s]);
    }
    return d;
  }
};

FetiProblem membrane_problem(std::vector<SubdomainInput> subs, FetiVariant variant) {
  const ContactInput contact = test::membrane_contact(subs);
  FetiSetupSettings setup;
  setup.variant = variant;
  return FetiProblem(std::move(subs), contact, setup);
}

class MembraneSensitivity : public ::testing::TestWithParam<FetiVariant> {};

TEST_P(MembraneSensitivity, DirectMatchesFiniteDifferencesAndAdjointMatchesDirect) {
  const MembraneDesign design;
  const double alpha = 0.1;
  const auto state_subs = design.at(alpha);
  const FetiProblem problem = membrane_problem(state_subs, GetParam());
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  const long factorizations = CholmodFactor::factorizations_in_process();

  SensitivityProblem sensitivity(problem, state, 1e-8);
  EXPECT_GT(sensitivity.classification().strong.size(), 10u);
  EXPECT_TRUE(sensitivity.classification().weak.empty());
  EXPECT_EQ(sensitivity.path(), DualPath::projected_cg);  // no weak row: equality constrained
  const SensitivityResult direct = sensitivity.direct(design.derivative(), tight());
  ASSERT_EQ(direct.status, SolveStatus::converged);
  EXPECT_LT(direct.kkt.max(), 1e-8);

  const auto fd = central_difference([&](double h) {
    return membrane_problem(design.at(alpha + h), GetParam()).solve(tight()).u;
  }, 1e-5);
  EXPECT_LT(relative_difference(direct.z, fd), 1e-6);

  // J(u) = g'u for a fixed weight g: the adjoint's g'z equals the direct one.
  std::vector<Vec> g;
  for (size_t s = 0; s < state.u.size(); ++s) g.push_back(Vec::LinSpaced(state.u[s].size(), 1.0, 2.0 + double(s)));
  const long after_finite_differences = CholmodFactor::factorizations_in_process();
  const AdjointResult adjoint = sensitivity.adjoint(g, tight());
  ASSERT_EQ(adjoint.status, SolveStatus::converged);
  const double through_adjoint = sensitivity.adjoint_gradient(design.derivative());
  const double through_direct = dot(g, direct.z);
  EXPECT_NEAR(through_adjoint, through_direct, 1e-8 * std::abs(through_direct));
  // The set-up factorized each subdomain once; the sensitivity and adjoint solves none.
  EXPECT_EQ(problem.factorizations(), problem.subdomain_count());
  EXPECT_EQ(after_finite_differences, factorizations + 2 * problem.subdomain_count());
  EXPECT_EQ(CholmodFactor::factorizations_in_process(), after_finite_differences);
}

TEST_P(MembraneSensitivity, BlockOfDirectionsMatchesOneByOne) {
  const MembraneDesign design;
  const FetiProblem problem = membrane_problem(design.at(0.1), GetParam());
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  std::vector<DesignDerivative> directions(3, design.derivative());
  directions[1].dK.clear();                                  // load only
  directions[2].df.clear();                                  // stiffness only
  for (SparseMatrix& dK : directions[2].dK) dK *= -2.5;
  SensitivityProblem one_by_one(problem, state, 1e-8), block(problem, state, 1e-8);
  const long factorizations = CholmodFactor::factorizations_in_process();
  const std::vector<SensitivityResult> together = block.direct(directions, tight());
  ASSERT_EQ(together.size(), directions.size());
  for (size_t j = 0; j < directions.size(); ++j) {
    const SensitivityResult alone = one_by_one.direct(directions[j], tight());
    ASSERT_EQ(together[j].status, SolveStatus::converged) << "direction " << j;
    EXPECT_EQ(together[j].counts.hessian, alone.counts.hessian) << "direction " << j;
    EXPECT_LT(relative_difference(together[j].z, alone.z), 1e-12) << "direction " << j;
    EXPECT_LT(together[j].kkt.max(), 1e-8) << "direction " << j;
  }
  EXPECT_EQ(block.counters().directions, 3);
  EXPECT_EQ(CholmodFactor::factorizations_in_process(), factorizations);
}

INSTANTIATE_TEST_SUITE_P(Variants, MembraneSensitivity, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

// ---- weakly active rows: bodies touching with zero gap and zero load ------------------

TEST(Sensitivity, WeaklyActiveRowsStayInequalitiesAndMatchOneSidedDifferences) {
  test::MembraneOptions o = test::membrane_options(8, 1);
  o.fix_right_body = true;  // coercive: both bodies fixed at their far ends
  auto base = test::membrane_subdomains(o);
  for (auto& s : base) s.f.setZero();  // u = 0, lambda = 0, every contact row weakly active
  const FetiProblem problem = membrane_problem(base, FetiVariant::feti1);
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  SensitivityProblem sensitivity(problem, state, 1e-8);
  EXPECT_TRUE(sensitivity.classification().strong.empty());
  EXPECT_EQ(sensitivity.classification().weak.size(), 9u);
  EXPECT_EQ(sensitivity.path(), DualPath::mprgp);

  // f(alpha) = alpha p with p pushing the bodies into each other: u(alpha) = alpha u(1)
  // for alpha > 0, the unconstrained -alpha u_free(1)... for alpha < 0.
  for (const double sign : {1.0, -1.0}) {
    DesignDerivative d;
    for (const auto& s : base) {
      Vec p = Vec::Constant(s.K.rows(), s.body == 0 ? 1.0 : -1.0);
      d.df.push_back(sign * p);
    }
    const SensitivityResult z = sensitivity.direct(d, tight());
    ASSERT_EQ(z.status, SolveStatus::converged);
    const double h = 1e-3;
    auto pushed = base;
    for (size_t s = 0; s < pushed.size(); ++s) pushed[s].f = h * d.df[s];
    const std::vector<Vec> u = membrane_problem(pushed, FetiVariant::feti1).solve(tight()).u;
    std::vector<Vec> one_sided;
    for (const Vec& us : u) one_sided.push_back(us / h);
    EXPECT_LT(relative_difference(z.z, one_sided), 1e-8) << "sign " << sign;
  }
  std::vector<Vec> g;
  for (const auto& s : base) g.push_back(Vec::Ones(s.K.rows()));
  EXPECT_EQ(sensitivity.adjoint(g, tight()).status, SolveStatus::weakly_active);
  EXPECT_THROW(sensitivity.adjoint_gradient(DesignDerivative{}), InputError);
}

// Both membranes held at y = 0 and y = 1 under one uniform load (body 1 a million times
// stiffer, its load as much larger): u = f y (1 - y) / 4 in each whatever x, so every contact
// row on x = 1 has zero gap and zero force while u is not 0. The gluing of 3 x 3 subdomains
// per body leaves round-off in the gaps: 5e-11 of max |u| at tol 1e-12 (the solve then
// stagnates at round-off), and with the threshold 10 tol 9 of the 11 rows were classified
// inactive, so a derivative pushing the bodies together came out as if they did not touch;
// at tol 1e-6 and 1e-9 all 11 were weak.
TEST(Sensitivity, WeaklyActiveRowsOfALoadedStateAreFoundAtEveryTolerance) {
  test::MembraneOptions o = test::membrane_options(12, 3);
  auto base = test::membrane_subdomains(o);
  for (auto& sub : base) {
    sub.dirichlet_dofs.clear();
    for (int k = 0; k < static_cast<int>(sub.y.size()); ++k)
      if (sub.y[k] == 0.0 || std::abs(sub.y[k] - 1.0) < 1e-12) sub.dirichlet_dofs.push_back(k);
    const double x0 = *std::min_element(sub.x.begin(), sub.x.end()), y0 = *std::min_element(sub.y.begin(), sub.y.end());
    const SubdomainInput uniform =
        test::p1_rectangle(x0, y0, 1.0 / 3, 1.0 / 3, 4, 4, 2.0, [](double, double) { return 1.0; }, sub.body);
    sub.f = uniform.f;  // the same nodes in the same order: p1_rectangle numbers them alike
  }
  for (auto& sub : base)
    if (sub.body == 1) {  // a million times stiffer and loaded as much: the same u, more round-off in the gaps
      sub.K = SharedMatrix(SparseMatrix(1e6 * sub.K.get()), "K");
      sub.f *= 1e6;
    }
  const FetiProblem problem = membrane_problem(base, FetiVariant::feti1);
  // The closing direction (every free row's gap shrinking: dgap = -1; the rows of the held
  // nodes at y = 0, 1 keep theirs) against a forward difference of re-solves with those gaps
  // at -h: one-sided, and exact to round-off, the contact set staying all closed. Classified
  // inactive, the rows once gave z = 0 here (1.4e-3 by the differences).
  DesignDerivative closing;
  ContactInput closed = test::membrane_contact(base);
  for (const SubdomainInput& sub : base) {
    closing.dgap.emplace_back(sub.x.size(), 0.0);
    closed.gap_field.emplace_back(sub.x.size(), 0.0);
    for (size_t i = 0; i < sub.y.size(); ++i)
      if (sub.y[i] > 1e-12 && sub.y[i] < 1 - 1e-12) closing.dgap.back()[i] = -1.0, closed.gap_field.back()[i] = -1e-4;
  }
  DualSolveSettings near = tight();
  near.tolerance = 1e-10;  // the differences' error 1e-10 / h, far below the check; 1e-12 took seconds here
  const FetiResult shifted = FetiProblem(base, closed, {}).solve(near), at_rest = problem.solve(near);
  ASSERT_TRUE(shifted.status == SolveStatus::converged || shifted.status == SolveStatus::stagnated);
  ASSERT_TRUE(at_rest.status == SolveStatus::converged || at_rest.status == SolveStatus::stagnated);
  for (const double tol : {1e-6, 1e-9, 1e-12}) {
    DualSolveSettings settings = tight();
    settings.tolerance = tol;
    const FetiResult state = problem.solve(settings);
    ASSERT_TRUE(state.status == SolveStatus::converged || state.status == SolveStatus::stagnated) << "tol " << tol;
    SensitivityProblem sensitivity(problem, state, default_classification_threshold(tol));
    EXPECT_EQ(sensitivity.classification().weak.size(), 11u) << "tol " << tol;  // 13 nodes, 2 held by y = 0, 1
    EXPECT_TRUE(sensitivity.classification().strong.empty()) << "tol " << tol;
    const SensitivityResult z = sensitivity.direct(closing, near);
    double error = 0, scale = 0;
    for (size_t k = 0; k < z.z.size(); ++k) {
      const Vec fd = (shifted.u[k] - at_rest.u[k]) / 1e-4;
      error = std::max(error, (fd - z.z[k]).cwiseAbs().maxCoeff());
      scale = std::max(scale, fd.cwiseAbs().maxCoeff());
    }
    EXPECT_GT(scale, 0) << "tol " << tol;
    EXPECT_LT(error, 1e-4 * scale) << "tol " << tol << ": the closing derivative against the differences";
  }
}

// ---- moving contact geometry: node to segment on non-matching meshes, and an obstacle ---

/// Body 0 = [0,1]^2 fixed at y = 0 (8 x 8 cells); body 1 = [0.05,0.95] x [1.02, 2.02]
/// (5 x 7 cells, non-matching) pressed down by u = (0, -0.05) at its top; body 1's bottom
/// nodes are slaves on body 0's top segments. Node velocities tilt body 0's top face.
struct SegmentScene {
  std::vector<SubdomainInput> base;
  ContactInput contact;
  SegmentScene() {
    const auto zero = [](double, double) { return 0.0; };
    base.push_back(test::two_components(test::p1_rectangle(0, 0, 1, 1, 8, 8, 1.0, zero, 0)));
    base.push_back(test::two_components(test::p1_rectangle(0.05, 1.02, 0.9, 1, 5, 7, 1.0, zero, 1)));
    for (size_t s = 0; s < 2; ++s) {
      SubdomainInput& sub = base[s];
      for (int k = 0; k < static_cast<int>(sub.x.size()); ++k) {
        const bool bottom = s == 0 && sub.y[k] < 1e-12, top = s == 1 && sub.y[k] > 2.02 - 1e-12;
        if (bottom || top) {
          sub.dirichlet_dofs.push_back(k);
          sub.dirichlet_values.push_back(top && sub.component[k] == 1 ? -0.05 : 0.0);
        }
      }
      sub.f = Vec::Constant(sub.K.rows(), 0.01);  // a small body load everywhere
    }
    contact.slave_dofs.resize(2), contact.input_of<NodeToSegmentInput>().segments.resize(2);
    for (int k = 0; k < static_cast<int>(base[1].x.size()); ++k)
      if (base[1].y[k] < 1.02 + 1e-12) contact.slave_dofs[1].push_back(k);
    // Body 0's top edge, nodes 2(72+i), left to right: the body lies below, on the right
    // of a -> b, so segments run right to left to keep it on the left.
    for (int i = 8; i > 0; --i) {
      const int b = 72 + i - 1, a = 72 + i;
      contact.input_of<NodeToSegmentInput>().segments[0].push_back({2 * a, 2 * a + 1, 2 * b, 2 * b + 1});
    }
  }
  /// Node velocity of the design: body 0's top face tilts, V = (0.02 y, 0.1 x y).
  std::vector<std::vector<double>> velocity(int component) const {
    std::vector<std::vector<double>> v(2);
    for (size_t k = 0; k < base[0].x.size(); ++k)
      v[0].push_back(component == 0 ? 0.02 * base[0].y[k] : 0.1 * base[0].x[k] * base[0].y[k]);
    v[1].assign(base[1].x.size(), 0.0);
    return v;
  }
  std::vector<SubdomainInput> at(double t) const {
    auto subs = base;
    const auto vx = velocity(0), vy = velocity(1);
    for (size_t s = 0; s < subs.size(); ++s)
      for (size_t k = 0; k < subs[s].x.size(); ++k) subs[s].x[k] += t * vx[s][k], subs[s].y[k] += t * vy[s][k];
    return subs;
  }
};

/// Direct z of a moving-geometry direction (no weakly active row) against central
/// differences, step 1e-5, of the solutions `solve_at(t)` of the moved scenes.
SensitivityResult expect_direct_matches_finite_differences(SensitivityProblem& sensitivity, const DesignDerivative& d,
                                                           const std::function<std::vector<Vec>(double)>& solve_at) {
  EXPECT_TRUE(sensitivity.classification().weak.empty());
  SensitivityResult z = sensitivity.direct(d, tight());
  EXPECT_EQ(z.status, SolveStatus::converged);
  EXPECT_LT(relative_difference(z.z, central_difference(solve_at, 1e-5)), 1e-5);
  return z;
}

class SegmentSensitivity : public ::testing::TestWithParam<FetiVariant> {};

TEST_P(SegmentSensitivity, MovingMasterFaceMatchesFiniteDifferences) {
  const SegmentScene scene;
  FetiSetupSettings setup;
  setup.variant = GetParam();
  const auto solve_at = [&](double t) {
    return FetiProblem(scene.at(t), scene.contact, setup).solve(tight());
  };
  const FetiProblem problem(scene.at(0), scene.contact, setup);
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  SensitivityProblem sensitivity(problem, state, 1e-8);
  ASSERT_GT(sensitivity.classification().strong.size(), 3u);
  DesignDerivative d;
  d.velocity_x = scene.velocity(0), d.velocity_y = scene.velocity(1);
  const SensitivityResult z = expect_direct_matches_finite_differences(
      sensitivity, d, [&](double t) { return solve_at(t).u; });

  std::vector<Vec> g;
  for (const Vec& us : state.u) g.push_back(Vec::LinSpaced(us.size(), -1.0, 1.0));
  ASSERT_EQ(sensitivity.adjoint(g, tight()).status, SolveStatus::converged);
  EXPECT_NEAR(sensitivity.adjoint_gradient(d), dot(g, z.z), 1e-8 * std::abs(dot(g, z.z)));
}

TEST(Sensitivity, MovingRowWithoutTheVelocityOfOneOfItsSubdomainsIsRefused) {
  // The master face moves, but the slave body's subdomain gets no velocity array: a script
  // that forgot it would get a silently wrong gradient; zeros there are accepted.
  const SegmentScene scene;
  const FetiProblem problem(scene.at(0), scene.contact);
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  SensitivityProblem sensitivity(problem, state, 1e-8);
  DesignDerivative d;
  d.velocity_x = scene.velocity(0), d.velocity_y = scene.velocity(1);
  EXPECT_EQ(sensitivity.direct(d, tight()).status, SolveStatus::converged);  // zeros on body 1: fine
  d.velocity_x[1].clear(), d.velocity_y[1].clear();
  try {
    sensitivity.direct(d, tight());
    ADD_FAILURE() << "a moving row without its slave subdomain's velocity was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("velocityX, velocityY"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("subdomain 1"), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, SegmentSensitivity, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

TEST(Sensitivity, MovingObstacleSlavesMatchFiniteDifferences) {
  // Body 1 of the segment scene alone on a tilted rigid obstacle below it; the design
  // moves the slave nodes (and so the gaps) with V = (0, 0.3 x).
  const SegmentScene scene;
  std::vector<SubdomainInput> base = {scene.base[1]};
  base[0].body = 0;
  base[0].f.setConstant(-0.01);  // pressed onto the obstacle
  ContactInput contact;
  contact.slave_dofs = {scene.contact.slave_dofs[1]};
  contact.input_of<ObstacleInput>().given = true;
  contact.input_of<ObstacleInput>().point = {0.0, 0.99};
  contact.input_of<ObstacleInput>().normal = {0.1, 1.0};
  const auto velocity = [&](int c) {
    std::vector<std::vector<double>> v(1);
    for (size_t k = 0; k < base[0].x.size(); ++k) v[0].push_back(c == 0 ? 0.0 : 0.3 * base[0].x[k]);
    return v;
  };
  const auto at = [&](double t) {
    auto subs = base;
    for (size_t k = 0; k < subs[0].y.size(); ++k) subs[0].y[k] += t * velocity(1)[0][k];
    return subs;
  };
  const FetiProblem problem(at(0), contact);
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  SensitivityProblem sensitivity(problem, state, 1e-8);
  ASSERT_GT(sensitivity.classification().strong.size(), 0u);
  DesignDerivative d;
  d.velocity_x = velocity(0), d.velocity_y = velocity(1);
  expect_direct_matches_finite_differences(sensitivity, d,
                                           [&](double t) { return FetiProblem(at(t), contact).solve(tight()).u; });
}

// ---- classification and bad input -------------------------------------------------------

TEST(Sensitivity, ClassificationThresholdIsRelativeToTheMultipliersScale) {
  const MembraneDesign design;
  const FetiProblem problem = membrane_problem(design.at(0), FetiVariant::feti1);
  const FetiResult state = problem.solve(tight());
  const ContactClassification c = classify_contact(problem, state, 1e-8);
  // The same cut with all loads scaled by 1e6: multipliers scale, the sets do not.
  auto scaled = design.at(0);
  for (auto& s : scaled) s.f *= 1e6;
  const FetiProblem big = membrane_problem(scaled, FetiVariant::feti1);
  const ContactClassification c_big = classify_contact(big, big.solve(tight()), 1e-8);
  EXPECT_EQ(c.strong, c_big.strong);
  EXPECT_EQ(c.inactive, c_big.inactive);
  EXPECT_NEAR(c_big.lambda_scale, 1e6 * c.lambda_scale, 1e-6 * c_big.lambda_scale);
  // A threshold above a row's relative multiplier moves it out of the strong set.
  double smallest = INFINITY;
  for (int i : c.strong) smallest = std::min(smallest, state.lambda[i] / c.lambda_scale);
  const ContactClassification coarser = classify_contact(problem, state, 1.01 * smallest);
  EXPECT_EQ(coarser.strong.size() + 1, c.strong.size());
  EXPECT_THROW(classify_contact(problem, state, 0.0), InputError);
  EXPECT_THROW(classify_contact(problem, state, 1.0), InputError);
}

TEST(Sensitivity, BadDirectionIsAnErrorNamingTheArgument) {
  const MembraneDesign design;
  const FetiProblem problem = membrane_problem(design.at(0), FetiVariant::feti1);
  SensitivityProblem sensitivity(problem, problem.solve(), 1e-6);
  const auto expect_error = [&](const DesignDerivative& d, const std::string& name) {
    try {
      sensitivity.direct(d, {});
      ADD_FAILURE() << "no error for " << name;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what();
    }
  };
  DesignDerivative wrong_count;
  wrong_count.df.resize(1);
  expect_error(wrong_count, "dF");
  DesignDerivative wrong_size;
  for (const auto& s : design.base) wrong_size.dK.push_back(SparseMatrix(s.K.rows() + 1, s.K.rows() + 1));
  expect_error(wrong_size, "dK[0]");
  DesignDerivative not_finite;
  for (const auto& s : design.base) not_finite.df.push_back(Vec::Constant(s.K.rows(), NAN));
  expect_error(not_finite, "dF[0]");
}

}  // namespace
}  // namespace ffeti
