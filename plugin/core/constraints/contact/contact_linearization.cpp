#include "constraints/contact/contact_linearization.h"

#include <algorithm>
#include <cmath>

namespace ffeti {

LinearizedRow node_to_segment_row(const Point& s, const Point& a, const Point& b, bool clamp_xi) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
  double xi = ((s[0] - a[0]) * dx + (s[1] - a[1]) * dy) / (length * length);
  if (clamp_xi) xi = std::clamp(xi, 0.0, 1.0);
  const double nx = dy / length, ny = -dx / length;  // outward: the body lies on the left
  const double px = a[0] + xi * dx, py = a[1] + xi * dy;
  return {{-nx, -ny, (1 - xi) * nx, (1 - xi) * ny, xi * nx, xi * ny}, nx * (s[0] - px) + ny * (s[1] - py)};
}

LinearizedRow obstacle_row(const Point& s, const Point& point, const Point& normal) {
  return {{-normal[0], -normal[1], 0, 0, 0, 0}, normal[0] * (s[0] - point[0]) + normal[1] * (s[1] - point[1])};
}

LinearizedRow node_to_segment_slip(const Point& s, const Point& a, const Point& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
  const double xi = std::clamp(((s[0] - a[0]) * dx + (s[1] - a[1]) * dy) / (length * length), 0.0, 1.0);
  const double tx = dx / length, ty = dy / length;
  return {{tx, ty, -(1 - xi) * tx, -(1 - xi) * ty, -xi * tx, -xi * ty}, 0.0};
}

std::array<double, 3> closest_point_weights(const Point3& s, const Point3& a, const Point3& b, const Point3& c) {
  // The Voronoi regions of the triangle's corners, edges and face, in turn (the classic
  // region test; weights of the point p = w_a a + w_b b + w_c c).
  const Point3 ab = minus(b, a), ac = minus(c, a), as = minus(s, a);
  const double d1 = dot(ab, as), d2 = dot(ac, as);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Point3 bs = minus(s, b);
  const double d3 = dot(ab, bs), d4 = dot(ac, bs);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double t = d1 / (d1 - d3);
    return {1 - t, t, 0};
  }
  const Point3 cs = minus(s, c);
  const double d5 = dot(ab, cs), d6 = dot(ac, cs);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double t = d2 / (d2 - d6);
    return {1 - t, 0, t};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - t, t};
  }
  const double denominator = 1 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  return {1 - v - w, v, w};
}

std::array<double, 3> plane_weights(const Point3& s, const Point3& a, const Point3& b, const Point3& c) {
  // The normal equations of ab, ac for the projection p - a = w_b ab + w_c ac.
  const Point3 ab = minus(b, a), ac = minus(c, a), as = minus(s, a);
  const double d00 = dot(ab, ab), d01 = dot(ab, ac), d11 = dot(ac, ac), d20 = dot(as, ab), d21 = dot(as, ac);
  const double denominator = d00 * d11 - d01 * d01;
  const double wb = (d11 * d20 - d01 * d21) / denominator, wc = (d00 * d21 - d01 * d20) / denominator;
  return {1 - wb - wc, wb, wc};
}

LinearizedFaceRow node_to_face_row(const Point3& s, const Point3& a, const Point3& b, const Point3& c, bool clamp,
                                   const Point3* direction) {
  const Point3 ab = minus(b, a), ac = minus(c, a);
  Point3 n = cross(ab, ac);
  const double length = std::sqrt(dot(n, n));
  for (double& component : n) component /= length;
  // The point the weights are taken at: s itself (its projection along the face's normal),
  // or the point of the face's plane s reaches along `direction`.
  Point3 along = s;
  if (direction) {
    const double distance = dot(n, minus(s, a)) / dot(n, *direction);
    for (size_t i = 0; i < 3; ++i) along[i] -= distance * (*direction)[i];
    n = *direction;
  }
  const std::array<double, 3> w = clamp ? closest_point_weights(along, a, b, c) : plane_weights(along, a, b, c);
  Point3 p{};
  for (size_t i = 0; i < 3; ++i) p[i] = w[0] * a[i] + w[1] * b[i] + w[2] * c[i];
  LinearizedFaceRow row{};
  for (size_t i = 0; i < 3; ++i) {
    row.coefficients[i] = -n[i];
    for (size_t corner = 0; corner < 3; ++corner) row.coefficients[3 + 3 * corner + i] = w[corner] * n[i];
  }
  row.gap = dot(n, minus(s, p));
  row.weights = w;
  return row;
}

}  // namespace ffeti
