#include "constraints/contact/contact_row_geometry.h"

#include <stdexcept>

namespace ffeti {

std::array<Point3, 2> ContactRowGeometry::tangents() const {
  const Point3 n = normal();
  if (three_d_) return tangent_pair(n);
  return {Point3{-n[1], n[0], 0.0}, Point3{0.0, 0.0, 0.0}};
}

std::vector<RowAt> ContactRowGeometry::slip_rows() const {
  // Reached only if the capability table says friction where the kind has no tangent.
  throw std::logic_error(std::string(capability_table()[static_cast<size_t>(kind_)].name) +
                         " contact has no slip rows; the capability table must refuse friction for it");
}

}  // namespace ffeti
