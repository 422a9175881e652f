// Mortar contact (three dimensions): one row per slave node, its normal gap weighted by its
// shape function over the slave faces that master faces cover (ContactInput::slave_faces,
// mortar_integration.h).
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

/// A mortar row sums over the pairs of faces its slave's faces overlap; its motion
/// derivative is not derived (the capability table refuses the sensitivity analysis).
class MortarGeometry final : public ContactRowGeometry {
 public:
  /// `normal`: the unit normal of the row's condition (normal()).
  MortarGeometry(DofRef slave, const Point3& s, const Point3& normal)
      : ContactRowGeometry(ContactKind::mortar, slave, s, true), unit_normal(normal) {}

  std::vector<DofRef> moving_nodes() const override { return {}; }
  RowAt row_at(const NodeMotion& v, double t) const override;
  double length() const override { return 1.0; }
  /// The masters' normals weighted by int phi_j over each overlap with the slave's faces,
  /// normalized (a flat contact: the master's normal).
  Point3 normal() const override { return unit_normal; }

  const Point3 unit_normal;
};

class Mortar final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::mortar; }
  /// Any slave face (ContactInput::slave_faces) on any rank.
  bool selected(const ContactRecords& in) const override;
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
  const char* searched_argument() const override { return "contactSlaveFaces"; }
  const char* master_word() const override { return "face"; }
};

}  // namespace ffeti
