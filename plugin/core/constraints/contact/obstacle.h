// A rigid obstacle (obstacle=, ObstacleInput): a line in the plane, a plane in three
// dimensions, with its outward unit normal n; each slave node s gets
// -n.u_s <= n.(s - point).
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

/// The plane obstacle's own input (ContactInput::input_of): a line (a plane in 3D) through
/// `point` with outward normal `normal` (pointing away from the obstacle):
/// -n.u_slave <= n.(x_slave - point).
struct ObstacleInput {
  bool given = false;
  std::array<double, 3> point{0, 0, 0}, normal{0, 1, 0};  ///< z entries: 3D only
};

class ObstacleGeometry final : public ContactRowGeometry {
 public:
  /// `slave`: the slave's x, y and z dofs (z {-1, -1} in a plane problem).
  ObstacleGeometry(std::array<DofRef, 3> slave, const Point3& s, const Point3& point, const Point3& normal, bool three_d)
      : ContactRowGeometry(ContactKind::obstacle, slave[0], s, three_d), slave(slave), point(point), unit_normal(normal) {}

  std::vector<DofRef> moving_nodes() const override { return {slave[0]}; }
  RowAt row_at(const NodeMotion& v, double t) const override;
  /// The row is linear in the slave position: any step is exact.
  double length() const override { return 1.0; }
  Point3 normal() const override { return unit_normal; }
  /// Along the line's direction (-n_y, n_x), the turn from the outward normal a segment's
  /// tangent makes (plane problems); along tangent_pair(n) in three dimensions.
  std::vector<RowAt> slip_rows() const override;

  const std::array<DofRef, 3> slave;
  const Point3 point, unit_normal;
};

class Obstacle final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::obstacle; }
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "obstacle", "contactSlave, obstacle", kBothDimensions, kBothDimensions, kBothDimensions, kNowhere,
            kBothDimensions, kBothDimensions, kBothDimensions};
  }
  /// obstacle = [px, py, nx, ny] (with Z: [px, py, pz, nx, ny, nz]).
  const KindInput* input() const override;
  /// Into its ObstacleInput.
  void read_input(const std::vector<double>& values, int dimension, ContactInput& contact) const override;
  /// For a caller that fills them itself: z entries only with Z, finite entries.
  void check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                     const ContactInput& contact, int dimension) const override;
  bool selected(const ContactRecords& in) const override { return in.contact.input_of<ObstacleInput>().given; }
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
};

}  // namespace ffeti
