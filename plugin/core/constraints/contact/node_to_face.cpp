#include "constraints/contact/node_to_face.h"

#include "constraints/constraint_rows.h"
#include "constraints/input_checks.h"
#include "constraints/contact/contact_linearization.h"
#include "constraints/contact/face_grid.h"

#include <algorithm>
#include <cmath>

namespace ffeti {
namespace {

/// A barycentric weight this close to 0 puts a point on the triangle's boundary.
constexpr double kEdge = 1e-9;

/// s projects along the face's normal inside the triangle (its edges included).
bool over_face(const Point3& s, const std::array<Point3, 3>& corners) {
  const std::array<double, 3> w = plane_weights(s, corners[0], corners[1], corners[2]);
  return *std::min_element(w.begin(), w.end()) >= -kEdge;
}

Point3 unit_normal(const std::array<Point3, 3>& c) {
  const Point3 n = cross(minus(c[1], c[0]), minus(c[2], c[0]));
  const double norm = std::sqrt(dot(n, n));
  return {n[0] / norm, n[1] / norm, n[2] / norm};
}

/// The slave s lies on an edge or a corner of `face` that a face of the same body with
/// another normal (beyond 1e-8 rad) also touches at s: the faceted surface bends there.
bool on_bent_edge(const Point3& s, const FaceRecord& face, const FaceGrid& grid) {
  const std::array<double, 3> w = plane_weights(s, face.corners[0], face.corners[1], face.corners[2]);
  if (*std::min_element(w.begin(), w.end()) >= kEdge) return false;  // inside the face
  const Point3 n = unit_normal(face.corners);
  const Point3 e = minus(face.corners[1], face.corners[0]);
  const double near = kEdge * std::sqrt(dot(e, e));
  bool bent = false;
  grid.for_each_in_box({s[0] - near, s[1] - near, s[2] - near}, {s[0] + near, s[1] + near, s[2] + near},
                       [&](const FaceRecord& other) {
                         if (&other == &face || other.body != face.body || bent) return;
                         const std::array<double, 3> v =
                             closest_point_weights(s, other.corners[0], other.corners[1], other.corners[2]);
                         Point3 p{0, 0, 0};
                         for (size_t k = 0; k < 3; ++k)
                           for (size_t i = 0; i < 3; ++i) p[i] += v[k] * other.corners[k][i];
                         const Point3 d = minus(p, s), m = cross(n, unit_normal(other.corners));
                         bent = std::sqrt(dot(d, d)) <= near && std::sqrt(dot(m, m)) > 1e-8;
                       });
  return bent;
}

}  // namespace

const ListInput* NodeToFace::list_input() const {
  static const ListInput spec{"contactFaces", 9, "9 dofs per face (a_x, a_y, a_z, b_x, ..., c_z)", "master", 3,
                              MeshEntries::triangles};
  return &spec;
}

void NodeToFace::read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                           ContactInput& contact) const {
  contact.master_faces = list_entries<9>(*list_input(), lists, ids);
}

void NodeToFace::check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                               const ContactInput& contact, int dimension) const {
  check_face_list(contact.master_faces, ids, subdomains, list_input()->argument);
  if (any_entry(contact.master_faces)) require(kind(), Feature::rows, dimension, list_input()->argument);
}

RowAt FaceGeometry::row_at(const NodeMotion& v, double t) const {
  const LinearizedFaceRow r = node_to_face_row(moved(slave_position(), v[0], t), moved(corners[0], v[1], t),
                                               moved(corners[1], v[2], t), moved(corners[2], v[3], t), false);
  RowAt row{{slave[0], slave[1], slave[2]}, {r.coefficients.begin(), r.coefficients.end()}, r.gap};
  row.dofs.insert(row.dofs.end(), face.begin(), face.end());
  return row;
}

std::string FaceGeometry::unverified_motion(const NodeMotion& v) const {
  double speed = 0;
  for (const Point3& w : v) speed = std::max(speed, std::hypot(w[0], w[1], w[2]));
  if (speed == 0) return "";
  const Point3& s = slave_position();
  const std::array<double, 3> w = plane_weights(s, corners[0], corners[1], corners[2]);
  if (*std::min_element(w.begin(), w.end()) >= kEdge) return "";  // over the face's interior
  if (*std::min_element(w.begin(), w.end()) < -kEdge)
    return "the slave node lies beyond the edges of its master face (its row projects it on the face's boundary, "
           "whose motion the derivative does not follow): give master faces that cover the slave nodes, or keep "
           "this row's nodes still";
  // On an edge or a corner: the pairing holds on both sides of the design only while the slave
  // moves along the face's boundary, its zero weights staying zero. Moving across, it passes to
  // the neighbouring face on one side: the gradient has two one-sided values, and the row's
  // derivative is one of them.
  const double step = 1e-6 * length() / speed;
  const auto at = [&](double t) {
    return plane_weights(moved(s, v[0], t), moved(corners[0], v[1], t), moved(corners[1], v[2], t),
                         moved(corners[2], v[3], t));
  };
  const std::array<double, 3> plus = at(step), minus = at(-step);
  for (size_t k = 0; k < 3; ++k)
    if (w[k] < kEdge && std::abs(plus[k] - minus[k]) / (2 * step) > 1e-6 * speed / length())
      return "the slave node lies on an edge or a corner of its master face and moves across it relative to the "
             "face (the slave's velocity differs from the face's there): on one side of the design it pairs with "
             "the neighbouring face, so the gradient has no two-sided value; give meshes whose slave nodes lie "
             "inside the master faces, or a motion that moves this slave and its face alike";
  return "";
}

bool FaceGeometry::one_sided_under(const NodeMotion& v) const {
  if (!on_bent_edge) return false;
  for (const Point3& w : v)
    if (w[0] != 0 || w[1] != 0 || w[2] != 0) return true;
  return false;
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
        s, face_dofs, face->corners, on_bent_edge(s, *face, grid));
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
