// Aitken's acceleration of the Coulomb bounds' fixed point (feti/bound_acceleration.h) on
// small contracting maps whose limit is known in closed form.
#include "feti/bound_acceleration.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <functional>
#include <limits>

namespace ffeti {
namespace {

using Map = std::function<Vec(const Vec&)>;

/// G evaluations until ||x - limit||_inf <= 1e-10 (at most 200), from x0, with or without the acceleration.
int evaluations_to_limit(const Map& map, const Vec& x0, const Vec& limit, bool accelerate) {
  BoundAcceleration acceleration;
  Vec x = x0;
  for (int k = 1; k <= 200; ++k) {
    const Vec image = map(x);
    x = accelerate ? acceleration.next(x, image) : image;
    EXPECT_GE(x.minCoeff(), 0.0);
    if ((x - limit).lpNorm<Eigen::Infinity>() <= 1e-10) return k;
  }
  return 200;
}

TEST(BoundAcceleration, OneContractingModeIsExactAfterTwoResiduals) {
  // G(x) = rho x + b: the limit b / (1 - rho); omega = 1 / (1 - rho) = 5 makes the second step exact.
  const double rho = 0.8;
  const Vec b = Vec::LinSpaced(4, 1.0, 4.0);
  const Map map = [&](const Vec& x) -> Vec { return rho * x + b; };
  const Vec limit = b / (1 - rho);
  BoundAcceleration acceleration;
  Vec x = Vec::Zero(4);
  x = acceleration.next(x, map(x));  // the plain step: no residual before
  EXPECT_FALSE(acceleration.accelerated());
  x = acceleration.next(x, map(x));
  EXPECT_TRUE(acceleration.accelerated());
  EXPECT_NEAR(acceleration.relaxation(), 1 / (1 - rho), 1e-12);
  EXPECT_LE((x - limit).lpNorm<Eigen::Infinity>(), 1e-12 * limit.lpNorm<Eigen::Infinity>());
}

TEST(BoundAcceleration, TwoModesNeedFewerEvaluationsThanThePlainIteration) {
  // G(x) = A x + b, A symmetric with eigenvalues 0.9 and 0.3: the limit (I - A)^-1 b > 0.
  Eigen::Matrix2d rotation;
  rotation << 0.8, -0.6, 0.6, 0.8;
  const Eigen::Matrix2d a = rotation * Eigen::Vector2d(0.9, 0.3).asDiagonal() * rotation.transpose();
  const Vec b = Eigen::Vector2d(1.0, 2.0);
  const Vec limit = (Eigen::Matrix2d::Identity() - a).inverse() * b;
  ASSERT_GT(limit.minCoeff(), 0.0);
  const Map map = [&](const Vec& x) -> Vec { return a * x + b; };
  const int plain = evaluations_to_limit(map, Vec::Zero(2), limit, false);
  const int aitken = evaluations_to_limit(map, Vec::Zero(2), limit, true);
  EXPECT_GT(plain, 150);  // 0.9^k from about 30 to 1e-10: k about 230 (capped at 200)
  EXPECT_LT(aitken, 60);
}

TEST(BoundAcceleration, ProjectedMapWithZerosInItsLimit) {
  // G(x) = max(0, rho x + b) with b's last entry negative: the limit has that entry 0, the
  // others b / (1 - rho). An extrapolated bound below 0 is projected back, not returned.
  const double rho = 0.85;
  const Vec b = Eigen::Vector3d(1.0, 0.5, -1.0);
  const Map map = [&](const Vec& x) -> Vec { return (rho * x + b).cwiseMax(0.0); };
  const Vec limit = Eigen::Vector3d(1.0 / (1 - rho), 0.5 / (1 - rho), 0.0);
  const int plain = evaluations_to_limit(map, Eigen::Vector3d(0, 0, 5), limit, false);
  const int aitken = evaluations_to_limit(map, Eigen::Vector3d(0, 0, 5), limit, true);
  EXPECT_GT(plain, 100);
  EXPECT_LT(aitken, plain / 3);
}

TEST(BoundAcceleration, PlainStepWithoutFiniteBoundsOrWhenTheResidualGrows) {
  BoundAcceleration acceleration;
  const double inf = std::numeric_limits<double>::infinity();
  const Vec image = Eigen::Vector2d(1.0, 2.0);
  // The first Coulomb solve's bounds are infinite: the image, and no history kept.
  EXPECT_EQ(acceleration.next(Eigen::Vector2d(inf, inf), image), image);
  EXPECT_FALSE(acceleration.accelerated());
  // A first finite residual: still plain.
  EXPECT_EQ(acceleration.next(Eigen::Vector2d(0.0, 0.0), image), image);  // residual (1, 2)
  // A larger residual than the last one: the plain step again, omega back to 1.
  const Vec farther = Eigen::Vector2d(4.0, 4.0);
  EXPECT_EQ(acceleration.next(Eigen::Vector2d(1.0, 2.0), farther), farther);  // residual (3, 2)
  EXPECT_FALSE(acceleration.accelerated());
  EXPECT_EQ(acceleration.relaxation(), 1.0);
  // A smaller one: extrapolated along it.
  const Vec accelerated = acceleration.next(Eigen::Vector2d(4.0, 4.0), Eigen::Vector2d(5.0, 4.5));
  EXPECT_TRUE(acceleration.accelerated());
  EXPECT_NE(accelerated, Vec(Eigen::Vector2d(5.0, 4.5)));
}

}  // namespace
}  // namespace ffeti
