#include "qp/smalbe.h"
#include "qp_test_problems.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace ffeti {
namespace {

struct Case {
  int n, k;
  double condition;
  unsigned seed;
  SmalbeVariant variant;
};

/// Shown by GoogleTest for a failing case (instead of a byte dump).
void PrintTo(const Case& c, std::ostream* os) {
  *os << "n=" << c.n << " k=" << c.k << " condition=" << c.condition << " seed=" << c.seed << " "
      << (c.variant == SmalbeVariant::smalbe_m ? "smalbe_m" : "seed_alg31");
}

class SmalbeManufactured : public ::testing::TestWithParam<Case> {};

TEST_P(SmalbeManufactured, FindsTheKnownSolution) {
  const Case c = GetParam();
  const test::BoundEqualityQp qp = test::manufactured_bound_equality_qp(c.n, c.k, c.condition, c.seed);
  qp::Problem problem = test::bound_problem(test::dense_operator(qp.H), qp.b, qp.lower, 1.05 * c.condition);
  problem.range_projector = test::dense_operator(qp.Q);
  SmalbeSettings settings;
  settings.variant = c.variant;
  Vec x = Vec::Zero(c.n);
  const double tol = 1e-10 * qp.b.norm();
  qp::Budget budget(5000);
  const SmalbeResult result = smalbe(problem, settings, x, budget, [&](const Vec& xi, const Vec&, double gp) {
    return gp <= tol && (qp.Q * xi).norm() <= 1e-10;
  });
  ASSERT_EQ(result.status, SolveStatus::converged) << to_string(result.status);
  EXPECT_LT((x - qp.x_star).norm(), 1e-6 * qp.x_star.norm());
  EXPECT_LT((qp.C * x).norm(), 1e-8 * qp.C.norm() * qp.x_star.norm());
  for (int i = 0; i < c.n; ++i)
    if (qp.lower[i] != kUnbounded) EXPECT_GE(x[i], qp.lower[i]);
  EXPECT_GE(result.counts.outer, 1);
}

INSTANTIATE_TEST_SUITE_P(
    Seeds, SmalbeManufactured,
    ::testing::Values(Case{30, 3, 10, 1, SmalbeVariant::smalbe_m},
                      Case{80, 8, 100, 2, SmalbeVariant::smalbe_m},
                      Case{30, 3, 10, 1, SmalbeVariant::seed_alg31},
                      Case{80, 8, 100, 2, SmalbeVariant::seed_alg31}),
    [](const auto& info) {
      return std::string(info.param.variant == SmalbeVariant::smalbe_m ? "smalbe_m" : "seed_alg31") + "_n" +
             std::to_string(info.param.n) + "_seed" + std::to_string(info.param.seed);
    });

TEST(Smalbe, IterationLimitIsAStatus) {
  const test::BoundEqualityQp qp = test::manufactured_bound_equality_qp(60, 5, 1e3, 9);
  qp::Problem problem = test::bound_problem(test::dense_operator(qp.H), qp.b, qp.lower, 1.05e3);
  problem.range_projector = test::dense_operator(qp.Q);
  Vec x = Vec::Zero(60);
  qp::Budget budget(10);
  const SmalbeResult result =
      smalbe(problem, SmalbeSettings{}, x, budget, [](const Vec&, const Vec&, double gp) { return gp <= 0; });
  EXPECT_EQ(result.status, SolveStatus::max_iterations);
  EXPECT_LE(result.counts.hessian, 10 + 2);  // a step in progress may finish (<= 2 products)
  EXPECT_EQ(budget.spent(), result.counts.hessian);  // the inner solves charged it, once each
}

TEST(Smalbe, ASecondSolveGetsWhatTheFirstLeft) {
  // One budget over two solves (friction's fixed point passes one down its Tresca solves).
  const test::BoundEqualityQp qp = test::manufactured_bound_equality_qp(60, 5, 1e3, 9);
  qp::Problem problem = test::bound_problem(test::dense_operator(qp.H), qp.b, qp.lower, 1.05e3);
  problem.range_projector = test::dense_operator(qp.Q);
  const StopTest tight = [&](const Vec&, const Vec&, double gp) { return gp <= 1e-8 * qp.b.norm(); };
  qp::Budget budget(1000);
  Vec x = Vec::Zero(60);
  const SmalbeResult first = smalbe(problem, SmalbeSettings{}, x, budget, tight);
  ASSERT_EQ(first.status, SolveStatus::converged);
  ASSERT_GT(first.counts.hessian, 20);
  budget = qp::Budget(first.counts.hessian + 20);
  budget.charge(first.counts.hessian);  // as if the first solve had run on it
  Vec y = Vec::Zero(60);
  const SmalbeResult second = smalbe(problem, SmalbeSettings{}, y, budget, tight);
  EXPECT_EQ(second.status, SolveStatus::max_iterations);  // 20 left: too few for a cold start
  EXPECT_LE(second.counts.hessian, 20 + 2);
  EXPECT_EQ(budget.spent(), first.counts.hessian + second.counts.hessian);
}

TEST(Smalbe, RejectsInvalidSettings) {
  SmalbeSettings settings;
  settings.beta = 1.0;
  EXPECT_THROW(settings.validate(), std::invalid_argument);
  settings = {};
  settings.alpha = 1.5;
  EXPECT_THROW(settings.validate(), std::invalid_argument);
}

}  // namespace
}  // namespace ffeti
