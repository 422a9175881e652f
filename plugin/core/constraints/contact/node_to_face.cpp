#include "constraints/contact/node_to_face.h"

#include "constraints/constraint_rows.h"
#include "constraints/contact/contact_linearization.h"
#include "constraints/contact/face_grid.h"

#include <algorithm>
#include <cmath>

namespace ffeti {

RowAt FaceGeometry::row_at(const NodeMotion& v, double t) const {
  const LinearizedFaceRow r = node_to_face_row(moved(slave_position(), v[0], t), moved(corners[0], v[1], t),
                                               moved(corners[1], v[2], t), moved(corners[2], v[3], t), false);
  RowAt row{{slave[0], slave[1], slave[2]}, {r.coefficients.begin(), r.coefficients.end()}, r.gap};
  row.dofs.insert(row.dofs.end(), face.begin(), face.end());
  return row;
}

std::string FaceGeometry::unverified_motion(const NodeMotion& v) const {
  const auto moves = [&](size_t node) { return v[node][0] != 0 || v[node][1] != 0 || v[node][2] != 0; };
  if (!moves(0) || !(moves(1) || moves(2) || moves(3))) return "";
  const std::array<double, 3> w = closest_point_weights(slave_position(), corners[0], corners[1], corners[2]);
  if (*std::max_element(w.begin(), w.end()) > 1 - 1e-9) return "";  // over a corner: matching faces
  return "the slave node and its master face both move, the slave not over a corner of the face (non-matching "
         "faces): such a row's derivative was measured 7 % off finite differences and is not trusted yet; move "
         "one side of the interface only, or use matching faces there";
}

double FaceGeometry::length() const {
  const Point3 &a = corners[0], &b = corners[1];
  return std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
}

Point3 FaceGeometry::normal() const {
  const Point3 normal_direction = cross(minus(corners[1], corners[0]), minus(corners[2], corners[0]));
  const double area = std::sqrt(dot(normal_direction, normal_direction));
  return {normal_direction[0] / area, normal_direction[1] / area, normal_direction[2] / area};
}

std::vector<RowAt> FaceGeometry::slip_rows() const {
  const Point3 n = normal();
  const std::array<double, 3> w = closest_point_weights(slave_position(), corners[0], corners[1], corners[2]);
  std::vector<RowAt> rows;
  for (const Point3& t : tangent_pair(n)) {
    RowAt row{{slave[0], slave[1], slave[2]}, {t[0], t[1], t[2]}, 0.0};
    for (size_t corner = 0; corner < 3; ++corner)
      for (size_t i = 0; i < 3; ++i) {
        row.dofs.push_back(face[3 * corner + i]);
        row.coefficients.push_back(-w[corner] * t[i]);
      }
    rows.push_back(std::move(row));
  }
  return rows;
}

namespace {

/// s projects along the face's normal inside the triangle (its edges included).
bool over_face(const Point3& s, const std::array<Point3, 3>& corners) {
  const Point3 u = minus(corners[1], corners[0]), v = minus(corners[2], corners[0]), w = minus(s, corners[0]);
  const double uu = dot(u, u), uv = dot(u, v), vv = dot(v, v), wu = dot(w, u), wv = dot(w, v);
  const double det = uu * vv - uv * uv;
  const double beta = (vv * wu - uv * wv) / det, gamma = (uu * wv - uv * wu) / det;
  constexpr double kEdge = 1e-9;
  return beta >= -kEdge && gamma >= -kEdge && beta + gamma <= 1 + kEdge;
}

}  // namespace

bool NodeToFace::selected(const ContactRecords& in) const {
  return !in.faces.empty() && std::none_of(in.faces.begin(), in.faces.end(), [](const FaceRecord& f) { return f.slave; });
}

void NodeToFace::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  const FaceGrid grid(in.faces);
  for (const SlaveNode& node : slave_nodes(in.records, in.snap, 3)) {
    const Point3 s{node.x_dof->x, node.x_dof->y, node.x_dof->z};
    const FaceRecord* face = grid.nearest(s, node.x_dof->body, in.contact.search_distance);
    // No master face within reach: no row, but a slave over a face beyond it, in front of
    // it, is watched for penetration after the solve (a radius too small answers otherwise
    // silently).
    const bool beyond_reach = !face && std::isfinite(in.contact.search_distance);
    if (beyond_reach) face = grid.nearest(s, node.x_dof->body, INFINITY);
    if (!face || (beyond_reach && !over_face(s, face->corners))) continue;
    std::array<DofRef, 9> face_dofs;
    for (size_t k = 0; k < 9; ++k) face_dofs[k] = {face->subdomain, face->dofs[k]};
    const auto geometry = std::make_shared<const FaceGeometry>(
        std::array<DofRef, 3>{{{node.x_dof->subdomain, node.x_dof->dof},
                               {node.y_dof->subdomain, node.y_dof->dof},
                               {node.z_dof->subdomain, node.z_dof->dof}}},
        s, face_dofs, face->corners);
    const LinearizedFaceRow linear = node_to_face_row(s, face->corners[0], face->corners[1], face->corners[2]);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->friction, beyond_reach};
    if (beyond_reach && row.rhs < 0) continue;  // behind the face from the start: not a contact it missed
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    for (size_t i = 0; i < 3; ++i)
      if (linear.coefficients[i] != 0) row.entries.push_back({slave[i]->subdomain, slave[i]->dof, linear.coefficients[i]});
    for (size_t k = 0; k < 9; ++k)
      if (linear.coefficients[3 + k] != 0) row.entries.push_back({face->subdomain, face->dofs[k], linear.coefficients[3 + k]});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
