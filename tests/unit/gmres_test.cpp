#include "qp/gmres.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

namespace ffeti {
namespace {

/// A nonsymmetric, well-conditioned n x n matrix: the identity plus a small skew part and a
/// small random-like part (deterministic).
Eigen::MatrixXd nonsymmetric(int n) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(n, n) * 4;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (i != j) A(i, j) = std::sin(1.0 + 3 * i + 7 * j) / n + (j == i + 1 ? 1.0 : 0.0) - (j + 1 == i ? 0.5 : 0.0);
  return A;
}

TEST(Gmres, SolvesANonsymmetricSystemToItsTolerance) {
  const int n = 60;
  const Eigen::MatrixXd A = nonsymmetric(n);
  Vec b(n);
  for (int i = 0; i < n; ++i) b[i] = std::cos(0.3 * i);
  const Vec exact = A.partialPivLu().solve(b);
  for (int restart : {5, 40}) {  // restarted or not, the same answer
    Vec x = Vec::Zero(n);
    const qp::GmresResult r =
        qp::gmres([&](const Vec& v, Vec& Av) { Av = A * v; }, b, x, 1e-10, 1000, restart);
    SCOPED_TRACE("restart " + std::to_string(restart));
    EXPECT_TRUE(r.converged);
    EXPECT_LE((b - A * x).norm(), 1.01e-10 * b.norm());  // the least-squares residual is the true one
    EXPECT_LE((x - exact).norm(), 1e-8 * exact.norm());
    EXPECT_GT(r.applications, 1);
  }
}

TEST(Gmres, StopsAtItsBudgetAndSaysSo) {
  const int n = 60;
  const Eigen::MatrixXd A = nonsymmetric(n);
  const Vec b = Vec::Ones(n);
  Vec x = Vec::Zero(n);
  const qp::GmresResult r = qp::gmres([&](const Vec& v, Vec& Av) { Av = A * v; }, b, x, 1e-14, 3);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.applications, 3);
  EXPECT_LT(r.relative_residual, 1.0);  // progress all the same
  EXPECT_NEAR(r.relative_residual, (b - A * x).norm() / b.norm(), 1e-12);
}

TEST(Gmres, AZeroRightHandSideNeedsNoApplication) {
  Vec x = Vec::Ones(4);
  const qp::GmresResult r = qp::gmres([](const Vec& v, Vec& Av) { Av = v; }, Vec::Zero(4), x, 1e-8, 10);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.applications, 0);
  EXPECT_EQ(x.norm(), 0.0);
}

}  // namespace
}  // namespace ffeti
