#include "constraints/contact/obstacle.h"

#include "constraints/constraint_rows.h"
#include "constraints/contact/contact_linearization.h"

#include "base/errors.h"

#include <cmath>

namespace ffeti {

RowAt ObstacleGeometry::row_at(const NodeMotion& v, double t) const {
  const Point3 s = moved(slave_position(), v[0], t);
  if (three_d()) {  // only the gap moves
    RowAt row{{slave[0], slave[1], slave[2]}, {-unit_normal[0], -unit_normal[1], -unit_normal[2]}, 0.0};
    for (size_t i = 0; i < 3; ++i) row.gap += unit_normal[i] * (s[i] - point[i]);
    return row;
  }
  const LinearizedRow r = obstacle_row({s[0], s[1]}, {point[0], point[1]}, {unit_normal[0], unit_normal[1]});
  return {{slave[0], slave[1]}, {r.coefficients[0], r.coefficients[1]}, r.gap};
}

std::vector<RowAt> ObstacleGeometry::slip_rows() const { return rigid_slip_rows(slave, unit_normal, three_d()); }

const KindInput* Obstacle::input() const {
  static const KindInput spec{"obstacle",
                              "obstacle",
                              {{"point", InputField::kDimension}, {"normal", InputField::kDimension, false, true}},
                              2,
                              "[point x, point y, normal x, normal y] (with Z: [px, py, pz, nx, ny, nz])",
                              "curve"};
  return &spec;
}

void Obstacle::read_input(const std::vector<double>& values, int dimension, ContactInput& contact) const {
  if (values.size() != 4 && values.size() != 6)
    throw InputError(std::string("obstacle: needs ") + input()->layout + ", got " + std::to_string(values.size()) +
                     " entries");
  // A line's four entries read as a plane would lie in z = 0 with a normal in the x-y plane:
  // the rows then fail far from the cause.
  if (dimension == 3 && values.size() == 4)
    throw InputError("obstacle: with Z (three dimensions) needs six entries, a plane [px, py, pz, nx, ny, nz]; "
                     "got four (a line of a plane problem)");
  ObstacleInput& plane = contact.input_of<ObstacleInput>();
  plane.given = true;
  if (values.size() == 6) {  // three dimensions: a plane (validate_input refuses z entries without Z)
    plane.point = {values[0], values[1], values[2]};
    plane.normal = {values[3], values[4], values[5]};
  } else {
    plane.point = {values[0], values[1], 0.0};
    plane.normal = {values[2], values[3], 0.0};
  }
}

void Obstacle::check_against(const std::vector<SubdomainInput>& /*subdomains*/, const std::vector<size_t>& /*ids*/,
                             const ContactInput& contact, int dimension) const {
  const ObstacleInput& plane = contact.input_of<ObstacleInput>();
  if (!plane.given) return;
  const auto& point = plane.point;
  const auto& normal = plane.normal;
  if (dimension == 2 && (point[2] != 0 || normal[2] != 0))
    throw InputError("obstacle: six entries (a plane) need Z (three dimensions); a plane problem takes four");
  for (double v : {point[0], point[1], point[2], normal[0], normal[1], normal[2]})
    if (!std::isfinite(v)) throw InputError("obstacle: the point and the normal must be finite");
}

void Obstacle::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  const ContactInput& contact = in.contact;
  const ObstacleInput& plane = contact.input_of<ObstacleInput>();
  const auto& point = plane.point;
  const auto& normal = plane.normal;
  const double norm = contact.three_d ? std::hypot(normal[0], normal[1], normal[2]) : std::hypot(normal[0], normal[1]);
  if (!(norm > 0)) throw InputError("obstacle: the normal must not be zero");
  const Point3 n{normal[0] / norm, normal[1] / norm, normal[2] / norm};
  for (const SlaveNode& node : slave_nodes(in.records, in.snap, contact.three_d ? 3 : 2)) {
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    const std::array<DofRef, 3> dofs{{{node.x_dof->subdomain, node.x_dof->dof},
                                      {node.y_dof->subdomain, node.y_dof->dof},
                                      contact.three_d ? DofRef{node.z_dof->subdomain, node.z_dof->dof} : DofRef{-1, -1}}};
    // -n.u_s <= n.(s - point): in the plane the row the sensitivity analysis differentiates,
    // in 3D the same with z.
    LinearizedRow linear = obstacle_row({node.x_dof->x, node.x_dof->y}, {point[0], point[1]},
                                        {n[0], n[1]});
    if (contact.three_d) {
      linear.coefficients[2] = -n[2];
      linear.gap += n[2] * (node.x_dof->z - point[2]);
    }
    const auto geometry = std::make_shared<const ObstacleGeometry>(
        dofs, Point3{node.x_dof->x, node.x_dof->y, node.x_dof->z}, point, n, contact.three_d);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->law_value};
    for (size_t k = 0; k < (contact.three_d ? 3u : 2u); ++k)
      if (linear.coefficients[k] != 0) row.entries.push_back({slave[k]->subdomain, slave[k]->dof, linear.coefficients[k]});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
