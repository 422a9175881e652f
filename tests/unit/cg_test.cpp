#include "qp/conjugate_gradient.h"
#include "qp_test_problems.h"

#include <gtest/gtest.h>

namespace ffeti {
namespace {

TEST(ConjugateGradient, SolvesAnSpdSystem) {
  const Eigen::MatrixXd A = test::random_spd(50, 100, 3);
  const Vec x_star = Vec::LinSpaced(50, -1, 1);
  const Vec b = A * x_star;
  Vec x = Vec::Zero(50), g;
  const CgResult result = conjugate_gradient(test::dense_operator(A), b, x, g, {},
      [&](const Vec&, const Vec&, double norm) { return norm <= 1e-12 * b.norm(); });
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_LT((x - x_star).norm(), 1e-9 * x_star.norm());
  EXPECT_LE(result.counts.cg, 2 * 50);  // n steps in exact arithmetic, a few more in rounding
  // The initial gradient, one per step, and the true gradient checked at the end.
  EXPECT_EQ(result.counts.hessian, result.counts.cg + 2);
  EXPECT_LE((A * x - b).norm(), 1e-12 * b.norm());
}

TEST(ConjugateGradient, ToleranceBelowRoundOffIsStagnationNotConvergence) {
  const Eigen::MatrixXd A = test::random_spd(50, 1e8, 5);
  const Vec b = A * Vec::LinSpaced(50, -1, 1);
  Vec x = Vec::Zero(50), g;
  const CgResult result = conjugate_gradient(test::dense_operator(A), b, x, g, {},
      [&](const Vec&, const Vec&, double norm) { return norm <= 1e-20 * b.norm(); });
  EXPECT_EQ(result.status, SolveStatus::stagnated);
  EXPECT_NEAR(result.gradient_norm, (A * x - b).norm(), 1e-12 * b.norm());  // the true gradient
}

TEST(ConjugateGradient, ProjectedOperatorStaysInTheSubspace) {
  // A = P M P with P the projector onto Ker C: CG from 0 on b in Ker C stays in Ker C.
  const Eigen::MatrixXd M = test::random_spd(40, 50, 4);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2, 40);
  C.row(0).head(20).setOnes();
  C.row(1).tail(20).setOnes();
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(40, 40) -
                            C.transpose() * (C * C.transpose()).inverse() * C;
  const Eigen::MatrixXd A = P * M * P;
  const Vec b = P * Vec::LinSpaced(40, 0, 3);
  Vec x = Vec::Zero(40), g;
  const CgResult result = conjugate_gradient(test::dense_operator(A), b, x, g, {},
      [&](const Vec&, const Vec&, double norm) { return norm <= 1e-11 * b.norm(); });
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_LT((C * x).norm(), 1e-10);
  EXPECT_LT((P * (M * x) - b).norm(), 1e-9 * b.norm());
}

TEST(ConjugateGradient, IndefiniteOperatorIsReported) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(1, 1) = -2;
  const Vec b = Vec::Ones(3);
  Vec x = Vec::Zero(3), g;
  const CgResult result = conjugate_gradient(test::dense_operator(A), b, x, g, {},
      [](const Vec&, const Vec&, double norm) { return norm <= 1e-14; });
  EXPECT_EQ(result.status, SolveStatus::not_positive_definite);
}

}  // namespace
}  // namespace ffeti
