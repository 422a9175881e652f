// A rigid ball (a disc in the plane) of obstacleBall = [centre, radius], kept as the ball's
// own input (ContactInput::kind_parameters), the bodies outside it: each slave node s against
// the tangent plane at its nearest point, n = (s - c)/|s - c|: -n.u_s <= |s - c| - radius.
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

class BallGeometry final : public ContactRowGeometry {
 public:
  /// `slave`: the slave's x, y and z dofs (z {-1, -1} in a plane problem, where s and the
  /// centre have z = 0).
  BallGeometry(std::array<DofRef, 3> slave, const Point3& s, const Point3& centre, double radius, bool three_d)
      : ContactRowGeometry(ContactKind::ball, slave[0], s, three_d), slave(slave), centre(centre), radius(radius) {}

  std::vector<DofRef> moving_nodes() const override { return {slave[0]}; }
  /// n moves with s.
  RowAt row_at(const NodeMotion& v, double t) const override;
  double length() const override { return radius; }
  /// (s - c)/|s - c|.
  Point3 normal() const override;
  /// t.u_s along the tangent(s) of the tangent plane at the slave's nearest ball point, whose
  /// normal is n = (s - c)/|s - c| (rigid_slip_rows: the ball does not move).
  std::vector<RowAt> slip_rows() const override;

  const std::array<DofRef, 3> slave;
  const Point3 centre;
  const double radius;
};

class Ball final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::ball; }
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "ball", "contactSlave, obstacleBall", kBothDimensions, kBothDimensions, kBothDimensions, kNowhere,
            kBothDimensions, kNowhere, kBothDimensions};
  }
  /// obstacleBall = [cx, cy, radius] (with Z: [cx, cy, cz, radius]).
  const KindInput* input() const override;
  /// Its entries into ContactInput::kind_parameters (one obstacle: a plane given before is
  /// refused; the entries against the dimension, then check_parameters).
  void read_input(const std::vector<double>& values, int dimension, ContactInput& contact) const override;
  /// A finite centre, a radius finite and > 0.
  void check_parameters(const std::vector<double>& values, int dimension) const override;
  bool selected(const ContactRecords& in) const override { return in.contact.kind_parameters.count(kind()) > 0; }
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
};

}  // namespace ffeti
