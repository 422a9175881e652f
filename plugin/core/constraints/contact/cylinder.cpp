#include "constraints/contact/cylinder.h"

#include "constraints/constraint_rows.h"

#include "base/errors.h"

#include <cmath>
#include <sstream>

namespace ffeti {
namespace {

/// r = (s - a) - ((s - a).e) e, the distance vector of s from the axis.
Point3 radial(const CylinderShape& c, const Point3& s) {
  const Point3 d = minus(s, c.point);
  const double along = dot(d, c.axis);
  return {d[0] - along * c.axis[0], d[1] - along * c.axis[1], d[2] - along * c.axis[2]};
}

std::string point_text(const Point3& s) {
  std::ostringstream out;
  out << "(" << s[0] << ", " << s[1] << ", " << s[2] << ")";
  return out.str();
}

}  // namespace

CylinderShape CylinderShape::from(const std::vector<double>& values) {
  const double length = std::hypot(values[3], values[4], values[5]);
  return {{values[0], values[1], values[2]},
          {values[3] / length, values[4] / length, values[5] / length},
          values[6],
          values.size() > 7 && values[7] != 0};
}

double CylinderShape::axis_distance(const Point3& s) const {
  const Point3 r = radial(*this, s);
  return std::sqrt(dot(r, r));
}

Point3 CylinderShape::normal_at(const Point3& s) const {
  const Point3 r = radial(*this, s);
  const double rho = std::sqrt(dot(r, r)), sign = inside ? -1.0 : 1.0;
  return {sign * r[0] / rho, sign * r[1] / rho, sign * r[2] / rho};
}

double CylinderShape::gap_at(const Point3& s) const {
  const double rho = axis_distance(s);
  return inside ? radius - rho : rho - radius;
}

RowAt CylinderGeometry::row_at(const NodeMotion& v, double t) const {
  const Point3 s = moved(slave_position(), v[0], t), n = shape.normal_at(s);
  return {{slave[0], slave[1], slave[2]}, {-n[0], -n[1], -n[2]}, shape.gap_at(s)};
}

std::vector<RowAt> CylinderGeometry::slip_rows() const { return rigid_slip_rows(slave, normal(), true); }

const KindInput* Cylinder::input() const {
  static const KindInput spec{"obstacleCylinder",
                              "cylinder",
                              {{"point", 3}, {"axis", 3}, {"radius", 1}, {"inside", 1, true}},
                              3,
                              "[px, py, pz, ax, ay, az, radius] or [px, py, pz, ax, ay, az, radius, inside] "
                              "(a point of the axis, its direction, the radius; inside 1: the bodies in the "
                              "cylinder, 0: outside)"};
  return &spec;
}

void Cylinder::check_parameters(const std::vector<double>& values, int dimension) const {
  const std::string argument = input()->argument;
  require(kind(), Feature::rows, dimension, argument);
  const char* names[] = {"px", "py", "pz", "ax", "ay", "az", "radius", "inside"};
  for (size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw InputError(argument + ": entry " + std::to_string(i) + " (" + names[i] + ") is " +
                       std::to_string(values[i]) + ", it must be finite");
  if (!(std::hypot(values[3], values[4], values[5]) > 0))
    throw InputError(argument + ": the axis [ax, ay, az] must not be zero");
  if (!(values[6] > 0)) throw InputError(argument + ": the radius must be > 0, got " + std::to_string(values[6]));
  if (values.size() > 7 && values[7] != 0 && values[7] != 1)
    throw InputError(argument + ": inside must be 1 (the bodies in the cylinder) or 0 (outside it), got " +
                     std::to_string(values[7]));
}

void Cylinder::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  const CylinderShape shape = CylinderShape::from(in.contact.kind_parameters.at(kind()));
  for (const SlaveNode& node : slave_nodes(in.records, in.snap, 3)) {
    const Point3 s{node.x_dof->x, node.x_dof->y, node.x_dof->z};
    if (!(shape.axis_distance(s) > 1e-12 * shape.radius))
      throw InputError(std::string(input()->argument) + ": the slave node at " + point_text(s) +
                       " lies on the cylinder's axis: it has no normal");
    const std::array<DofRef, 3> dofs{{{node.x_dof->subdomain, node.x_dof->dof},
                                      {node.y_dof->subdomain, node.y_dof->dof},
                                      {node.z_dof->subdomain, node.z_dof->dof}}};
    const auto geometry = std::make_shared<const CylinderGeometry>(kind(), dofs, s, shape);
    const Point3 n = geometry->normal();
    Row row{{}, shape.gap_at(s) + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->law_value};
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    for (size_t k = 0; k < 3; ++k)
      if (n[k] != 0) row.entries.push_back({slave[k]->subdomain, slave[k]->dof, -n[k]});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
