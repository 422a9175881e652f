// qp::project_onto_cone and qp::cone_distance against closed forms.
#include "qp/cone_distance.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ffeti::qp {
namespace {

TEST(ConeProjection, KeepsInsideZeroesThePolarConeAndOtherwiseMeetsTheNearestRay) {
  double n = 1, t[2] = {0.1, 0.2};
  project_onto_cone(n, t, 2, 0.5);  // ||t|| = 0.22 <= 0.5: inside
  EXPECT_DOUBLE_EQ(n, 1);
  EXPECT_DOUBLE_EQ(t[1], 0.2);
  n = -1, t[0] = 0.1, t[1] = 0;
  project_onto_cone(n, t, 2, 0.5);  // 0.5 * 0.1 <= 1: the polar cone
  EXPECT_EQ(n, 0);
  EXPECT_EQ(t[0], 0);
  // (1, 2) onto |t| <= 0.5 n in the plane: the ray (1, 0.5)/|.|, the residual orthogonal to it.
  double m = 1, s[1] = {2};
  project_onto_cone(m, s, 1, 0.5);
  EXPECT_NEAR(s[0], 0.5 * m, 1e-15);             // on the cone's boundary
  EXPECT_NEAR((1 - m) * 1 + (2 - s[0]) * 0.5, 0, 1e-15);  // residual orthogonal to the ray
}

TEST(ConeDistance, FindsTheDistanceToTheConeOrStopsWithinReach) {
  // C = I on (n, t): the distance from the target to the cone |t| <= 0.4 n itself.
  const Eigen::MatrixXd C = Eigen::MatrixXd::Identity(2, 2);
  const auto project = [](Vec& x) { project_onto_cone(x[0], &x[1], 1, 0.4); };
  Vec outside(2);
  outside << 1, 1;  // its projection: along = (1 + 0.4) / 1.16 on the ray (1, 0.4)
  const double along = 1.4 / 1.16;
  const double exact = std::hypot(1 - along, 1 - 0.4 * along);
  const ConeDistance far = cone_distance(C, outside, project, 1.0, 1e-12);
  EXPECT_NEAR(far.distance, exact, 1e-9);
  Vec inside(2);
  inside << 1, 0.3;
  EXPECT_LE(cone_distance(C, inside, project, 1.0, 1e-9).distance, 1e-9);
}

}  // namespace
}  // namespace ffeti::qp
