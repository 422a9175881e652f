#include "qp/mprgp.h"
#include "qp/start_settling.h"
#include "qp_test_problems.h"

#include <gtest/gtest.h>

#include <random>

namespace ffeti {
namespace {

double cost(const test::BoundQp& qp, const Vec& x) { return 0.5 * x.dot(qp.A * x) - qp.b.dot(x); }

/// The known solution with its active bounds wrongly freed (a small positive value, as a
/// start carried from a coarser mesh has couples in contact that should not be) and every
/// free component perturbed: the set is nearly right, the values are not.
Vec nearly_right_start(const test::BoundQp& qp, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> noise(-0.3, 0.3);
  Vec x = qp.x_star;
  int freed = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (qp.lower[i] != kUnbounded && x[i] == qp.lower[i]) {
      if (freed++ % 2 == 0) x[i] += 0.05 * qp.x_star.cwiseAbs().maxCoeff();
    } else {
      x[i] *= 1 + noise(random);
    }
  }
  return x;
}

TEST(SettleStart, LowersTheCostAndKeepsTheIterateFeasibleAndItsGradientExact) {
  const test::BoundQp qp = test::manufactured_bound_qp(60, 200, 7, true);
  Vec x = nearly_right_start(qp, 1);
  qp::ConstraintSet::from_bounds(qp.lower).project(x);
  Vec g = qp.A * x - qp.b;
  const double before = cost(qp, x);
  IterationCounts counts;
  settle_start(test::dense_operator(qp.A), qp.b, qp::ConstraintSet::from_bounds(qp.lower), 2, 1000, x, g, counts);
  EXPECT_LT(cost(qp, x), before);
  EXPECT_GT(counts.settle, 0);
  EXPECT_GE(counts.hessian, counts.settle);
  EXPECT_LE(counts.hessian, counts.settle + 2);  // one product per CG step, one per projection
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (qp.lower[i] != kUnbounded) EXPECT_GE(x[i], qp.lower[i]);
  EXPECT_LT((qp.A * x - qp.b - g).norm(), 1e-10 * qp.b.norm());
}

TEST(SettleStart, KeepsTheStartWhenTheProjectedFaceSolutionCostsMore) {
  // min 1/2 x'Ax - b'x, x_0 >= 0: the solution (0, 0.5) has x_0 strictly active (g_0 = 3.5).
  // From (1e-3, 0.5) both components are free; the face solve reaches the unconstrained
  // minimizer (-7/3, 5/3), whose projection (0, 5/3) costs 10/9 against -0.2465 at the start.
  test::BoundQp qp;
  qp.A = (Eigen::MatrixXd(2, 2) << 2, 1, 1, 2).finished();
  qp.b = (Vec(2) << -3, 1).finished();
  qp.lower = (Vec(2) << 0, kUnbounded).finished();
  const Vec start = (Vec(2) << 1e-3, 0.5).finished();
  Vec x = start, g = qp.A * x - qp.b;
  const Vec g_start = g;
  IterationCounts counts;
  settle_start(test::dense_operator(qp.A), qp.b, qp::ConstraintSet::from_bounds(qp.lower), 2, 100, x, g, counts);
  EXPECT_EQ(counts.settle, 2);    // the face solve ran
  EXPECT_EQ(counts.hessian, 3);  // two CG steps and the projected point's gradient
  EXPECT_EQ(x, start);           // and was not kept
  EXPECT_EQ(g, g_start);
}

TEST(SettleStart, StaysWithinTheMultiplicationBudget) {
  const test::BoundQp qp = test::manufactured_bound_qp(60, 1e4, 8, false);
  Vec x = nearly_right_start(qp, 2);
  qp::ConstraintSet::from_bounds(qp.lower).project(x);
  Vec g = qp.A * x - qp.b;
  IterationCounts counts;
  settle_start(test::dense_operator(qp.A), qp.b, qp::ConstraintSet::from_bounds(qp.lower), 5, 4, x, g, counts);
  EXPECT_LE(counts.hessian, 4);
  EXPECT_LT((qp.A * x - qp.b - g).norm(), 1e-10 * qp.b.norm());
}

TEST(MprgpSettled, ReachesTheKnownSolutionFromANearlyRightStart) {
  const test::BoundQp qp = test::manufactured_bound_qp(80, 500, 9, true);
  for (int rounds : {0, 1, 2}) {
    MprgpSettings settings;
    settings.settle_rounds = rounds;
    Vec x = nearly_right_start(qp, 3), g;
    const double tol = 1e-10 * qp.b.norm();
    const MprgpResult result = mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 510), settings, x, g, false, test::large_budget(),
                                     [&](const Vec&, const Vec&, double gp) { return gp <= tol; });
    ASSERT_EQ(result.status, SolveStatus::converged) << rounds << " rounds";
    EXPECT_LT((x - qp.x_star).norm(), 1e-7 * qp.x_star.norm()) << rounds << " rounds";
    EXPECT_EQ(result.counts.settle > 0, rounds > 0);
  }
}

TEST(MprgpSettled, ReturnsAStartThatAlreadyPassesTheTestUntouched) {
  const test::BoundQp qp = test::manufactured_bound_qp(40, 100, 10, false);
  MprgpSettings settings;
  settings.settle_rounds = 2;
  Vec x = qp.x_star, g;
  const MprgpResult result = mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 105), settings, x, g, false, test::large_budget(),
                                   [&](const Vec&, const Vec&, double gp) { return gp <= 1e-8 * qp.b.norm(); });
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_EQ(result.counts.hessian, 1);  // the start's gradient only
  EXPECT_EQ(result.counts.settle, 0);
  EXPECT_EQ(x, qp.x_star);
}

TEST(MprgpSettled, RejectsANegativeRoundCount) {
  MprgpSettings settings;
  settings.settle_rounds = -1;
  EXPECT_THROW(settings.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace ffeti
