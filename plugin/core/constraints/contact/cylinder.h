// A rigid cylinder (three dimensions): an infinite circular cylinder of axis point a, unit
// axis direction e and radius R, the bodies outside it (a shaft pressed against them) or
// inside it (a body in a cylindrical hole). Each slave node s gets the row of the tangent
// plane at its nearest cylinder point: with r = (s - a) - ((s - a).e) e its distance vector
// from the axis and rho = |r|, outside n = r/rho and -n.u_s <= rho - R; inside n = -r/rho
// (the hole's wall pushes towards the axis) and -n.u_s <= R - rho.
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

/// The cylinder of obstacleCylinder = [px, py, pz, ax, ay, az, radius(, inside)].
struct CylinderShape {
  Point3 point, axis;  ///< axis: unit
  double radius;
  bool inside;  ///< the bodies lie inside the cylinder (a hole), not outside it (a shaft)
  /// From the argument's entries (checked by Cylinder::check_parameters).
  static CylinderShape from(const std::vector<double>& values);
  /// The unit normal at the nearest cylinder point of `s`, pointing from the cylinder to
  /// s, and the gap, the signed distance of s from the surface; rho = 0 (s on the axis)
  /// leaves both undefined (the caller refuses it).
  Point3 normal_at(const Point3& s) const;
  double gap_at(const Point3& s) const;
  /// |r|, the distance of s from the axis.
  double axis_distance(const Point3& s) const;
};

class CylinderGeometry final : public ContactRowGeometry {
 public:
  /// `slave`: the slave's x, y and z dofs.
  CylinderGeometry(ContactKind kind, std::array<DofRef, 3> slave, const Point3& s, const CylinderShape& shape)
      : ContactRowGeometry(kind, slave[0], s, true), slave(slave), shape(shape) {}

  std::vector<DofRef> moving_nodes() const override { return {slave[0]}; }
  /// n and the gap move with s (the cylinder stands still).
  RowAt row_at(const NodeMotion& v, double t) const override;
  double length() const override { return shape.radius; }
  Point3 normal() const override { return shape.normal_at(slave_position()); }
  /// t.u_s along tangent_pair(n) of the tangent plane at the nearest cylinder point.
  std::vector<RowAt> slip_rows() const override;

  const std::array<DofRef, 3> slave;
  const CylinderShape shape;
};

class Cylinder final : public ContactDiscretization {
 public:
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "cylinder", "contactSlave, obstacleCylinder", kSolidOnly, kSolidOnly, kSolidOnly, kNowhere,
            kSolidOnly, kSolidOnly, kSolidOnly};
  }
  const KindInput* input() const override;
  /// Three dimensions; finite entries, an axis not zero, a radius > 0, inside 0 or 1.
  void check_parameters(const std::vector<double>& values, int dimension) const override;
  bool selected(const ContactRecords& in) const override { return in.contact.kind_parameters.count(kind()) > 0; }
  /// InputError for a slave node on the axis (no normal).
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
};

}  // namespace ffeti
