#include "constraints/contact/mortar_integration.h"

#include <cmath>
#include <vector>

namespace ffeti {
namespace {

using Point2 = std::array<double, 2>;

double cross2(const Point2& o, const Point2& p, const Point2& q) {
  return (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0]);
}

/// Barycentric weights of q in the 2D triangle t (twice its signed area given).
std::array<double, 3> barycentric(const std::array<Point2, 3>& t, double twice_area, const Point2& q) {
  const double wa = cross2(q, t[1], t[2]) / twice_area, wb = cross2(t[0], q, t[2]) / twice_area;
  return {wa, wb, 1 - wa - wb};
}

/// The part of the convex polygon `polygon` on the left of the directed line p -> q.
std::vector<Point2> clip_left_of(const std::vector<Point2>& polygon, const Point2& p, const Point2& q) {
  std::vector<Point2> kept;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % polygon.size()];
    const double sa = cross2(p, q, a), sb = cross2(p, q, b);
    if (sa >= 0) kept.push_back(a);
    if ((sa >= 0) != (sb >= 0)) {
      const double t = sa / (sa - sb);
      kept.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  return kept;
}

}  // namespace

MortarIntegrals integrate_mortar_pair(const Triangle3& slave, const Triangle3& master) {
  MortarIntegrals out;
  // Coordinates in the master's plane: e1 along its first edge, e2 = n x e1, so that the
  // master runs counter-clockwise.
  const Point3 ab = minus(master[1], master[0]), normal_area = cross(ab, minus(master[2], master[0]));
  const double twice_master_area = std::sqrt(dot(normal_area, normal_area)), edge = std::sqrt(dot(ab, ab));
  if (!(twice_master_area > 0)) return out;
  const Point3 n{normal_area[0] / twice_master_area, normal_area[1] / twice_master_area,
                 normal_area[2] / twice_master_area};
  const Point3 e1{ab[0] / edge, ab[1] / edge, ab[2] / edge}, e2 = cross(n, e1);
  const auto in_plane = [&](const Point3& p) {
    const Point3 d = minus(p, master[0]);
    return Point2{dot(d, e1), dot(d, e2)};
  };
  const std::array<Point2, 3> m2{in_plane(master[0]), in_plane(master[1]), in_plane(master[2])};
  const std::array<Point2, 3> s2{in_plane(slave[0]), in_plane(slave[1]), in_plane(slave[2])};
  const double twice_slave_area = cross2(s2[0], s2[1], s2[2]);
  // A slave facing the master projects clockwise; edge-on (no area) it covers nothing.
  if (std::abs(twice_slave_area) <= 1e-12 * twice_master_area) return out;
  out.normal = n;
  std::array<size_t, 3> order{0, 1, 2};  // counter-clockwise corners of the projected slave
  if (twice_slave_area < 0) std::swap(order[1], order[2]);

  std::vector<Point2> overlap{s2[order[0]], s2[order[1]], s2[order[2]]};
  for (size_t e = 0; e < 3 && overlap.size() >= 3; ++e) overlap = clip_left_of(overlap, m2[e], m2[(e + 1) % 3]);
  if (overlap.size() < 3) return out;

  constexpr double kInside = 2.0 / 3.0, kOutside = 1.0 / 6.0;  // the 3-point rule, degree 2
  for (size_t i = 1; i + 1 < overlap.size(); ++i) {
    const Point2 &p0 = overlap[0], &p1 = overlap[i], &p2 = overlap[i + 1];
    const double area = 0.5 * cross2(p0, p1, p2);
    if (!(area > 0)) continue;
    out.area += area;
    for (size_t q = 0; q < 3; ++q) {
      const std::array<double, 3> w{q == 0 ? kInside : kOutside, q == 1 ? kInside : kOutside, q == 2 ? kInside : kOutside};
      const Point2 x{w[0] * p0[0] + w[1] * p1[0] + w[2] * p2[0], w[0] * p0[1] + w[1] * p1[1] + w[2] * p2[1]};
      const std::array<double, 3> phi = barycentric(s2, twice_slave_area, x);
      const std::array<double, 3> psi = barycentric(m2, twice_master_area, x);  // both signed
      Point3 on_slave{}, on_master{};
      for (size_t c = 0; c < 3; ++c)
        for (size_t d = 0; d < 3; ++d) {
          on_slave[d] += phi[c] * slave[c][d];
          on_master[d] += psi[c] * master[c][d];
        }
      const double weight = area / 3;
      for (size_t j = 0; j < 3; ++j) {
        for (size_t k = 0; k < 3; ++k) {
          out.D[j][k] += weight * phi[j] * phi[k];
          out.M[j][k] += weight * phi[j] * psi[k];
        }
        for (size_t d = 0; d < 3; ++d) out.G[j][d] += weight * phi[j] * (on_slave[d] - on_master[d]);
      }
    }
  }
  return out;
}

}  // namespace ffeti
