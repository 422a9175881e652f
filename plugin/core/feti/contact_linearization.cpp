#include "feti/contact_linearization.h"

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

LinearizedRow obstacle_slip(const Point& normal) { return {{-normal[1], normal[0], 0, 0, 0, 0}, 0.0}; }

}  // namespace ffeti
