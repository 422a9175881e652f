#include "feti/coarse_space.h"
#include "constraints/contact/node_to_node.h"
#include "feti/dual_operator.h"
#include "base/errors.h"
#include "feti/feti_problem.h"
#include "feti/kernel.h"
#include "service/options.h"
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

using test::membrane_problem;

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

TEST(FetiProblem, StiffnessScalingIsMultiplicityWhereTheSidesAreEquallyStiff) {
  // Regular membranes, 4 x 4 subdomains per body with cross points: every row's sides are
  // equally stiff, and the stiffness weights reduce to the multiplicity ones, bit for bit
  // in the counts. Body 0 graded towards the contact line (its cells 1000 times narrower
  // there; 2 x 2 subdomains per body: the sides of its rows differ): the same solution either
  // way, and with the lumped preconditioner in fewer than half the multiplications (114
  // against 287 when written). Both preconditioners (Dirichlet: the weights around S_s;
  // there the graded mesh took 89 against 78: the same answer, no gain).
  for (DualPreconditioner kind : {DualPreconditioner::lumped, DualPreconditioner::dirichlet})
  for (bool graded : {false, true}) {
    test::MembraneOptions o = test::membrane_options(64, graded ? 2 : 4);
    if (graded) o.x_map = test::graded_towards_contact(64, 1000.0);
    DualSolveSettings settings;
    settings.tolerance = 1e-10;
    const FetiResult m = membrane_problem(o, FetiVariant::feti1, 0, kind).solve(settings);
    const FetiResult k = membrane_problem(o, FetiVariant::feti1, 0, kind, InterfaceScaling::stiffness).solve(settings);
    ASSERT_EQ(m.status, SolveStatus::converged);
    ASSERT_EQ(k.status, SolveStatus::converged);
    EXPECT_NEAR(k.energy, m.energy, 1e-9 * std::abs(m.energy));
    EXPECT_EQ(k.active_contact, m.active_contact);
    EXPECT_LT(k.kkt.max(), 1e-9);
    if (!graded) {
      EXPECT_EQ(k.counts.hessian, m.counts.hessian);
    } else if (kind == DualPreconditioner::lumped) {
      EXPECT_LT(2 * k.counts.hessian, m.counts.hessian)
          << "multiplicity " << m.counts.hessian << ", stiffness " << k.counts.hessian;
    }
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
    contact.input_of<NodeToNodeInput>().gap = c.gap;
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

}  // namespace

}  // namespace ffeti
