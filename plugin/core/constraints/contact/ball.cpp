#include "constraints/contact/ball.h"

#include "constraints/contact/obstacle.h"
#include "constraints/constraint_rows.h"

#include "base/errors.h"

#include <cmath>

namespace ffeti {

RowAt BallGeometry::row_at(const NodeMotion& v, double t) const {
  const Point3 s = moved(slave_position(), v[0], t), &c = centre;
  const double distance = std::hypot(s[0] - c[0], s[1] - c[1], s[2] - c[2]);
  RowAt row{{slave[0], slave[1], slave[2]}, {}, distance - radius};
  for (size_t i = 0; i < 3; ++i) row.coefficients.push_back(-(s[i] - c[i]) / distance);
  return row;
}

Point3 BallGeometry::normal() const {
  const Point3 d = minus(slave_position(), centre);
  const double distance = std::sqrt(dot(d, d));
  return {d[0] / distance, d[1] / distance, d[2] / distance};
}

std::vector<RowAt> BallGeometry::slip_rows() const { return rigid_slip_rows(slave, normal(), three_d()); }

const KindInput* Ball::input() const {
  static const KindInput spec{"obstacleBall", nullptr, {{"centre", InputField::kDimension}, {"radius", 1}}, 2,
                              "[centre x, centre y, radius] (with Z: [cx, cy, cz, radius])"};
  return &spec;
}

void Ball::read_input(const std::vector<double>& values, int dimension, ContactInput& contact) const {
  if (contact.input_of<ObstacleInput>().given) throw InputError("obstacle, obstacleBall: give one obstacle, a plane or a ball");
  const size_t n = values.size();
  if (n != 3 && n != 4)
    throw InputError(std::string("obstacleBall: needs ") + input()->layout + ", got " + std::to_string(n) + " entries");
  if ((dimension == 3) != (n == 4))
    throw InputError(dimension == 3 ? "obstacleBall: with Z (three dimensions) needs [cx, cy, cz, radius], got 3 entries"
                                    : "obstacleBall: four entries (a ball) need Z (three dimensions); a plane problem "
                                      "takes [cx, cy, radius] (a disc)");
  ContactDiscretization::read_input(values, dimension, contact);
}

void Ball::check_parameters(const std::vector<double>& values, int /*dimension*/) const {
  for (size_t i = 0; i + 1 < values.size(); ++i)
    if (!std::isfinite(values[i])) throw InputError("obstacle: the point and the normal must be finite");
  const double radius = values.back();
  if (!(radius > 0 && std::isfinite(radius)))
    throw InputError("obstacleBall: the radius must be finite and > 0, got " + std::to_string(radius));
}

void Ball::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  const ContactInput& contact = in.contact;
  const std::vector<double>& values = contact.kind_parameters.at(kind());
  const size_t n = values.size();
  const Point3 c{values[0], values[1], n == 4 ? values[2] : 0.0};
  const double radius = values[n - 1];
  for (const SlaveNode& node : slave_nodes(in.records, in.snap, contact.three_d ? 3 : 2)) {
    const Point3 s{node.x_dof->x, node.x_dof->y, node.x_dof->z};
    const double distance = std::hypot(s[0] - c[0], s[1] - c[1], s[2] - c[2]);
    if (!(distance > 1e-12 * radius))
      throw InputError("obstacleBall: the slave node at (" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ", " +
                       std::to_string(s[2]) + ") is the ball's centre: it has no normal");
    const std::array<DofRef, 3> dofs{{{node.x_dof->subdomain, node.x_dof->dof},
                                      {node.y_dof->subdomain, node.y_dof->dof},
                                      contact.three_d ? DofRef{node.z_dof->subdomain, node.z_dof->dof} : DofRef{-1, -1}}};
    const auto geometry = std::make_shared<const BallGeometry>(dofs, s, c, radius, contact.three_d);
    Row row{{}, distance - radius + node.x_dof->gap, RowKind::contact, false, geometry, -1,
            node.x_dof->law_value};
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    for (size_t k = 0; k < (contact.three_d ? 3u : 2u); ++k)
      if (s[k] != c[k]) row.entries.push_back({slave[k]->subdomain, slave[k]->dof, -(s[k] - c[k]) / distance});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
