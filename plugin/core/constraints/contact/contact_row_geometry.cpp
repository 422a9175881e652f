#include "constraints/contact/contact_row_geometry.h"

#include <algorithm>
#include <cmath>

namespace ffeti {

std::vector<Point3> slip_directions(const Point3& n, bool three_d) {
  if (!three_d) return {{-n[1], n[0], 0.0}};
  const auto pair = tangent_pair(n);
  return {pair[0], pair[1]};
}

std::vector<RowAt> rigid_slip_rows(const std::array<DofRef, 3>& slave, const Point3& n, bool three_d) {
  const size_t components = three_d ? 3 : 2;
  std::vector<RowAt> rows;
  for (const Point3& t : slip_directions(n, three_d))
    rows.push_back({{slave.begin(), slave.begin() + components}, {t.begin(), t.begin() + components}, 0.0});
  return rows;
}

std::array<Point3, 2> ContactRowGeometry::tangents() const {
  const std::vector<Point3> t = slip_directions(normal(), three_d_);
  return {t[0], t.size() > 1 ? t[1] : Point3{0, 0, 0}};
}

double difference_step(const ContactRowGeometry& g, const NodeMotion& velocities) {
  double speed = 0;
  for (const Point3& w : velocities) speed = std::max(speed, std::hypot(w[0], w[1], w[2]));
  return speed == 0 ? 0.0 : 1e-6 * g.length() / speed;
}

}  // namespace ffeti
