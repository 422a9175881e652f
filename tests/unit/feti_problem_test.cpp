#include "feti/coarse_space.h"
#include "feti/dual_operator.h"
#include "base/errors.h"
#include "feti/feti_problem.h"
#include "feti/kernel.h"
#include "feti/options.h"
#include "feti/primal.h"
#include "parallel/process.h"
#include "membrane_model.h"
#include "input_error.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numeric>

namespace ffeti {
namespace {

FetiProblem membrane_problem(const test::MembraneOptions& o, FetiVariant variant, int threads = 0,
                             DualPreconditioner preconditioner = DualPreconditioner::none) {
  auto subs = test::membrane_subdomains(o);
  ContactInput contact = o.with_contact ? test::membrane_contact(subs) : ContactInput{};
  FetiSetupSettings setup;
  setup.variant = variant;
  setup.threads = threads;
  setup.preconditioner = preconditioner;
  return FetiProblem(std::move(subs), contact, setup);
}

std::vector<double> active_contact_y(const FetiProblem& problem, const FetiResult& result,
                                     const std::vector<SubdomainInput>& subs) {
  std::vector<double> ys;
  const Constraints& c = problem.constraints();
  for (int i = c.equality_rows; i < c.rows(); ++i) {
    if (!(result.lambda[i] > 0)) continue;
    const ConstraintEntry& e = c.entries[c.row_start[i]];
    ys.push_back(subs[e.subdomain].y[e.dof]);
  }
  std::sort(ys.begin(), ys.end());
  return ys;
}

/// The pieces of the dual operator built by hand, for dense comparisons.
struct DualPieces {
  std::vector<SubdomainInput> subs;
  Constraints constraints;
  std::vector<LocalConstraints> local;
  SubdomainList subdomains;
  Eigen::MatrixXd B, Kplus_dense, R;
};

/// `ordering`: where each subdomain's factor puts its interface (forced last: the dual
/// operator's solves on the interface alone, fixing dofs among it).
DualPieces dual_pieces(const test::MembraneOptions& o, InterfaceOrdering ordering = InterfaceOrdering::fill_reducing) {
  DualPieces p;
  p.subs = test::membrane_subdomains(o);
  // Total FETI: Dirichlet conditions as rows, every subdomain floats (the hardest case).
  p.constraints = build_constraints(p.subs, test::membrane_contact(p.subs), FetiVariant::tfeti);
  std::vector<Eigen::Index> sizes;
  int n = 0, r = 0;
  for (const auto& s : p.subs) sizes.push_back(s.K.rows()), n += static_cast<int>(s.K.rows());
  p.local = split_by_subdomain(p.constraints, sizes);
  for (size_t s = 0; s < p.subs.size(); ++s)
    p.subdomains.push_back(std::make_unique<Subdomain>(
        static_cast<int>(s), p.subs[s].K, candidate_kernel(p.subs[s].x, p.subs[s].y, p.subs[s].component),
        FactorKind::simplicial, ordering, nullptr, touched_dofs(p.local[s].B)));
  for (const auto& s : p.subdomains) r += static_cast<int>(s->kernel().cols());
  p.B = Eigen::MatrixXd::Zero(p.constraints.rows(), n);
  p.Kplus_dense = Eigen::MatrixXd::Zero(n, n);  // Moore-Penrose, independent of fixing dofs
  p.R = Eigen::MatrixXd::Zero(n, r);
  int offset = 0, column = 0;
  for (size_t s = 0; s < p.subs.size(); ++s) {
    const auto ns = static_cast<int>(p.subs[s].K.rows());
    p.B.middleCols(offset, ns) = Eigen::MatrixXd::Zero(p.constraints.rows(), ns);
    for (size_t k = 0; k < p.local[s].rows.size(); ++k)
      for (int j = 0; j < ns; ++j) p.B(p.local[s].rows[k], offset + j) = p.local[s].B.coeff(static_cast<int>(k), j);
    p.Kplus_dense.block(offset, offset, ns, ns) =
        Eigen::MatrixXd(p.subs[s].K.get()).completeOrthogonalDecomposition().pseudoInverse();
    const Eigen::MatrixXd& Rs = p.subdomains[s]->kernel();
    p.R.block(offset, column, ns, Rs.cols()) = Rs;
    offset += ns, column += static_cast<int>(Rs.cols());
  }
  return p;
}

class DualOperatorOrdering : public ::testing::TestWithParam<InterfaceOrdering> {};

TEST_P(DualOperatorOrdering, ProjectedOperatorMatchesDenseExplicit) {
  DualPieces p = dual_pieces(test::membrane_options(8, 2), GetParam());
  const auto on_interface = std::count_if(p.subdomains.begin(), p.subdomains.end(),
                                          [](const auto& s) { return s->interface_solves(); });
  EXPECT_EQ(on_interface, GetParam() == InterfaceOrdering::interface_last ? static_cast<long>(p.subdomains.size()) : 0);
  std::vector<int> bodies;
  for (const auto& s : p.subs) bodies.push_back(s.body);
  const int m = p.constraints.rows();
  const int S = static_cast<int>(p.subs.size());
  const SerialCommunicator comm;
  std::vector<int> ids(S);
  std::iota(ids.begin(), ids.end(), 0);
  const SubdomainSum sum(rows_by_subdomain(p.constraints, S), std::vector<int>(S, 0), m, comm);
  const DualOperator F(p.subdomains, p.local, sum, m, 1);
  const CoarseSpace coarse(p.subdomains, p.local, ids, m, p.constraints.equality_rows, bodies, comm);
  // G = R'B' and P = I - G'(GG')^{-1}G built densely; P F P does not depend on which
  // generalized inverse K^+ is, so the fixing-dof inverse must agree with Moore-Penrose.
  const Eigen::MatrixXd G = p.R.transpose() * p.B.transpose();
  EXPECT_LT((Eigen::MatrixXd(coarse.G()) - G).norm(), 1e-12 * G.norm());
  const Eigen::MatrixXd P =
      Eigen::MatrixXd::Identity(m, m) - G.transpose() * (G * G.transpose()).ldlt().solve(G);
  const Eigen::MatrixXd PFP_dense = P * p.B * p.Kplus_dense * p.B.transpose() * P;
  Eigen::MatrixXd PFP(m, m);
  Vec Px(m), FPx(m), y(m);
  for (int j = 0; j < m; ++j) {
    coarse.project(Vec::Unit(m, j), Px);
    F.apply(Px, FPx);
    coarse.project(FPx, y);
    PFP.col(j) = y;
  }
  EXPECT_LT((PFP - PFP_dense).norm(), 1e-9 * PFP_dense.norm());
  // The projector is symmetric, idempotent and annihilates G'.
  Eigen::MatrixXd P_applied(m, m);
  for (int j = 0; j < m; ++j) {
    coarse.project(Vec::Unit(m, j), y);
    P_applied.col(j) = y;
  }
  EXPECT_LT((P_applied - P).norm(), 1e-12 * m);
  EXPECT_LT((P_applied * P_applied - P_applied).norm(), 1e-12 * m);
  EXPECT_LT((G * P_applied).norm(), 1e-12 * G.norm());
}

TEST_P(DualOperatorOrdering, CoerciveOperatorMatchesDenseExplicit) {
  test::MembraneOptions o = test::membrane_options(8, 2);
  o.with_contact = false;
  o.body2 = false;
  std::vector<SubdomainInput> subs = test::membrane_subdomains(o);
  // Regularize every subdomain with a mass-like diagonal so that none floats.
  for (auto& s : subs) {
    for (Eigen::Index i = 0; i < s.K.rows(); ++i) s.K.edit().coeffRef(i, i) += 0.1;
    s.dirichlet_dofs.clear();
  }
  const Constraints c = build_constraints(subs, {}, FetiVariant::feti1);
  std::vector<Eigen::Index> sizes;
  for (const auto& s : subs) sizes.push_back(s.K.rows());
  const auto local = split_by_subdomain(c, sizes);
  SubdomainList subdomains;
  for (size_t s = 0; s < subs.size(); ++s)
    subdomains.push_back(std::make_unique<Subdomain>(static_cast<int>(s), subs[s].K,
        candidate_kernel(subs[s].x, subs[s].y, subs[s].component), FactorKind::simplicial, GetParam(), nullptr,
        touched_dofs(local[s].B)));
  const int m = c.rows();
  const SerialCommunicator comm;
  const int S = static_cast<int>(subs.size());
  const SubdomainSum sum(rows_by_subdomain(c, S), std::vector<int>(S, 0), m, comm);
  const DualOperator F(subdomains, local, sum, m, 2);
  Eigen::MatrixXd F_dense = Eigen::MatrixXd::Zero(m, m);
  for (size_t s = 0; s < subs.size(); ++s) {
    const Eigen::MatrixXd Bs = Eigen::MatrixXd(local[s].B);
    const Eigen::MatrixXd block = Bs * Eigen::MatrixXd(subs[s].K.get()).inverse() * Bs.transpose();
    for (size_t a = 0; a < local[s].rows.size(); ++a)
      for (size_t b = 0; b < local[s].rows.size(); ++b)
        F_dense(local[s].rows[a], local[s].rows[b]) += block(a, b);
  }
  Vec y(m);
  for (int j = 0; j < m; ++j) {
    F.apply(Vec::Unit(m, j), y);
    EXPECT_LT((y - F_dense.col(j)).norm(), 1e-10 * F_dense.norm());
  }
  // Blocks: of every column (block solves on the whole factor) and of one or two columns
  // (with the interface last: a solve on the interface per column, cheaper there).
  for (int width : {m, 1, 2}) {
    const Eigen::MatrixXd X = Eigen::MatrixXd::Identity(m, m).leftCols(width);
    Eigen::MatrixXd Y;
    F.apply(X, Y);
    EXPECT_LT((Y - F_dense.leftCols(width)).norm(), 1e-10 * F_dense.norm()) << "block of " << width;
  }
}

INSTANTIATE_TEST_SUITE_P(BothOrderings, DualOperatorOrdering,
                         ::testing::Values(InterfaceOrdering::fill_reducing, InterfaceOrdering::interface_last));

TEST(FetiProblem, MembraneMatchesMonolithicActiveSetReference) {
  const int n = 16;
  const test::ReferenceSolution reference = test::membrane_reference(n);
  ASSERT_FALSE(reference.active_y.empty());
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti}) {
    const auto subs = test::membrane_subdomains(test::membrane_options(n, 2));
    const FetiProblem problem = membrane_problem(test::membrane_options(n, 2), variant);
    DualSolveSettings settings;
    settings.tolerance = 1e-10;
    const FetiResult result = problem.solve(settings);
    ASSERT_EQ(result.status, SolveStatus::converged) << to_string(result.status);
    EXPECT_EQ(result.path, DualPath::smalbe);
    EXPECT_NEAR(result.energy, reference.energy, 1e-8 * std::abs(reference.energy));
    EXPECT_EQ(active_contact_y(problem, result, subs), reference.active_y);
    EXPECT_LT(result.kkt.max(), 1e-7) << result.kkt.equilibrium << " " << result.kkt.equality << " "
                                      << result.kkt.inequality << " " << result.kkt.complementarity;
  }
}

TEST(FetiProblem, PreconditionersGiveTheSameSolutionInFewerSteps) {
  // Both membranes fixed, no contact: glued subdomains, projected CG (FETI-1) and CG on the
  // Dirichlet rows too (Total FETI), 4 x 4 subdomains per body with cross points. Dirichlet:
  // fewer than half the steps; lumped: fewer.
  test::MembraneOptions glued = test::membrane_options(64, 4);
  glued.with_contact = false;
  glued.fix_right_body = true;
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti})
  for (DualPreconditioner kind : {DualPreconditioner::dirichlet, DualPreconditioner::lumped}) {
    DualSolveSettings settings;
    settings.tolerance = 1e-10;
    const FetiProblem plain = membrane_problem(glued, variant);
    const FetiProblem preconditioned = membrane_problem(glued, variant, 0, kind);
    const FetiResult a = plain.solve(settings), b = preconditioned.solve(settings);
    ASSERT_EQ(a.status, SolveStatus::converged);
    ASSERT_EQ(b.status, SolveStatus::converged);
    EXPECT_EQ(b.path, DualPath::projected_cg);
    EXPECT_NEAR(b.energy, a.energy, 1e-10 * std::abs(a.energy));
    double difference = 0, size = 0;
    for (size_t s = 0; s < a.u.size(); ++s) {
      difference = std::max(difference, (a.u[s] - b.u[s]).cwiseAbs().maxCoeff());
      size = std::max(size, a.u[s].cwiseAbs().maxCoeff());
    }
    EXPECT_LT(difference, 1e-8 * size);
    EXPECT_LT(b.kkt.max(), 1e-8);
    EXPECT_LT((kind == DualPreconditioner::dirichlet ? 2 : 1) * b.counts.cg, a.counts.cg)
        << preconditioner_name(kind) << ": plain " << a.counts.cg << ", preconditioned " << b.counts.cg;
    // The split of the solve's time (fetiInfo): the preconditioner's only where it ran, the
    // stopping test's primal checks wherever it checked, all parts within the solve.
    EXPECT_EQ(a.times.preconditioner, 0.0);
    EXPECT_GT(b.times.preconditioner, 0.0);
    EXPECT_GT(b.scale_evaluations, 0);
    EXPECT_GT(b.times.primal_checks, 0.0);
    EXPECT_LE(b.times.dual_operator + b.times.preconditioner + b.times.primal_checks, b.times.solve);
  }
}

TEST(FetiProblem, PreconditionersInFaceKeepTheContactSolution) {
  // The membranes with contact: SMALBE-M (FETI-1, 4 x 4 subdomains per body, a floating
  // membrane) and MPRGP (one subdomain per body, both fixed: nothing floats),
  // preconditioned in face (Dirichlet, lumped) against unpreconditioned.
  for (DualPreconditioner kind : {DualPreconditioner::dirichlet, DualPreconditioner::lumped})
  for (bool fix_right : {false, true}) {
    test::MembraneOptions o = test::membrane_options(64, fix_right ? 1 : 4);
    o.fix_right_body = fix_right;
    DualSolveSettings settings;
    settings.tolerance = 1e-10;
    const FetiResult a = membrane_problem(o, FetiVariant::feti1).solve(settings);
    const FetiResult b = membrane_problem(o, FetiVariant::feti1, 0, kind).solve(settings);
    ASSERT_EQ(a.status, SolveStatus::converged);
    ASSERT_EQ(b.status, SolveStatus::converged);
    EXPECT_EQ(b.path, fix_right ? DualPath::mprgp : DualPath::smalbe);
    EXPECT_NEAR(b.energy, a.energy, 1e-10 * std::abs(a.energy));
    EXPECT_EQ(b.active_contact, a.active_contact);
    EXPECT_LT(b.kkt.max(), 1e-7);
    if (fix_right) continue;  // the fixed membranes part at once: nothing to iterate
    EXPECT_GT(b.counts.preconditioner, 0);
    EXPECT_LT(b.counts.hessian, a.counts.hessian)
        << preconditioner_name(kind) << ": plain " << a.counts.hessian << ", in face " << b.counts.hessian;
  }
}

TEST(FetiProblem, FreeRowsAndPenaltyGiveTheSameSolution) {
  // The coarse constraints met by the free multipliers (T, SMALBE-M on the floating
  // membrane's one mode) against all of G penalized: the same QP two ways, FETI-1 (the left
  // membrane's fixed subdomains ground the gluing) and Total FETI (Dirichlet rows are free
  // rows too), 4 x 4 subdomains per body.
  const test::MembraneOptions o = test::membrane_options(64, 4);
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti}) {
    const FetiProblem problem = membrane_problem(o, variant);
    DualSolveSettings settings;
    settings.tolerance = 1e-10;
    const FetiResult free_rows = problem.solve(settings);
    settings.coarse_constraints = CoarseConstraints::penalty;
    settings.smalbe.M_factor = 100;
    const FetiResult penalty = problem.solve(settings);
    ASSERT_EQ(free_rows.status, SolveStatus::converged);
    ASSERT_EQ(penalty.status, SolveStatus::converged);
    EXPECT_EQ(free_rows.path, DualPath::smalbe);
    EXPECT_NEAR(free_rows.energy, penalty.energy, 1e-10 * std::abs(penalty.energy));
    EXPECT_EQ(free_rows.active_contact, penalty.active_contact);
    EXPECT_LT(free_rows.kkt.max(), 1e-8);
    EXPECT_LT((free_rows.lambda - penalty.lambda).lpNorm<Eigen::Infinity>(),
              1e-6 * penalty.lambda.lpNorm<Eigen::Infinity>());
  }
}

TEST(FetiProblem, DefaultStopBoundsTheRelativeKktResidualsByTol) {
  // The stopping test in primal terms: tol bounds the relative KKT residuals, recomputed in
  // primal form after the solve, on the SMALBE path (a floating membrane) and the MPRGP one.
  for (bool fix_right : {false, true}) {
    test::MembraneOptions o = test::membrane_options(64, fix_right ? 1 : 4);
    o.fix_right_body = fix_right;
    const FetiProblem problem = membrane_problem(o, FetiVariant::feti1);
    for (double tol : {1e-3, 1e-5, 1e-7}) {
      DualSolveSettings settings;
      settings.tolerance = tol;
      const FetiResult r = problem.solve(settings);
      ASSERT_EQ(r.status, SolveStatus::converged) << "tol " << tol;
      EXPECT_EQ(r.path, fix_right ? DualPath::mprgp : DualPath::smalbe);
      EXPECT_LE(r.violation, tol);
      EXPECT_GE(r.scale_evaluations, 1);
      EXPECT_LE(r.scale_evaluations, 6);
      EXPECT_LT(r.kkt.max(), 1.1 * tol) << "tol " << tol;  // tol bounds them (round-off aside)
    }
  }
}

TEST(FetiProblem, ToleranceBelowRoundOffCostsNoCheckPerIteration) {
  // tol = 1e-15 cannot be met (SMALBE path: the last violation is 3.5e-15): the solve ends
  // at its limit and says so, having checked the recovered solution once per halving of the
  // gradient at most, not every iteration (each check is a K^+ application the Hessian
  // count does not see).
  const FetiProblem problem = membrane_problem(test::membrane_options(32, 2), FetiVariant::feti1);
  DualSolveSettings settings;
  settings.tolerance = 1e-15;
  settings.max_hessian = 1500;
  const FetiResult r = problem.solve(settings);
  EXPECT_NE(r.status, SolveStatus::converged);
  EXPECT_GT(r.violation, 1e-15);
  EXPECT_LT(r.scale_evaluations, 40) << to_string(r.status) << " after " << r.counts.hessian;
}

TEST(FetiProblem, SeedToleranceGivesSmallKktResidualsAndBoundedIterations) {
  const FetiProblem problem = membrane_problem(test::membrane_options(32, 2), FetiVariant::feti1);
  DualSolveSettings seed;
  seed.stopping = StoppingTest::seed;
  const FetiResult result = problem.solve(seed);
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_LE(result.gradient_norm, 1e-4 * result.gradient_reference);
  EXPECT_LE(result.equality_norm, 1e-4 * result.equality_reference);
  EXPECT_LT(result.kkt.equilibrium, 1e-3);
  EXPECT_LT(result.kkt.equality, 1e-3);
  EXPECT_GE(result.counts.hessian, 5);
  EXPECT_LE(result.counts.hessian, 100);
  EXPECT_GT(result.active_contact, 0);
  EXPECT_LE(result.active_contact, 33);
}

TEST(FetiProblem, PathFollowsTheScene) {
  test::MembraneOptions single = test::membrane_options(8, 1);
  single.body2 = false;
  single.with_contact = false;
  EXPECT_EQ(membrane_problem(single, FetiVariant::feti1).path(), DualPath::cholesky);

  // Body 0 split 2 x 2 without contact: the right column floats -> projected CG.
  test::MembraneOptions glued = test::membrane_options(8, 2);
  glued.body2 = false;
  glued.with_contact = false;
  const FetiProblem projected = membrane_problem(glued, FetiVariant::feti1);
  EXPECT_EQ(projected.path(), DualPath::projected_cg);
  EXPECT_GT(projected.coarse_dimension(), 0);

  // Both bodies fixed, one subdomain each: coercive contact -> MPRGP, no coarse space.
  test::MembraneOptions coercive = test::membrane_options(8, 1);
  coercive.fix_right_body = true;
  const FetiProblem mprgp_scene = membrane_problem(coercive, FetiVariant::feti1);
  EXPECT_EQ(mprgp_scene.path(), DualPath::mprgp);
  EXPECT_EQ(mprgp_scene.coarse_dimension(), 0);
  const FetiResult r = mprgp_scene.solve();
  EXPECT_EQ(r.status, SolveStatus::converged);
  EXPECT_EQ(r.phases.find("coarse"), std::string::npos);
  EXPECT_GT(r.counts.hessian_norm_estimate, 0);

  EXPECT_EQ(membrane_problem(test::membrane_options(8, 2), FetiVariant::feti1).path(), DualPath::smalbe);

  // Each path's solution satisfies the primal KKT conditions.
  for (const test::MembraneOptions& o : {single, glued, coercive}) {
    const FetiResult result = membrane_problem(o, FetiVariant::feti1).solve();
    EXPECT_EQ(result.status, SolveStatus::converged);
    EXPECT_LT(result.kkt.max(), 1e-3) << path_name(result.path);
  }
}

TEST(FetiProblem, CoarseSpaceOnlyWhereSomethingFloats) {
  test::MembraneOptions o = test::membrane_options(8, 1);
  o.fix_right_body = true;
  const FetiProblem problem = membrane_problem(o, FetiVariant::feti1);
  EXPECT_EQ(problem.floating_subdomains(), 0);
  EXPECT_EQ(problem.setup_times().coarse_space, 0.0);
  const FetiProblem total = membrane_problem(o, FetiVariant::tfeti);
  EXPECT_EQ(total.floating_subdomains(), 2);  // Total FETI: every subdomain floats
}

TEST(FetiProblem, SecondLoadCaseReusesTheFactorizations) {
  FetiProblem problem = membrane_problem(test::membrane_options(16, 2), FetiVariant::feti1);
  auto subs = test::membrane_subdomains(test::membrane_options(16, 2));
  std::vector<Vec> doubled;
  for (auto& s : subs) doubled.push_back(2.0 * s.f);
  problem.set_loads(doubled);
  DualSolveSettings settings;
  settings.tolerance = 1e-10;
  const FetiResult reused = problem.solve(settings);
  for (auto& s : subs) s.f *= 2.0;
  const FetiProblem fresh(std::move(subs), test::membrane_contact(test::membrane_subdomains(test::membrane_options(16, 2))));
  const FetiResult direct = fresh.solve(settings);
  ASSERT_EQ(reused.status, SolveStatus::converged);
  EXPECT_NEAR(reused.energy, direct.energy, 1e-9 * std::abs(direct.energy));
  // Linear scaling: doubling the load doubles u and multiplies the energy by 4.
  const FetiResult single = membrane_problem(test::membrane_options(16, 2), FetiVariant::feti1).solve(settings);
  EXPECT_NEAR(reused.energy, 4 * single.energy, 1e-8 * std::abs(reused.energy));
}

TEST(FetiProblem, ThreadCountDoesNotChangeTheResult) {
  const FetiResult one = membrane_problem(test::membrane_options(32, 4), FetiVariant::feti1, 1).solve();
  const FetiResult two = membrane_problem(test::membrane_options(32, 4), FetiVariant::feti1, 2).solve();
  EXPECT_EQ(one.counts.hessian, two.counts.hessian);
  EXPECT_EQ(one.counts.outer, two.counts.outer);
  EXPECT_EQ(one.lambda, two.lambda);  // bitwise: the scatter order is fixed
}

TEST(FetiProblem, IdenticalSubdomainsShareOneFactorAndGiveTheSameAnswerBitForBit) {
  // h = 1/32, H = 1/4: coordinates exact in binary, so the boxes of one position class
  // (interior, each side, each corner, per body) assemble bitwise equal matrices.
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti}) {
    std::vector<FetiResult> results;
    std::vector<long> factorizations, shared;
    for (bool share : {true, false}) {
      auto subs = test::membrane_subdomains(test::membrane_options(32, 4));
      const ContactInput contact = test::membrane_contact(subs);
      FetiSetupSettings setup;
      setup.variant = variant;
      setup.threads = 2;  // subdomains sharing a factor solve on both threads at once
      setup.share_factors = share;
      const FetiProblem problem(std::move(subs), contact, setup);
      results.push_back(problem.solve());
      factorizations.push_back(problem.factorizations());
      shared.push_back(problem.shared_factors());
      EXPECT_EQ(problem.factorizations() + problem.shared_factors(), problem.subdomain_count());
    }
    EXPECT_GT(shared[0], 16) << "of 32 subdomains, interior and side boxes repeat";
    EXPECT_EQ(shared[1], 0);
    ASSERT_EQ(results[0].status, SolveStatus::converged);
    EXPECT_EQ(results[0].counts.hessian, results[1].counts.hessian);
    EXPECT_EQ(results[0].lambda, results[1].lambda);  // bitwise: the same factor values
  }
}

TEST(FetiProblem, TheDirichletPreconditionerFactorizesEqualInteriorBlocksOnce) {
  std::vector<FetiResult> results;
  std::vector<long> set_up_factorizations;
  for (bool share : {true, false}) {
    auto subs = test::membrane_subdomains(test::membrane_options(32, 4));
    const ContactInput contact = test::membrane_contact(subs);
    FetiSetupSettings setup;
    setup.preconditioner = DualPreconditioner::dirichlet;
    setup.threads = 2;  // subdomains sharing a K_ii factor solve on both threads at once
    setup.share_factors = share;
    const long before = CholmodFactor::factorizations_in_process();
    const FetiProblem problem(std::move(subs), contact, setup);
    set_up_factorizations.push_back(CholmodFactor::factorizations_in_process() - before);
    results.push_back(problem.solve());
  }
  // Without sharing: 32 subdomain factors and 32 K_ii; with it fewer of each.
  EXPECT_EQ(set_up_factorizations[1], 64);
  EXPECT_LT(set_up_factorizations[0], 32);
  ASSERT_EQ(results[0].status, SolveStatus::converged);
  EXPECT_EQ(results[0].counts.hessian, results[1].counts.hessian);
  EXPECT_EQ(results[0].lambda, results[1].lambda);  // bitwise: the same factor values
}

TEST(FetiProblem, ASolveEndingAtItsLastCheckedMultipliersKeepsTheirRecoveredField) {
  // The stopping test recovers u at the multipliers it accepts; the solve returns that u
  // (no second recovery), which must be the recovery of the returned lambda bit for bit.
  auto subs = test::membrane_subdomains(test::membrane_options(16, 2));
  const ContactInput contact = test::membrane_contact(subs);
  std::vector<Vec> loads;
  for (const SubdomainInput& s : subs) loads.push_back(s.f);
  FetiSetupSettings setup;
  setup.variant = FetiVariant::tfeti;  // F's loads are the subdomains' f
  const FetiProblem problem(std::move(subs), contact, setup);
  const FetiResult result = problem.solve();
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_EQ(result.times.recovery, 0.0) << "recovered again instead of kept";
  const Constraints& rows = problem.dual().constraints();
  const Vec c = Eigen::Map<const Vec>(rows.rhs.data(), rows.rows());
  const std::vector<Vec> u =
      recover_primal(problem.dual().F(), problem.dual().coarse(), rows, loads, c, result.lambda, Vec());
  ASSERT_EQ(u.size(), result.u.size());
  for (size_t s = 0; s < u.size(); ++s) EXPECT_EQ(u[s], result.u[s]) << "subdomain " << s;
}

TEST(FetiProblem, SubdomainsDifferingInOneValueDoNotShare) {
  auto subs = test::membrane_subdomains(test::membrane_options(32, 4));
  const ContactInput contact = test::membrane_contact(subs);
  // A stiffer material in one interior box of body 1: same pattern, other values.
  const auto changed = static_cast<size_t>(16 + 5);
  subs[changed].K.edit() *= 1.0 + 1e-15;
  const FetiProblem problem(std::move(subs), contact);
  auto same = test::membrane_subdomains(test::membrane_options(32, 4));
  const FetiProblem reference(std::move(same), contact);
  EXPECT_EQ(problem.shared_factors(), reference.shared_factors() - 1);
  EXPECT_EQ(problem.factorizations() + problem.shared_factors(), problem.subdomain_count());
}

TEST(FetiProblem, AStartAtTheSolutionCostsAFewMultiplicationsAndAnyStartConverges) {
  // Every dual path: projected CG (glued, floating), MPRGP (both membranes fixed, pressed
  // into each other by a negative gap: some couples active), SMALBE-M with the free-rows
  // projector and with all of G penalized (floating contact).
  test::MembraneOptions glued = test::membrane_options(16, 2);
  glued.body2 = false;
  glued.with_contact = false;
  test::MembraneOptions coercive = test::membrane_options(16, 1);
  coercive.fix_right_body = true;
  const test::MembraneOptions floating = test::membrane_options(16, 2);
  struct Case {
    test::MembraneOptions options;
    double gap;
    CoarseConstraints coarse;
    DualPath path;
  };
  for (const Case& c : {Case{glued, 0.0, CoarseConstraints::free_rows, DualPath::projected_cg},
                        Case{coercive, -0.2, CoarseConstraints::free_rows, DualPath::mprgp},
                        Case{floating, 0.0, CoarseConstraints::free_rows, DualPath::smalbe},
                        Case{floating, 0.0, CoarseConstraints::penalty, DualPath::smalbe}}) {
    auto subs = test::membrane_subdomains(c.options);
    ContactInput contact = c.options.with_contact ? test::membrane_contact(subs) : ContactInput{};
    contact.gap = c.gap;
    const FetiProblem problem(std::move(subs), contact, FetiSetupSettings{});
    ASSERT_EQ(problem.path(), c.path);
    DualSolveSettings settings;
    settings.coarse_constraints = c.coarse;
    settings.tolerance = 1e-8;
    const FetiResult cold = problem.solve(settings);
    ASSERT_EQ(cold.status, SolveStatus::converged) << path_name(c.path);
    EXPECT_GE(cold.counts.hessian, 10) << path_name(c.path);  // a start that saves something
    if (c.options.with_contact) EXPECT_GT(cold.active_contact, 0) << path_name(c.path);
    settings.start = cold.lambda;
    const FetiResult warm = problem.solve(settings);
    ASSERT_EQ(warm.status, SolveStatus::converged) << path_name(c.path);
    EXPECT_LE(warm.counts.hessian, 3) << path_name(c.path) << " cold: " << cold.counts.hessian;
    EXPECT_NEAR(warm.energy, cold.energy, 1e-10 * std::abs(cold.energy)) << path_name(c.path);
    // A start off the feasible set (pulling contact forces, G lambda != e) is moved onto it.
    settings.start = Vec::Random(cold.lambda.size()) * cold.lambda.lpNorm<Eigen::Infinity>();
    const FetiResult any = problem.solve(settings);
    ASSERT_EQ(any.status, SolveStatus::converged) << path_name(c.path);
    EXPECT_NEAR(any.energy, cold.energy, 1e-7 * std::abs(cold.energy)) << path_name(c.path);
    EXPECT_LT(any.kkt.max(), 1e-7) << path_name(c.path);
    EXPECT_EQ(any.active_contact, cold.active_contact) << path_name(c.path);
  }
}

TEST(FetiProblem, NonConvergenceIsAStatusNotAnException) {
  const FetiProblem problem = membrane_problem(test::membrane_options(16, 2), FetiVariant::feti1);
  DualSolveSettings settings;
  settings.max_hessian = 3;
  const FetiResult result = problem.solve(settings);
  EXPECT_EQ(result.status, SolveStatus::max_iterations);
  EXPECT_EQ(result.u.size(), 8u);  // the last iterate is still returned
}

TEST(FetiProblem, BadInputIsAnErrorNamingTheArgument) {
  const auto make = [](const std::function<void(std::vector<SubdomainInput>&)>& spoil) {
    auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
    const ContactInput contact = test::membrane_contact(subs);
    spoil(subs);
    FetiProblem problem(std::move(subs), contact);
  };
  const FetiProblem problem = membrane_problem(test::membrane_options(8, 2), FetiVariant::feti1);
  DualSolveSettings wrong_start;
  wrong_start.start = Vec::Zero(problem.constraints().rows() + 1);
  expect_input_error([&] { problem.solve(wrong_start); }, "start: has");
  wrong_start.start = Vec::Zero(problem.constraints().rows());
  wrong_start.start[0] = NAN;
  expect_input_error([&] { problem.solve(wrong_start); }, "start: has entries that are not finite");
  expect_input_error([&] { make([](auto& s) { s[2].K.edit().coeffRef(0, 1) += 1.0; }); }, "K[2]: not symmetric");
  // An entry whose mirror is not stored at all, above and below the diagonal.
  expect_input_error([&] { make([](auto& s) { s[2].K.edit().coeffRef(0, s[2].K.cols() - 1) = 1.0; }); }, "K[2]: not symmetric");
  expect_input_error([&] { make([](auto& s) { s[1].K.edit().coeffRef(s[1].K.rows() - 1, 0) = 1.0; }); }, "K[1]: not symmetric");
  // Checked on threads, named as a serial loop would: the lowest bad subdomain.
  expect_input_error([&] {
    make([](auto& s) {
      s[3].K.edit().coeffRef(0, 1) += 1.0;
      s[1].f[0] = NAN;
    });
  }, "F[1]");
  expect_input_error([&] { make([](auto& s) { s[1].f.conservativeResize(3); }); }, "F[1]");
  expect_input_error([&] { make([](auto& s) { s[3].f[0] = NAN; }); }, "F[3]");
  expect_input_error([&] { make([](auto& s) { s[0].K.edit().coeffRef(0, 0) = INFINITY; }); }, "K[0]");
  expect_input_error([&] { make([](auto& s) { s[1].x.pop_back(); }); }, "X[1]");
  expect_input_error([&] { make([](auto& s) { s[0].dirichlet_dofs.push_back(100000); }); }, "dirichlet[0]");
  expect_input_error([&] { make([](auto& s) { s[2].y[5] = NAN; }); }, "X[2], Y[2]: the coordinates of dof 5");
  expect_input_error([&] { make([](auto& s) { s[3].body = -1; }); }, "body[3]");
  expect_input_error([&] {
    make([](auto& s) {
      s[0].dirichlet_values.assign(s[0].dirichlet_dofs.size(), 0.0);
      s[0].dirichlet_values[1] = NAN;
    });
  }, "dirichletValues[0]: entry 1");
  // A floating body with no condition at all: its rigid mode is unrestrained.
  expect_input_error([] {
    auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
    FetiProblem problem(std::move(subs), ContactInput{});
  }, "body 1");
  // Node-to-node partners and an obstacle for the same slaves: ambiguous, refused.
  expect_input_error([] {
    auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
    ContactInput contact = test::membrane_contact(subs);
    contact.obstacle = true;
    FetiProblem problem(std::move(subs), contact);
  }, "contactMaster");
  // Positive diagonal but indefinite (a large symmetric off-diagonal pair between free
  // dofs), in a subdomain touching the Dirichlet boundary and in a floating one: the
  // simplicial LDL' factor would complete with a negative D and the solve find a saddle
  // point; it must be an error naming K[s].
  for (int s : {0, 5})
    for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti})
      expect_input_error([&] {
        auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
        const ContactInput contact = test::membrane_contact(subs);
        const double d = subs[static_cast<size_t>(s)].K.get().coeff(12, 12);
        subs[static_cast<size_t>(s)].K.edit().coeffRef(12, 13) += 5 * d;
        subs[static_cast<size_t>(s)].K.edit().coeffRef(13, 12) += 5 * d;
        FetiSetupSettings setup;
        setup.variant = variant;
        FetiProblem problem(std::move(subs), contact, setup);
      }, "K[" + std::to_string(s) + "]: not positive definite");
  DualSolveSettings bad;
  bad.tolerance = 0;
  expect_input_error([&] { membrane_problem(test::membrane_options(8, 1), FetiVariant::feti1).solve(bad); }, "tol");
}

}  // namespace
TEST(Threads, TheDefaultLeavesBusyCoresToOthersAndAnExplicitCountAlone) {
  // Between 1 and the cores asked for, whatever the machine's load now.
  const int adapted = threads_for_load(4);
  EXPECT_GE(adapted, 1);
  EXPECT_LE(adapted, 4);
  // OMP_NUM_THREADS set by the user: the count stands.
  const char* before = std::getenv("OMP_NUM_THREADS");
  const std::string saved = before ? before : "";
  setenv("OMP_NUM_THREADS", "3", 1);
  EXPECT_EQ(threads_for_load(64), 64);
  if (before) setenv("OMP_NUM_THREADS", saved.c_str(), 1);
  else unsetenv("OMP_NUM_THREADS");
}

}  // namespace ffeti
