#include "mesh/element_quality.h"

#include <algorithm>
#include <cmath>

namespace ffeti {
namespace {

using Point = std::array<double, 3>;

Point edge(const Point& from, const Point& to) { return {to[0] - from[0], to[1] - from[1], to[2] - from[2]}; }

Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// The longest of the edges between any two of the corners.
template <size_t N>
double longest_edge(const std::array<Point, N>& p) {
  double longest = 0;
  for (size_t i = 0; i < N; ++i)
    for (size_t j = i + 1; j < N; ++j) {
      const Point e = edge(p[i], p[j]);
      longest = std::max(longest, std::hypot(e[0], e[1], e[2]));
    }
  return longest;
}

}  // namespace

double tetrahedron_flatness(const std::array<Point, 4>& p) {
  const Point a = edge(p[0], p[1]), n = cross(edge(p[0], p[2]), edge(p[0], p[3]));
  const double volume = std::abs(a[0] * n[0] + a[1] * n[1] + a[2] * n[2]) / 6;
  const double longest = longest_edge(p);
  return longest > 0 ? volume / (longest * longest * longest) : 0.0;
}

double triangle_flatness(const std::array<Point, 3>& p) {
  const Point n = cross(edge(p[0], p[1]), edge(p[0], p[2]));
  const double area = std::hypot(n[0], n[1], n[2]) / 2;
  const double longest = longest_edge(p);
  return longest > 0 ? area / (longest * longest) : 0.0;
}

}  // namespace ffeti
