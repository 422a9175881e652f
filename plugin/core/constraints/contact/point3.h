// Vector arithmetic on points of three dimensions, shared by the 3D contact rows (node to
// face, mortar) and the faces' grid.
#pragma once

#include <array>
#include <cmath>

namespace ffeti {

using Point3 = std::array<double, 3>;

inline Point3 minus(const Point3& p, const Point3& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
inline double dot(const Point3& p, const Point3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
inline Point3 cross(const Point3& p, const Point3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}

/// The tangent pair of friction in three dimensions for the unit normal n: t1 the axis least
/// aligned with n (the first of equals) with its n part removed, t2 = n x t1, so (t1, t2, n)
/// is right-handed and orthonormal. A function of n alone: the rows do not depend on how
/// subdomains are spread over ranks. For n = e_z: t1 = e_x, t2 = e_y.
inline std::array<Point3, 2> tangent_pair(const Point3& n) {
  size_t axis = 0;
  for (size_t i = 1; i < 3; ++i)
    if (std::abs(n[i]) < std::abs(n[axis])) axis = i;
  Point3 t1{0, 0, 0};
  t1[axis] = 1;
  const double along = dot(t1, n);
  for (size_t i = 0; i < 3; ++i) t1[i] -= along * n[i];
  const double length = std::sqrt(dot(t1, t1));
  for (double& v : t1) v /= length;
  return {t1, cross(n, t1)};
}

}  // namespace ffeti
