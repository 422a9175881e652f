#include "qp/mprgp.h"
#include "qp/norm_estimate.h"
#include "qp_test_problems.h"

#include <gtest/gtest.h>

#include <ostream>
#include <string>

namespace ffeti {
namespace {

struct Case {
  int n;
  double condition;
  unsigned seed;
  bool some_unbounded;
};

/// Shown by GoogleTest for a failing case (instead of a byte dump).
void PrintTo(const Case& c, std::ostream* os) {
  *os << "n=" << c.n << " condition=" << c.condition << " seed=" << c.seed
      << (c.some_unbounded ? " some unbounded" : " all bounded");
}

class MprgpManufactured : public ::testing::TestWithParam<Case> {};

TEST_P(MprgpManufactured, FindsTheKnownSolution) {
  const Case c = GetParam();
  const test::BoundQp qp = test::manufactured_bound_qp(c.n, c.condition, c.seed, c.some_unbounded);
  const LinearOperator A = test::dense_operator(qp.A);
  const NormEstimate norm = estimate_norm(A, c.n);
  // The estimate is within a few percent above ||A||_2 = condition.
  EXPECT_GT(norm.norm, 0.9 * c.condition);
  EXPECT_LT(norm.norm, 1.06 * c.condition);
  for (MprgpExpansion expansion :
       {MprgpExpansion::fixed_step, MprgpExpansion::projected_cg_restart, MprgpExpansion::projected_cg}) {
    Vec x = Vec::Zero(c.n), g;
    const double tol = 1e-10 * qp.b.norm();
    MprgpSettings settings;
    settings.expansion = expansion;
    const MprgpResult result = mprgp_with_gradient(test::bound_problem(A, qp.b, qp.lower, norm.norm), settings, x, g, false, test::large_budget(),
                                     [&](const Vec&, const Vec&, double gp) { return gp <= tol; });
    ASSERT_EQ(result.status, SolveStatus::converged);
    EXPECT_LT((x - qp.x_star).norm(), 1e-7 * qp.x_star.norm());
    // Independent KKT check: feasibility, sign of the gradient on the active set.
    const Vec gradient = qp.A * x - qp.b;
    EXPECT_LT((gradient - g).norm(), 1e-9 * qp.b.norm());
    for (int i = 0; i < c.n; ++i) {
      if (qp.lower[i] == kUnbounded) continue;
      EXPECT_GE(x[i], qp.lower[i]);
      EXPECT_GE(gradient[i], -1e-8 * qp.b.norm());
    }
    EXPECT_GT(result.counts.hessian, 0);
    // An expansion costs the CG trial step's multiplication and its own; a projected CG
    // expansion that falls back to the fixed step one more.
    EXPECT_EQ(result.counts.hessian, 1 + result.counts.cg + 2 * result.counts.expansion +
                                         result.counts.proportioning + result.counts.expansion_fallback);
    if (expansion == MprgpExpansion::fixed_step) EXPECT_EQ(result.counts.expansion_fallback, 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Seeds, MprgpManufactured,
                         ::testing::Values(Case{20, 10, 1, false}, Case{60, 100, 2, true},
                                           Case{100, 1000, 3, true}, Case{40, 1, 4, false}),
                         [](const auto& info) {
                           return "n" + std::to_string(info.param.n) + "_seed" + std::to_string(info.param.seed);
                         });

TEST(Mprgp, StartsFromAnInfeasiblePointAndProjectsIt) {
  const test::BoundQp qp = test::manufactured_bound_qp(30, 50, 11, false);
  Vec x = Vec::Constant(30, -100.0), g;
  const MprgpResult result =
      mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 55), MprgpSettings{}, x, g, false, test::large_budget(),
            [&](const Vec&, const Vec&, double gp) { return gp <= 1e-10 * qp.b.norm(); });
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_LT((x - qp.x_star).norm(), 1e-7 * qp.x_star.norm());
}

TEST(Mprgp, ReportsTheIterationLimitInsteadOfHiding) {
  const test::BoundQp qp = test::manufactured_bound_qp(80, 1e4, 5, false);
  Vec x = Vec::Zero(80);
  qp::Budget budget(5);
  const MprgpResult result = mprgp(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 1.05e4), MprgpSettings{},
                                   x, budget, [](const Vec&, const Vec&, double gp) { return gp <= 0; });
  EXPECT_EQ(result.status, SolveStatus::max_iterations);
  EXPECT_LE(result.counts.hessian, 5 + 2);  // a step in progress may finish (<= 2 products)
  EXPECT_GT(result.gradient_norm, 0);
  EXPECT_EQ(budget.spent(), result.counts.hessian);  // charged with what it spent
  EXPECT_TRUE(budget.exhausted());
}

TEST(Mprgp, DetectsAnIndefiniteOperator) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(4, 4);
  A(2, 2) = -1;
  const Vec b = Vec::Ones(4), lower = Vec::Constant(4, kUnbounded);
  Vec x = Vec::Zero(4), g;
  const MprgpResult result = mprgp_with_gradient(test::bound_problem(test::dense_operator(A), b, lower, 1.0), MprgpSettings{}, x, g, false, test::large_budget(),
                                   [](const Vec&, const Vec&, double gp) { return gp <= 1e-12; });
  EXPECT_EQ(result.status, SolveStatus::not_positive_definite);
}

TEST(Mprgp, RejectsAnEmptyBudget) { EXPECT_THROW(qp::Budget(0), std::invalid_argument); }

TEST(Mprgp, RejectsInvalidSettings) {
  MprgpSettings settings;
  settings.step_factor = 2.5;
  EXPECT_THROW(settings.validate(), std::invalid_argument);
  settings = {};
  settings.gamma = 0;
  EXPECT_THROW(settings.validate(), std::invalid_argument);
}

TEST(ProjectedGradient, ChopsNegativePartsOnlyOnTheActiveSet) {
  const Vec x = (Vec(4) << 0, 1, 0, 2).finished();
  const Vec g = (Vec(4) << -1, -1, 3, 5).finished();
  const Vec lower = (Vec(4) << 0, 0, 0, kUnbounded).finished();
  const Vec gp = qp::ConstraintSet::from_bounds(lower).projected_gradient(x, g);
  EXPECT_EQ(gp, (Vec(4) << -1, -1, 0, 5).finished());
}

}  // namespace
}  // namespace ffeti
