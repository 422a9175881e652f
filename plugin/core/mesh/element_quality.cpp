#include "mesh/element_quality.h"

#include <algorithm>
#include <cmath>

namespace ffeti {

double tetrahedron_flatness(const std::array<std::array<double, 3>, 4>& p) {
  const auto edge = [&](size_t i, size_t j) {
    return std::array<double, 3>{p[j][0] - p[i][0], p[j][1] - p[i][1], p[j][2] - p[i][2]};
  };
  const auto a = edge(0, 1), b = edge(0, 2), c = edge(0, 3);
  const double volume = std::abs(a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                                 a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  double longest = 0;
  for (size_t i = 0; i < 4; ++i)
    for (size_t j = i + 1; j < 4; ++j) {
      const auto e = edge(i, j);
      longest = std::max(longest, std::hypot(e[0], e[1], e[2]));
    }
  return longest > 0 ? volume / (longest * longest * longest) : 0.0;
}

double triangle_flatness(const std::array<std::array<double, 3>, 3>& p) {
  const auto edge = [&](size_t i, size_t j) {
    return std::array<double, 3>{p[j][0] - p[i][0], p[j][1] - p[i][1], p[j][2] - p[i][2]};
  };
  const auto a = edge(0, 1), b = edge(0, 2);
  const double area = std::hypot(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]) / 2;
  double longest = 0;
  for (size_t i = 0; i < 3; ++i)
    for (size_t j = i + 1; j < 3; ++j) {
      const auto e = edge(i, j);
      longest = std::max(longest, std::hypot(e[0], e[1], e[2]));
    }
  return longest > 0 ? area / (longest * longest) : 0.0;
}

}  // namespace ffeti
