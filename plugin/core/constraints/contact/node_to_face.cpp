#include "constraints/contact/node_to_face.h"

#include "constraints/constraint_rows.h"
#include "constraints/input_checks.h"
#include "constraints/contact/contact_linearization.h"
#include "constraints/contact/face_grid.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

namespace ffeti {
namespace {

/// A barycentric weight this close to 0 puts a point on the triangle's boundary.
constexpr double kEdge = 1e-9;
/// cos 75 degrees: a row's normal this far from its face's normal measures no gap to speak of.
constexpr double kFacing = 0.2588;

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

/// The slave's fan: the faces of its own body with a corner at s (within 1e-9 of s's size:
/// the same node's coordinates, copied into every subdomain that holds it), their other
/// corners numbered once per dof.
SlaveFan fan_at(const Point3& s, int body, const FaceGrid& grid, ContactNormal normal) {
  SlaveFan fan{normal, {}, {}, {}};
  const double near = 1e-9 * (1 + std::abs(s[0]) + std::abs(s[1]) + std::abs(s[2]));
  grid.for_each_in_box({s[0] - near, s[1] - near, s[2] - near}, {s[0] + near, s[1] + near, s[2] + near},
                       [&](const FaceRecord& f) {
                         if (f.body != body) return;
                         std::array<int, 3> corners{};
                         bool at_slave = false;
                         for (size_t k = 0; k < 3; ++k) {
                           const Point3 d = minus(f.corners[k], s);
                           if (std::sqrt(dot(d, d)) <= near) {
                             corners[k] = -1;
                             at_slave = true;
                             continue;
                           }
                           const DofRef dof{f.subdomain, f.dofs[3 * k]};
                           const auto at = std::find(fan.neighbours.begin(), fan.neighbours.end(), dof);
                           corners[k] = static_cast<int>(at - fan.neighbours.begin());
                           if (at == fan.neighbours.end()) {
                             fan.neighbours.push_back(dof);
                             fan.positions.push_back(f.corners[k]);
                           }
                         }
                         if (at_slave) fan.faces.push_back(corners);
                       });
  return fan;
}

/// How much unit normals spread: 1 - |their mean| (0 where they agree, about theta^2 / 4 for
/// normals tilted up to theta round a cap's axis).
double spread(const std::vector<Point3>& normals) {
  Point3 sum{0, 0, 0};
  for (const Point3& n : normals)
    for (size_t i = 0; i < 3; ++i) sum[i] += n[i];
  return 1 - std::sqrt(dot(sum, sum)) / static_cast<double>(normals.size());
}

/// A surface counts as the flatter one when its normals spread by less than this share of
/// the other's; between the two, the surfaces are curved alike and the rows take the
/// average (two equal spheres: their common plane).
constexpr double kFlatterShare = 0.5;
/// Normals that spread less than this on both sides are flat alike: the master's is kept
/// (the rows of flat contacts then need no slave faces, nor do their derivatives).
constexpr double kFlat = 1e-12;

/// A couple of bodies in contact: the slave's body and its master face's.
using BodyPair = std::pair<int, int>;

/// contactNormal="flatter" resolved per couple of bodies over the slave nodes with a master
/// face within `reach`: flatter_side of the faces' normals and the slave surface's own; the
/// master's for a couple where any such slave has no face of its own body in contactFaces.
std::map<BodyPair, ContactNormal> flatter_normals(const std::vector<SlaveNode>& nodes, const FaceGrid& grid,
                                                  double reach) {
  std::map<BodyPair, std::pair<std::vector<Point3>, std::vector<Point3>>> normals;  // master's, slave's
  std::set<BodyPair> fanless;
  for (const SlaveNode& node : nodes) {
    const Point3 s{node.x_dof->x, node.x_dof->y, node.x_dof->z};
    const FaceRecord* face = grid.nearest(s, node.x_dof->body, reach);
    if (!face) continue;
    const BodyPair couple{node.x_dof->body, face->body};
    const SlaveFan fan = fan_at(s, node.x_dof->body, grid, ContactNormal::slave);
    if (fan.faces.empty()) {
      fanless.insert(couple);
      continue;
    }
    normals[couple].first.push_back(unit_normal(face->corners));
    normals[couple].second.push_back(fan_normal(fan, s, fan.positions));
  }
  std::map<BodyPair, ContactNormal> chosen;
  for (const auto& [couple, both] : normals)
    chosen[couple] = fanless.count(couple) ? ContactNormal::master : flatter_side(both.first, both.second);
  return chosen;
}

std::string where(const Point3& s) {
  return "(" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ", " + std::to_string(s[2]) + ")";
}

}  // namespace

Point3 fan_normal(const SlaveFan& fan, const Point3& s, const std::vector<Point3>& neighbours) {
  Point3 sum{0, 0, 0};
  for (const std::array<int, 3>& f : fan.faces) {
    const auto corner = [&](size_t k) { return f[k] < 0 ? s : neighbours[static_cast<size_t>(f[k])]; };
    const Point3 n = cross(minus(corner(1), corner(0)), minus(corner(2), corner(0)));
    for (size_t i = 0; i < 3; ++i) sum[i] += n[i];
  }
  const double length = std::sqrt(dot(sum, sum));
  return {sum[0] / length, sum[1] / length, sum[2] / length};
}

ContactNormal flatter_side(const std::vector<Point3>& master_normals, const std::vector<Point3>& slave_normals) {
  if (master_normals.empty() || slave_normals.empty()) return ContactNormal::master;
  const double master = spread(master_normals), slave = spread(slave_normals);
  if (std::max(master, slave) <= kFlat || master <= kFlatterShare * slave) return ContactNormal::master;
  return slave <= kFlatterShare * master ? ContactNormal::slave : ContactNormal::average;
}

Point3 row_direction(ContactNormal normal, const Point3& m, const Point3& o) {
  if (normal == ContactNormal::master) return m;
  if (normal == ContactNormal::slave) return {-o[0], -o[1], -o[2]};
  Point3 n{m[0] - o[0], m[1] - o[1], m[2] - o[2]};
  const double length = std::sqrt(dot(n, n));
  return {n[0] / length, n[1] / length, n[2] / length};
}

FaceGeometry::FaceGeometry(std::array<DofRef, 3> slave, const Point3& s, std::array<DofRef, 9> face,
                           const std::array<Point3, 3>& corners, bool on_bent_edge, SlaveFan fan)
    : ContactRowGeometry(ContactKind::node_to_face, slave[0], s, true), slave(slave), face(face), corners(corners),
      on_bent_edge(on_bent_edge), fan(std::move(fan)) {}

std::vector<DofRef> FaceGeometry::moving_nodes() const {
  std::vector<DofRef> nodes{slave[0], face[0], face[3], face[6]};
  nodes.insert(nodes.end(), fan.neighbours.begin(), fan.neighbours.end());
  return nodes;
}

LinearizedFaceRow FaceGeometry::linearized(const NodeMotion& v, double t, bool clamp) const {
  const Point3 s = moved(slave_position(), v[0], t), a = moved(corners[0], v[1], t), b = moved(corners[1], v[2], t),
               c = moved(corners[2], v[3], t);
  if (fan.normal == ContactNormal::master) return node_to_face_row(s, a, b, c, clamp);
  std::vector<Point3> neighbours;
  for (size_t k = 0; k < fan.positions.size(); ++k) neighbours.push_back(moved(fan.positions[k], v[4 + k], t));
  const Point3 direction = row_direction(fan.normal, unit_normal({a, b, c}), fan_normal(fan, s, neighbours));
  return node_to_face_row(s, a, b, c, clamp, &direction);
}

void NodeToFace::check_combination(const ContactInput& contact) const {
  const ContactNormal normal = contact.input_of<NodeToFaceInput>().normal;
  if (normal == ContactNormal::master || normal == ContactNormal::flatter) return;
  if (!list_given(contact) || ffeti::list_given(ContactKind::mortar, contact))
    throw InputError(std::string("contactNormal: \"") + (normal == ContactNormal::slave ? "slave" : "average") +
                     "\" applies to node-to-face contact (contactSlave with contactFaces, the slave surface's faces "
                     "among them); mortar (contactSlaveFaces) and the other kinds take their master's or obstacle's "
                     "normal");
}

const ListInput* NodeToFace::list_input() const {
  static const ListInput spec{"contactFaces", 9, "9 dofs per face (a_x, a_y, a_z, b_x, ..., c_z)", "master", 3,
                              MeshEntries::triangles,
                              {{"contactNormal", "contact_normal", {"master", "slave", "average", "flatter"},  // ContactNormal's order
                                "node-to-face contact (3 components, a master group)"}}};
  return &spec;
}

void NodeToFace::read_option(size_t /*option*/, double value, ContactInput& contact) const {
  contact.input_of<NodeToFaceInput>().normal = static_cast<ContactNormal>(static_cast<int>(value));
}

void NodeToFace::read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                           ContactInput& contact) const {
  contact.input_of<NodeToFaceInput>().faces = list_entries<9>(*list_input(), lists, ids);
}

void NodeToFace::check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                               const ContactInput& contact, int dimension) const {
  check_face_list(contact.input_of<NodeToFaceInput>().faces, ids, subdomains, list_input()->argument);
  if (list_given(contact)) require(kind(), Feature::rows, dimension, list_input()->argument);
}

RowAt FaceGeometry::row_at(const NodeMotion& v, double t) const {
  const LinearizedFaceRow r = linearized(v, t, false);
  RowAt row{{slave[0], slave[1], slave[2]}, {r.coefficients.begin(), r.coefficients.end()}, r.gap};
  row.dofs.insert(row.dofs.end(), face.begin(), face.end());
  return row;
}

std::string FaceGeometry::unverified_motion(const NodeMotion& v) const {
  double speed = 0;
  for (const Point3& w : v) speed = std::max(speed, std::hypot(w[0], w[1], w[2]));
  if (speed == 0) return "";
  const std::array<double, 3> w = linearized({}, 0, false).weights;
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
  const auto at = [&](double t) { return linearized(v, t, false).weights; };
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
  if (fan.normal == ContactNormal::master) return unit_normal(corners);
  return row_direction(fan.normal, unit_normal(corners), fan_normal(fan, slave_position(), fan.positions));
}

std::vector<RowAt> FaceGeometry::slip_rows() const {
  const Point3 n = normal();
  const std::array<double, 3> w = linearized({}, 0, true).weights;
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
  const std::vector<SlaveNode> nodes = slave_nodes(in.records, in.snap, 3);
  const ContactNormal asked = in.contact.input_of<NodeToFaceInput>().normal;
  const std::map<BodyPair, ContactNormal> flatter =
      asked == ContactNormal::flatter ? flatter_normals(nodes, grid, in.contact.search_distance)
                                      : std::map<BodyPair, ContactNormal>();
  for (const SlaveNode& node : nodes) {
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
    ContactNormal normal = asked;
    if (asked == ContactNormal::flatter) {  // a slave beyond reach is watched along its face's normal
      const auto couple = flatter.find({node.x_dof->body, face->body});
      normal = beyond_reach || couple == flatter.end() ? ContactNormal::master : couple->second;
    }
    SlaveFan fan;
    if (normal != ContactNormal::master) {
      fan = fan_at(s, node.x_dof->body, grid, normal);
      if (fan.faces.empty())
        throw InputError("contactNormal: the slave node at " + where(s) +
                         " has no face of its own body in contactFaces: the slave surface's normal is taken from its "
                         "faces, give them in contactFaces too (a slave pairs with faces of other bodies only)");
      const Point3 n = row_direction(normal, unit_normal(face->corners), fan_normal(fan, s, fan.positions));
      if (dot(n, unit_normal(face->corners)) < kFacing)
        throw InputError("contactNormal: the slave node at " + where(s) +
                         ": its row's normal lies within 15 degrees of its master face's plane (the two surfaces "
                         "do not face each other there): give contactNormal=\"master\", or leave this node out of "
                         "contactSlave");
    }
    const auto geometry = std::make_shared<const FaceGeometry>(
        std::array<DofRef, 3>{{{node.x_dof->subdomain, node.x_dof->dof},
                               {node.y_dof->subdomain, node.y_dof->dof},
                               {node.z_dof->subdomain, node.z_dof->dof}}},
        s, face_dofs, face->corners, on_bent_edge(s, *face, grid), std::move(fan));
    const LinearizedFaceRow linear = geometry->linearized({}, 0, true);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->law_value, beyond_reach};
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
