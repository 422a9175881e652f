// Vector arithmetic on points of three dimensions, shared by the 3D contact rows (node to
// face, mortar) and the faces' grid.
#pragma once

#include <array>

namespace ffeti {

using Point3 = std::array<double, 3>;

inline Point3 minus(const Point3& p, const Point3& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }
inline double dot(const Point3& p, const Point3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }
inline Point3 cross(const Point3& p, const Point3& q) {
  return {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
}

}  // namespace ffeti
