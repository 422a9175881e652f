#include "qp/norm_estimate.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace ffeti {
namespace {

/// Q diag(eigenvalues) Q' with a pseudo-random orthogonal Q.
Eigen::MatrixXd with_spectrum(const Eigen::VectorXd& eigenvalues, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  const Eigen::Index n = eigenvalues.size();
  Eigen::MatrixXd random(n, n);
  for (Eigen::Index i = 0; i < random.size(); ++i) random.data()[i] = normal(generator);
  const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(random).householderQ();
  return Q * eigenvalues.asDiagonal() * Q.transpose();
}

LinearOperator dense(const Eigen::MatrixXd& A) {
  return [A](const Vec& x, Vec& y) { y = A * x; };
}

/// The power method the Lanczos estimate replaced, from the same start: its Rayleigh
/// quotient after k multiplications.
double power_rayleigh(const Eigen::MatrixXd& A, int k, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vec x(A.rows());
  for (Eigen::Index i = 0; i < x.size(); ++i) x[i] = uniform(generator);
  double rayleigh = 0;
  for (int j = 0; j < k; ++j) {
    x.normalize();
    const Vec y = A * x;
    rayleigh = x.dot(y);
    x = y;
  }
  return rayleigh;
}

TEST(NormEstimate, WithinTheSafetyFactorAboveTheLargestEigenvalueInFewSteps) {
  // A FETI-like spectrum: eigenvalues spread over two decades, crowded at the top.
  const int n = 300;
  Eigen::VectorXd eigenvalues(n);
  for (int i = 0; i < n; ++i) eigenvalues[i] = 1.0 + 99.0 * std::sqrt(static_cast<double>(i) / (n - 1));
  const Eigen::MatrixXd A = with_spectrum(eigenvalues, 3);
  const double largest = eigenvalues.maxCoeff();
  const NormEstimateSettings settings;
  const NormEstimate estimate = estimate_norm(dense(A), n, settings);
  const double ritz = estimate.norm / settings.safety_factor;
  EXPECT_LE(ritz, largest * (1 + 1e-12));  // a Ritz value never exceeds the largest eigenvalue
  EXPECT_GE(ritz, 0.95 * largest);         // ...and the safety factor covers what it lacks
  EXPECT_LT(estimate.multiplications, settings.iterations);
  // At least as good as the power method's quotient from as many multiplications and the
  // same start, and as its 15 steps.
  EXPECT_GE(ritz, power_rayleigh(A, estimate.multiplications, settings.seed) * (1 - 1e-12));
  EXPECT_GE(ritz, power_rayleigh(A, 15, settings.seed) * (1 - 1e-3));
}

TEST(NormEstimate, ExactOnAnInvariantSubspace) {
  // Rank 3: the Krylov space is exhausted after three steps and the Ritz values are exact.
  const int n = 50;
  Eigen::VectorXd eigenvalues = Eigen::VectorXd::Zero(n);
  eigenvalues.head(3) << 2.0, 5.0, 7.0;
  const NormEstimateSettings settings;
  const NormEstimate estimate = estimate_norm(dense(with_spectrum(eigenvalues, 5)), n, settings);
  EXPECT_LE(estimate.multiplications, 4);
  EXPECT_NEAR(estimate.norm, settings.safety_factor * 7.0, 1e-10);
}

TEST(NormEstimate, TheStartFilterKeepsTheIteratesInItsSubspace) {
  // A acts on the first half with norm 3 and on the second with norm 10; the filter zeroes
  // the second half (a projector commuting with A), so the estimate is the first half's.
  const int n = 40;
  Eigen::VectorXd eigenvalues(n);
  for (int i = 0; i < n; ++i) eigenvalues[i] = i < n / 2 ? 1.0 + 2.0 * i / (n / 2 - 1) : 10.0;
  const LinearOperator A = [&](const Vec& x, Vec& y) { y = eigenvalues.cwiseProduct(x); };
  const auto first_half = [](Vec& v) { v.tail(v.size() / 2).setZero(); };
  NormEstimateSettings settings;
  settings.tolerance = 1e-8;
  const NormEstimate estimate = estimate_norm(A, n, settings, first_half);
  EXPECT_NEAR(estimate.norm / settings.safety_factor, 3.0, 1e-4);  // not 10
}

TEST(NormEstimate, StopsAtTheGivenNumberOfSteps) {
  const int n = 200;
  Eigen::VectorXd eigenvalues(n);
  for (int i = 0; i < n; ++i) eigenvalues[i] = 1.0 + i;
  NormEstimateSettings settings;
  settings.iterations = 4, settings.tolerance = 0;
  const NormEstimate estimate = estimate_norm(dense(with_spectrum(eigenvalues, 7)), n, settings);
  EXPECT_EQ(estimate.multiplications, 4);
  EXPECT_LE(estimate.norm / settings.safety_factor, 200.0 * (1 + 1e-12));
}

}  // namespace
}  // namespace ffeti
