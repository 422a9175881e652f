// Friction against a dense reference: an elastic block pressed onto a rigid plane and
// dragged along it by its top edge, split in two subdomains; the reference solves the
// undivided block's dual (B K^-1 B' with a dense K) by enumerating every assignment of the
// rows to their bounds, an exact active-set method that shares no code with qp/.
#include "feti/feti_problem.h"
#include "constraints/contact/obstacle.h"
#include "feti/friction.h"
#include "sens/sensitivity.h"
#include "base/errors.h"
#include "input_error.h"
#include "plane_block.h"

#include <gtest/gtest.h>

#include <memory>

#include <Eigen/Dense>

#include <cmath>
#include <functional>

namespace ffeti {
namespace {

constexpr double kPush = -0.01, kDrag = 0.004, kGap = 0.001;  // top edge moves by (kDrag, kPush)

/// The bottom nodes' dofs (both components): the slaves on the plane y = -kGap.
ContactInput on_plane(const std::vector<SubdomainInput>& subdomains) {
  ContactInput contact;
  for (const SubdomainInput& s : subdomains) {
    contact.slave_dofs.emplace_back();
    for (int k = 0; k < static_cast<int>(s.y.size()); ++k)
      if (s.y[static_cast<size_t>(k)] == 0) contact.slave_dofs.back().push_back(k);
  }
  contact.input_of<ObstacleInput>().given = true;
  contact.input_of<ObstacleInput>().point = {0, -kGap};
  contact.input_of<ObstacleInput>().normal = {0, 1};
  return contact;
}

std::vector<SubdomainInput> two_subdomains(double drag) {
  return {elastic_block(0, 0.5, 0.5, 2, 2, drag, kPush), elastic_block(0.5, 0.5, 0.5, 2, 2, drag, kPush)};
}

/// The undivided block's dual by enumeration. Rows per bottom node k (x = k/4): the normal
/// row -u_y <= kGap (multiplier n_k >= 0) and the slip row -u_x - s_k (s_k the slip
/// reference of the step, multiplier t_k in [-g_k, g_k]), with u = u(lambda) of the block
/// whose top edge is fixed. Returns per node (x, n_k, t_k) and the bottom u_x.
struct Reference {
  std::vector<double> x, normal, tangential, bottom_ux;
};
Reference enumerated(const Eigen::VectorXd& g, const Eigen::VectorXd& slip_reference, double drag) {
  const SubdomainInput block = elastic_block(0, 1, 0.5, 4, 2, drag, kPush);
  const int n = static_cast<int>(block.K.rows());
  std::vector<int> free, fixed_at(static_cast<size_t>(n), -1);
  for (size_t k = 0; k < block.dirichlet_dofs.size(); ++k) fixed_at[static_cast<size_t>(block.dirichlet_dofs[k])] = static_cast<int>(k);
  for (int i = 0; i < n; ++i)
    if (fixed_at[static_cast<size_t>(i)] < 0) free.push_back(i);
  const Eigen::MatrixXd K(block.K.get());
  const int nf = static_cast<int>(free.size());
  Eigen::MatrixXd Kff(nf, nf);
  Eigen::VectorXd f(nf);
  for (int a = 0; a < nf; ++a) {
    f[a] = 0;
    for (int i = 0; i < n; ++i)
      if (fixed_at[static_cast<size_t>(i)] >= 0) f[a] -= K(free[static_cast<size_t>(a)], i) * block.dirichlet_values[static_cast<size_t>(fixed_at[static_cast<size_t>(i)])];
    for (int b = 0; b < nf; ++b) Kff(a, b) = K(free[static_cast<size_t>(a)], free[static_cast<size_t>(b)]);
  }
  const int nodes = 5, m = 2 * nodes;  // rows: normal 0..4, slip 5..9
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(m, nf);
  Eigen::VectorXd c(m);
  for (int k = 0; k < nodes; ++k) {
    const int x_dof = 2 * k, y_dof = 2 * k + 1;  // bottom row of nodes: ids 0..4
    const auto col = [&](int dof) { return static_cast<int>(std::find(free.begin(), free.end(), dof) - free.begin()); };
    B(k, col(y_dof)) = -1, c[k] = kGap;
    B(nodes + k, col(x_dof)) = -1, c[nodes + k] = slip_reference[k];
  }
  const Eigen::LLT<Eigen::MatrixXd> Kllt(Kff);
  const Eigen::MatrixXd H = B * Kllt.solve(B.transpose());
  const Eigen::VectorXd d = B * Kllt.solve(f) - c;
  // State per row: normal rows 0 (lambda = 0) or 1 (free); slip rows 0 (-g), 1 (free), 2 (+g).
  Eigen::VectorXd best;
  int found = 0;
  std::vector<int> state(static_cast<size_t>(m), 0);
  const std::function<void(int)> visit = [&](int row) {
    if (row == m) {
      Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m);
      std::vector<int> open;
      for (int i = 0; i < m; ++i) {
        const int st = state[static_cast<size_t>(i)];
        if (st == 1) open.push_back(i);
        else if (i >= nodes) lambda[i] = st == 0 ? -g[i - nodes] : g[i - nodes];
      }
      const int o = static_cast<int>(open.size());
      Eigen::MatrixXd Hoo(o, o);
      Eigen::VectorXd rhs(o);
      for (int a = 0; a < o; ++a) {
        rhs[a] = d[open[static_cast<size_t>(a)]] - H.row(open[static_cast<size_t>(a)]).dot(lambda);
        for (int b = 0; b < o; ++b) Hoo(a, b) = H(open[static_cast<size_t>(a)], open[static_cast<size_t>(b)]);
      }
      const Eigen::VectorXd lo = Hoo.ldlt().solve(rhs);
      for (int a = 0; a < o; ++a) lambda[open[static_cast<size_t>(a)]] = lo[a];
      const Eigen::VectorXd grad = H * lambda - d;  // of 1/2 l'Hl - d'l
      const double eps = 1e-12 * (1 + d.lpNorm<Eigen::Infinity>());
      for (int i = 0; i < m; ++i) {
        const int st = state[static_cast<size_t>(i)];
        const double lower = i < nodes ? 0.0 : -g[i - nodes], upper = i < nodes ? INFINITY : g[i - nodes];
        if (st == 1 && (lambda[i] < lower - eps || lambda[i] > upper + eps)) return;
        if (st == 0 && grad[i] < -eps) return;
        if (st == 2 && grad[i] > eps) return;
      }
      best = lambda, ++found;
      return;
    }
    const int states = row < nodes ? 2 : (g[row - nodes] > 0 ? 3 : 1);
    for (int st = 0; st < states; ++st) {
      state[static_cast<size_t>(row)] = states == 1 ? 0 : st;
      visit(row + 1);
    }
  };
  visit(0);
  EXPECT_GE(found, 1);
  Reference r;
  const Eigen::VectorXd uf = Kllt.solve(f - B.transpose() * best);
  for (int k = 0; k < nodes; ++k) {
    r.x.push_back(k / 4.0), r.normal.push_back(best[k]), r.tangential.push_back(best[nodes + k]);
    r.bottom_ux.push_back(uf[std::find(free.begin(), free.end(), 2 * k) - free.begin()]);
  }
  return r;
}

/// FETI's multipliers per bottom node in x order: (normal, tangential), from fetiContact's rows.
std::vector<std::array<double, 2>> per_node(const FetiProblem& p, const FetiResult& r) {
  const Constraints& c = p.constraints();
  const ContactRowForces forces = contact_row_forces(c, r.lambda, r.slip_bound);
  std::vector<std::pair<double, std::array<double, 2>>> rows;
  for (int i = 0; i < c.contact_rows(); ++i)
    rows.push_back({p.contact_positions()[static_cast<size_t>(i)][0],
                    {r.lambda[c.equality_rows + i], forces.tangential[static_cast<size_t>(i)]}});
  std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::array<double, 2>> out;
  for (const auto& row : rows) out.push_back(row.second);
  return out;
}

DualSolveSettings tight() {
  DualSolveSettings s;
  s.tolerance = 1e-12;
  s.max_hessian = 100000;
  return s;
}

void expect_matches(const FetiProblem& p, const FetiResult& r, const Reference& ref) {
  ASSERT_EQ(r.status, SolveStatus::converged);
  const auto rows = per_node(p, r);
  ASSERT_EQ(rows.size(), 5u);
  double scale = 0;
  for (double v : ref.normal) scale = std::max(scale, std::abs(v));
  for (size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(rows[k][0], ref.normal[k], 1e-8 * scale) << "normal force at node " << k;
    EXPECT_NEAR(rows[k][1], ref.tangential[k], 1e-8 * scale) << "friction force at node " << k;
  }
}

/// The block dragged on the plane with Coulomb friction, mu = 0.3.
std::unique_ptr<FetiProblem> dragged_coulomb(FetiVariant variant) {
  ContactInput contact = on_plane(two_subdomains(kDrag));
  contact.friction = 0.3;
  FetiSetupSettings setup;
  setup.variant = variant;
  return std::make_unique<FetiProblem>(two_subdomains(kDrag), contact, setup);
}

/// A value per dof of each subdomain, `value` of its x (frictionField, slipBoundField).
std::vector<std::vector<double>> field_of_x(const std::vector<SubdomainInput>& subs, double (*value)(double)) {
  std::vector<std::vector<double>> field;
  for (const SubdomainInput& s : subs) {
    field.emplace_back();
    for (double x : s.x) field.back().push_back(value(x));
  }
  return field;
}

class Tresca : public ::testing::TestWithParam<FetiVariant> {};

TEST_P(Tresca, MatchesTheEnumeratedDualOfTheUndividedBlock) {
  // A bound that holds some rows and lets others slip: both kinds must appear.
  for (double bound : {0.0, 1.0, 2.0, 100.0}) {
    ContactInput contact = on_plane(two_subdomains(kDrag));
    contact.slip_bound = bound;
    FetiSetupSettings setup;
    setup.variant = GetParam();
    const FetiProblem p(two_subdomains(kDrag), contact, setup);
    EXPECT_EQ(p.constraints().friction_rows, bound > 0 ? 5 : 0);  // a zero bound holds nothing: no rows
    const FetiResult r = p.solve(tight());
    const Reference ref = enumerated(Eigen::VectorXd::Constant(5, bound), Eigen::VectorXd::Zero(5), kDrag);
    SCOPED_TRACE("slip bound " + std::to_string(bound));
    expect_matches(p, r, ref);
    EXPECT_LT(r.kkt.max(), 1e-8);
    EXPECT_EQ(r.friction_iterations, bound > 0 ? 1 : 0);
    if (bound == 1.0) {  // the mixed case the test is for: some rows stick, some slip
      EXPECT_GT(r.slipping_contact, 0);
      EXPECT_LT(r.slipping_contact, r.active_contact);
    }
  }
}

TEST_P(Tresca, ZeroBoundIsTheFrictionlessSolution) {
  FetiSetupSettings setup;
  setup.variant = GetParam();
  const FetiProblem frictionless(two_subdomains(kDrag), on_plane(two_subdomains(kDrag)), setup);
  ContactInput contact = on_plane(two_subdomains(kDrag));
  contact.friction = 0;
  const FetiProblem coulomb(two_subdomains(kDrag), contact, setup);
  const FetiResult a = frictionless.solve(tight()), b = coulomb.solve(tight());
  ASSERT_EQ(b.status, SolveStatus::converged);
  EXPECT_EQ(coulomb.constraints().friction_rows, 0);  // mu = 0: no row, the frictionless problem
  EXPECT_EQ(a.energy, b.energy);
  EXPECT_EQ(a.counts.hessian, b.counts.hessian);
}

TEST_P(Tresca, TrescaWithABoundPerRow) {
  // slipBoundField: g = 0.2 + 2 x at each bottom node (x in [0, 1]), some rows at their bound.
  std::vector<SubdomainInput> subs = two_subdomains(kDrag);
  ContactInput contact = on_plane(subs);
  contact.slip_bound = 0;
  contact.slip_bound_field = field_of_x(subs, [](double x) { return 0.2 + 2 * x; });
  FetiSetupSettings setup;
  setup.variant = GetParam();
  const FetiProblem p(std::move(subs), contact, setup);
  const FetiResult r = p.solve(tight());
  ASSERT_EQ(r.status, SolveStatus::converged);
  Eigen::VectorXd g(5);
  for (int k = 0; k < 5; ++k) g[k] = 0.2 + 2 * (k / 4.0);
  expect_matches(p, r, enumerated(g, Eigen::VectorXd::Zero(5), kDrag));
  EXPECT_GT(r.slipping_contact, 0);
  EXPECT_LT(r.slipping_contact, r.active_contact);
}

std::vector<std::vector<double>> dirichlet_values(const std::vector<SubdomainInput>& subdomains) {
  std::vector<std::vector<double>> values;
  for (const SubdomainInput& s : subdomains) values.push_back(s.dirichlet_values);
  return values;
}

TEST_P(Tresca, APrescribedMotionChangedBetweenSteps) {
  FetiSetupSettings setup;
  setup.variant = GetParam();
  // Frictionless: the top edge moved back to 0 on the problem set up at kDrag is the fresh
  // problem at 0 (no load path without friction).
  {
    FetiProblem moved(two_subdomains(kDrag), on_plane(two_subdomains(kDrag)), setup);
    const FetiResult first = moved.solve(tight());
    ASSERT_EQ(first.status, SolveStatus::converged);
    moved.set_dirichlet_values(dirichlet_values(two_subdomains(0.0)));
    const FetiResult again = moved.solve(tight());
    const FetiResult fresh = FetiProblem(two_subdomains(0.0), on_plane(two_subdomains(0.0)), setup).solve(tight());
    ASSERT_EQ(again.status, SolveStatus::converged);
    for (size_t s = 0; s < 2; ++s) EXPECT_LT((again.u[s] - fresh.u[s]).lpNorm<Eigen::Infinity>(), 1e-10);
  }
  // Tresca: step 2 brings the top edge back on the same problem; the slip of step 1 stays
  // (the enumerated dual with step 1's slip as the reference and the edge at 0).
  constexpr double bound = 1.0;
  ContactInput contact = on_plane(two_subdomains(kDrag));
  contact.slip_bound = bound;
  FetiProblem p(two_subdomains(kDrag), contact, setup);
  const FetiResult r1 = p.solve(tight());
  const Reference ref1 = enumerated(Eigen::VectorXd::Constant(5, bound), Eigen::VectorXd::Zero(5), kDrag);
  expect_matches(p, r1, ref1);
  p.start_load_step(r1);
  p.set_dirichlet_values(dirichlet_values(two_subdomains(0.0)));
  const FetiResult r2 = p.solve(tight());
  Eigen::VectorXd slip1(5);
  for (int k = 0; k < 5; ++k) slip1[k] = -ref1.bottom_ux[static_cast<size_t>(k)];
  expect_matches(p, r2, enumerated(Eigen::VectorXd::Constant(5, bound), slip1, 0.0));
  expect_input_error([&] { p.set_dirichlet_values({{0.0}, {}}); }, "dirichletValues[0]: needs one value per Dirichlet dof");
}

TEST_P(Tresca, CoulombFixedPointMeetsTheLawAndTheReference) {
  constexpr double mu = 0.3;
  ContactInput contact = on_plane(two_subdomains(kDrag));
  contact.friction = mu;
  FetiSetupSettings setup;
  setup.variant = GetParam();
  const FetiProblem p(two_subdomains(kDrag), contact, setup);
  const FetiResult r = p.solve(tight());
  ASSERT_EQ(r.status, SolveStatus::converged);
  EXPECT_GT(r.friction_iterations, 1);
  EXPECT_LE(r.friction_bound_change, 1e-12);
  // The answer is the Tresca solution for g = mu lambda_n of itself.
  const auto rows = per_node(p, r);
  Eigen::VectorXd g(5);
  for (size_t k = 0; k < 5; ++k) g[static_cast<Eigen::Index>(k)] = mu * rows[k][0];
  expect_matches(p, r, enumerated(g, Eigen::VectorXd::Zero(5), kDrag));
  EXPECT_GT(r.slipping_contact, 0);
}

TEST_P(Tresca, NewtonAndTheFixedPointGiveTheSameCoulombAnswer) {
  // coulomb = "newton" (the default in a plane problem) and "fixed-point": the same law, the
  // same multipliers to the tolerance, Newton's steps counted only where it ran.
  const auto problem = dragged_coulomb(GetParam());
  const FetiProblem& p = *problem;
  DualSolveSettings fixed = tight(), newton = tight(), automatic = tight();
  fixed.coulomb = CoulombMethod::fixed_point;
  newton.coulomb = CoulombMethod::newton;
  const FetiResult a = p.solve(fixed), b = p.solve(newton), c = p.solve(automatic);
  ASSERT_EQ(a.status, SolveStatus::converged);
  ASSERT_EQ(b.status, SolveStatus::converged);
  EXPECT_EQ(a.newton_steps, 0);
  EXPECT_GT(b.newton_steps, 0);
  EXPECT_GT(b.newton_hessian, 0);
  EXPECT_LE(b.newton_hessian, b.counts.hessian);
  EXPECT_EQ(c.newton_steps, b.newton_steps);  // plane problem: automatic is Newton
  EXPECT_LE((a.lambda - b.lambda).norm(), 1e-9 * a.lambda.norm());
  EXPECT_LE(b.friction_bound_change, 1e-12);
  EXPECT_GT(b.slipping_contact, 0);
}

TEST_P(Tresca, AnUnsettledFixedPointIsReportedAsSuch) {
  // The same Coulomb problem allowed one Tresca solve (frictionit = 1): the bounds of the
  // first, sticking solve are not the law's, and the status says so.
  const auto problem = dragged_coulomb(GetParam());
  const FetiProblem& p = *problem;
  DualSolveSettings one = tight();
  one.friction_iterations = 1;
  const FetiResult r = p.solve(one);
  EXPECT_EQ(r.status, SolveStatus::max_iterations);
  EXPECT_EQ(r.friction_iterations, 1);
  EXPECT_GT(r.friction_bound_change, 1e-3);
}

TEST_P(Tresca, CoulombBelowRoundOffEndsStagnatedWithTheLawsResidual) {
  // tol 1e-17 lies below what the data allow: Tresca solves stagnate. The fixed point goes on
  // to bounds within the residual reached, and reports it: status stagnated, the residual
  // at least the bounds' last change (once the first stagnated solve ended it, reporting its
  // KKT residual while the bounds still moved by more).
  const auto problem = dragged_coulomb(GetParam());
  const FetiProblem& p = *problem;
  DualSolveSettings below = tight();
  below.tolerance = 1e-17;
  const FetiResult r = p.solve(below);
  EXPECT_EQ(r.status, SolveStatus::stagnated);
  EXPECT_GE(r.violation, r.friction_bound_change);
  EXPECT_LT(r.violation, 1e-9);
  // The law from the answer itself: no friction force beyond mu lambda_n by more than the
  // residual reported.
  double scale = 0, excess = 0;
  for (const auto& row : per_node(p, r)) scale = std::max(scale, 0.3 * row[0]);
  for (const auto& row : per_node(p, r)) excess = std::max(excess, std::abs(row[1]) - 0.3 * row[0]);
  EXPECT_LE(excess, r.violation * scale + 1e-15 * scale);
}

TEST_P(Tresca, MaxitBoundsTheWholeFixedPoint) {
  // maxit holds over all Tresca solves of the fixed point: with the multiplications of the
  // first two solves as the budget, the third finds none left and the status says so.
  const auto problem = dragged_coulomb(GetParam());
  const FetiProblem& p = *problem;
  const FetiResult full = p.solve(tight());
  ASSERT_EQ(full.status, SolveStatus::converged);
  ASSERT_GE(full.friction_iterations, 3);
  DualSolveSettings limited = tight();
  limited.max_hessian = full.friction_hessian[0] + full.friction_hessian[1];
  const FetiResult r = p.solve(limited);
  EXPECT_EQ(r.status, SolveStatus::max_iterations);
  EXPECT_EQ(r.friction_iterations, 2);
  EXPECT_EQ(r.counts.hessian, limited.max_hessian);  // the same two solves, nothing beyond
  // A budget that runs out inside a solve stops that solve, not only the fixed point.
  limited.max_hessian = full.friction_hessian[0] + 1;
  const FetiResult cut = p.solve(limited);
  EXPECT_EQ(cut.status, SolveStatus::max_iterations);
  EXPECT_LE(cut.counts.hessian, limited.max_hessian + 2);  // a step in progress may finish (<= 2 products)
}

TEST_P(Tresca, CoulombWithACoefficientPerRow) {
  // frictionField: mu = 0.1 + 0.2 x at each bottom node (x in [0, 1]).
  std::vector<SubdomainInput> subs = two_subdomains(kDrag);
  ContactInput contact = on_plane(subs);
  contact.friction = 0;
  contact.friction_field = field_of_x(subs, [](double x) { return 0.1 + 0.2 * x; });
  FetiSetupSettings setup;
  setup.variant = GetParam();
  const FetiProblem p(std::move(subs), contact, setup);
  const FetiResult r = p.solve(tight());
  ASSERT_EQ(r.status, SolveStatus::converged);
  const auto rows = per_node(p, r);
  Eigen::VectorXd g(5);
  for (size_t k = 0; k < 5; ++k) g[static_cast<Eigen::Index>(k)] = (0.1 + 0.2 * (k / 4.0)) * rows[k][0];
  expect_matches(p, r, enumerated(g, Eigen::VectorXd::Zero(5), kDrag));
}

TEST_P(Tresca, LoadStepsMeasureTheSlipFromTheLastStep) {
  // Step 1 drags the top edge by kDrag, step 2 brings it back to 0: what slipped in step 1
  // stays (hysteresis), unlike a single solve with the top edge at 0.
  constexpr double bound = 1.0;
  FetiSetupSettings setup;
  setup.variant = GetParam();
  ContactInput contact = on_plane(two_subdomains(kDrag));
  contact.slip_bound = bound;
  FetiProblem step1(two_subdomains(kDrag), contact, setup);
  const FetiResult r1 = step1.solve(tight());
  const Reference ref1 = enumerated(Eigen::VectorXd::Constant(5, bound), Eigen::VectorXd::Zero(5), kDrag);
  expect_matches(step1, r1, ref1);
  // The second step on a problem whose Dirichlet values are those of step 2: the state of
  // step 1 enters through start_load_step on a problem set up with the same rows.
  FetiProblem step2(two_subdomains(0.0), contact, setup);
  FetiResult carried = r1;  // u and lambda of step 1 on the same subdomains and rows
  step2.start_load_step(carried);
  const FetiResult r2 = step2.solve(tight());
  Eigen::VectorXd slip1(5);  // B_t u of step 1: -u_x at the bottom nodes
  for (int k = 0; k < 5; ++k) slip1[k] = -ref1.bottom_ux[static_cast<size_t>(k)];
  expect_matches(step2, r2, enumerated(Eigen::VectorXd::Constant(5, bound), slip1, 0.0));
  const FetiResult fresh = FetiProblem(two_subdomains(0.0), contact, setup).solve(tight());
  const auto a = per_node(step2, r2), b = per_node(step2, fresh);
  double difference = 0;
  for (size_t k = 0; k < 5; ++k) difference = std::max(difference, std::abs(a[k][1] - b[k][1]));
  EXPECT_GT(difference, 0.1 * bound);  // the path matters
}

INSTANTIATE_TEST_SUITE_P(Variants, Tresca, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

TEST(CoulombSchedule, NextToleranceFollowsTheBoundsTightensAtMostTenfoldAndLandsOnTol) {
  // 0.1 times 1e-5 rounds to one ulp above 1e-6: the next solve is at tol itself, so that one
  // solve to tol can end the fixed point (before, a further solve at tol did).
  EXPECT_NE(0.1 * 1e-5, 1e-6);
  EXPECT_EQ(next_tresca_tolerance(1e-5, 1e-9, 1e-6), 1e-6);
  EXPECT_EQ(next_tresca_tolerance(1e-2, 1.0, 1e-6), 1e-2);      // the bounds moved a lot: as loose as before
  EXPECT_DOUBLE_EQ(next_tresca_tolerance(1e-2, 0.5, 1e-6), 5e-3);  // 0.01 times the bounds' change
  EXPECT_DOUBLE_EQ(next_tresca_tolerance(1e-2, 1e-6, 1e-6), 1e-3);  // at most ten times tighter
  EXPECT_EQ(next_tresca_tolerance(1e-6, 1e-9, 1e-6), 1e-6);       // never below what is reachable
  EXPECT_DOUBLE_EQ(next_tresca_tolerance(1e-4, 5e-3, 1e-8), 5e-5);  // 0.01 times the change, within tenfold
}

TEST(FrictionInput, BadLawsAreRefusedByName) {
  const auto with = [](const std::function<void(ContactInput&)>& change) {
    ContactInput contact = on_plane(two_subdomains(kDrag));
    change(contact);
    FetiProblem p(two_subdomains(kDrag), contact);
  };
  expect_input_error([&] { with([](ContactInput& c) { c.friction = -0.5; }); }, "friction: must be");
  expect_input_error([&] { with([](ContactInput& c) { c.slip_bound = NAN; }); }, "slipBound: must be");
  expect_input_error([&] { with([](ContactInput& c) { c.friction = 0.3, c.slip_bound = 1; }); }, "give one law");
  expect_input_error([&] { with([](ContactInput& c) { c.friction_field = {{}, {}}; }); }, "frictionField: needs friction");
  expect_input_error([&] { with([](ContactInput& c) { c.slip_bound_field = {{}, {}}; }); }, "slipBoundField: needs slipBound");
  expect_input_error([&] {
    with([](ContactInput& c) { c.slip_bound = 0, c.slip_bound_field = {{}, std::vector<double>(18, -1.0)}; });
  }, "slipBoundField[1]: entry 0 is");
  expect_input_error([&] {
    with([](ContactInput& c) { c.friction = 0, c.slip_bound = 0, c.friction_field = {{}, {}}, c.slip_bound_field = {{}, {}}; });
  }, "frictionField, slipBound");
  expect_input_error([&] {
    with([](ContactInput& c) { c.friction = 0, c.friction_field = {std::vector<double>(2, 0.3), {}}; });
  }, "frictionField[0]: needs one value per dof");
  expect_input_error([&] {
    with([](ContactInput& c) { c.friction = 0, c.friction_field = {{}, std::vector<double>(18, -1.0)}; });
  }, "frictionField[1]: entry 0 is");
}

TEST(FrictionInput, SensitivityOfAFrictionStateIsRefused) {
  ContactInput contact = on_plane(two_subdomains(kDrag));
  contact.friction = 0.3;
  const FetiProblem p(two_subdomains(kDrag), contact);
  const FetiResult r = p.solve();
  expect_input_error([&] { SensitivityProblem s(p, r, 1e-8); }, "P: obstacle contact does not support sensitivity with friction yet");
}

}  // namespace
}  // namespace ffeti
