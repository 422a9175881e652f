// Mortar contact (three dimensions): one row per slave node, its normal gap weighted by its
// shape function over the slave faces that master faces cover (ContactInput::slave_faces,
// mortar_integration.h).
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

#include <utility>

namespace ffeti {

/// A dof's share of a mortar row's weighted jump: coefficient times its component of u.
struct JumpEntry {
  DofRef dof;
  int component;
  double coefficient;
};

/// A mortar row sums over the pairs of faces its slave's faces overlap; its motion
/// derivative is not derived (the capability table refuses the sensitivity analysis).
class MortarGeometry final : public ContactRowGeometry {
 public:
  /// With friction: `jump`, the row's weighted jump (1/w_j) int phi_j (u_s - u_m) as entries
  /// per dof and component; `weighted_normal`, its pairs' normals weighted by int phi_j.
  MortarGeometry(DofRef slave, const Point3& s, std::vector<JumpEntry> jump, const Point3& weighted_normal)
      : ContactRowGeometry(ContactKind::mortar, slave, s, true), jump(std::move(jump)), weighted_normal(weighted_normal) {}

  std::vector<DofRef> moving_nodes() const override { return {}; }
  RowAt row_at(const NodeMotion& v, double t) const override;
  double length() const override { return 1.0; }
  /// weighted_normal normalized (a flat contact: the master's normal).
  Point3 normal() const override;
  /// t.(the weighted jump) along tangent_pair(normal) (docs/algorithms.md, "Mortar", friction).
  std::vector<RowAt> slip_rows() const override;

  const std::vector<JumpEntry> jump;
  const Point3 weighted_normal;
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
