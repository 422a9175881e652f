// The contact entries of a problem file as the core's ContactInput, for this rank's
// subdomains: slave nodes, the list kinds' entries read from the mesh groups their keys name
// (master nodes, segments, faces in a solid oriented out of their body) and stored by the
// kinds themselves (read_list), obstacles, friction coefficients.
#include "native/contact_input.h"

#include "native/mesh_groups.h"

#include "base/errors.h"
#include "constraints/contact/contact_discretization.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ffeti::native {
namespace {

/// Each triangle edge of the local subdomains: (subdomain position, opposite vertex).
using EdgeMap = std::map<std::pair<NodeTag, NodeTag>, std::pair<size_t, NodeTag>>;

EdgeMap edges_of(const std::vector<SubdomainLayout>& layouts) {
  EdgeMap edges;
  for (size_t k = 0; k < layouts.size(); ++k)
    for (const Element& t : layouts[k].cells)
      for (int e = 0; e < 3; ++e) {
        const NodeTag a = t.nodes[e], b = t.nodes[(e + 1) % 3];
        edges[{std::min(a, b), std::max(a, b)}] = {k, t.nodes[(e + 2) % 3]};
      }
  return edges;
}

/// The master segments of a curve that lie on the local subdomains, as dofs of the
/// subdomain holding the segment's triangle, oriented with that triangle on the left (the
/// core's convention, whatever the curve's orientation in the mesh). Returns how many of
/// the curve's segments are here; the caller checks that every rank together found all.
long add_master_segments(const std::vector<std::array<NodeTag, 2>>& segments, const GmshMesh& mesh,
                         const std::vector<SubdomainLayout>& layouts, const EdgeMap& edges,
                         std::vector<std::vector<int>>& lists) {
  long found = 0;
  for (const auto& [a, b] : segments) {
    const auto edge = edges.find({std::min(a, b), std::max(a, b)});
    if (edge == edges.end()) continue;
    const auto [k, c] = edge->second;
    const auto pa = mesh.position(a), pb = mesh.position(b), pc = mesh.position(c);
    const double left = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
    const NodeTag first = left > 0 ? a : b, second = left > 0 ? b : a;
    const auto& rows = layouts[k].rows;
    lists[k].insert(lists[k].end(), {rows.at({first, 0}), rows.at({first, 1}), rows.at({second, 0}), rows.at({second, 1})});
    ++found;
  }
  return found;
}

/// Each tetrahedron face of the local subdomains (its nodes sorted): the subdomain position
/// and the opposite vertex of a tetrahedron it bounds, and how many of the local
/// tetrahedra it bounds (2: an inner face).
struct FaceOwner {
  size_t subdomain;
  NodeTag opposite;
  int tetrahedra;
};
using FaceMap = std::map<std::array<NodeTag, 3>, FaceOwner>;

FaceMap faces_of(const std::vector<SubdomainLayout>& layouts) {
  FaceMap faces;
  for (size_t k = 0; k < layouts.size(); ++k)
    for (const Element& t : layouts[k].cells)
      for (size_t opposite = 0; opposite < 4; ++opposite) {
        std::array<NodeTag, 3> face{};
        for (size_t i = 0, j = 0; i < 4; ++i)
          if (i != opposite) face[j++] = t.nodes[i];
        std::sort(face.begin(), face.end());
        const auto [it, added] = faces.try_emplace(face, FaceOwner{k, t.nodes[opposite], 0});
        ++it->second.tetrahedra;
      }
  return faces;
}

/// The master triangles of a surface that lie on the local subdomains, as the 9 dofs
/// of the subdomain holding the triangle's tetrahedron, ordered so that (b - a) x (c - a)
/// points away from that tetrahedron (out of its body: the core's convention, whatever the
/// surface's orientation in the mesh). Returns how many are here; the caller checks that
/// every rank together found all.
long add_master_faces(const std::vector<std::array<NodeTag, 3>>& triangles, const GmshMesh& mesh,
                      const std::vector<SubdomainLayout>& layouts, const FaceMap& faces, std::vector<std::vector<int>>& lists) {
  long found = 0;
  for (std::array<NodeTag, 3> corners : triangles) {
    std::array<NodeTag, 3> key = corners;
    std::sort(key.begin(), key.end());
    const auto face = faces.find(key);
    if (face == faces.end()) continue;
    // Between two tetrahedra the face has no outside to point to (checked where both are
    // on this rank).
    if (face->second.tetrahedra > 1)
      throw InputError("contact master: the triangle (" + std::to_string(corners[0]) + ", " + std::to_string(corners[1]) +
                       ", " + std::to_string(corners[2]) + ") lies between two tetrahedra: master faces must be on "
                       "a body's boundary");
    const size_t k = face->second.subdomain;
    const NodeTag d = face->second.opposite;
    const auto pa = mesh.position(corners[0]), pb = mesh.position(corners[1]), pc = mesh.position(corners[2]);
    const auto pd = mesh.position(d);
    const std::array<double, 3> u{pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]}, v{pc[0] - pa[0], pc[1] - pa[1], pc[2] - pa[2]};
    const std::array<double, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    if (n[0] * (pd[0] - pa[0]) + n[1] * (pd[1] - pa[1]) + n[2] * (pd[2] - pa[2]) > 0) std::swap(corners[1], corners[2]);
    const auto& rows = layouts[k].rows;
    for (size_t corner = 0; corner < 3; ++corner)
      for (int c = 0; c < 3; ++c) lists[k].push_back(rows.at({corners[corner], c}));
    ++found;
  }
  return found;
}

/// The line of a straight curve (c.line_curve, named `where`), its normal pointing to the
/// slave nodes' side: [px, py, nx, ny]. InputError if the curve is not straight or the slave
/// nodes' centroid lies on it.
std::vector<double> line_from_curve(const ProblemFile& problem, const GmshMesh& mesh, const ContactSpec& c,
                                    const std::string& where) {
  const auto nodes = from_group(problem, where, [&] { return mesh.nodes(1, c.line_curve); });
  const auto p0 = mesh.position(nodes.front());
  std::array<double, 3> far = p0;
  for (NodeTag node : nodes) {
    const auto p = mesh.position(node);
    if (std::hypot(p[0] - p0[0], p[1] - p0[1]) > std::hypot(far[0] - p0[0], far[1] - p0[1])) far = p;
  }
  const double length = std::hypot(far[0] - p0[0], far[1] - p0[1]);
  if (!(length > 0)) throw InputError(problem.path + ": " + where + ": the curve has no length");
  std::array<double, 2> normal{-(far[1] - p0[1]) / length, (far[0] - p0[0]) / length};
  auto offset = [&](const std::array<double, 3>& p) { return normal[0] * (p[0] - p0[0]) + normal[1] * (p[1] - p0[1]); };
  for (NodeTag node : nodes)
    if (std::abs(offset(mesh.position(node))) > 1e-9 * length)
      throw InputError(problem.path + ": " + where + ": curve " + std::to_string(c.line_curve) +
                       " is not straight (node " + std::to_string(node) + " lies off the line): a rigid obstacle is a line");
  std::array<double, 3> centroid{0, 0, 0};  // z unused: a plane problem
  const auto slaves = mesh.nodes(1, c.slave);
  for (NodeTag node : slaves)
    for (int k = 0; k < 2; ++k) centroid[k] += mesh.position(node)[k] / static_cast<double>(slaves.size());
  const double side = offset(centroid);
  if (std::abs(side) <= 1e-9 * length)
    throw InputError(problem.path + ": " + where + ": the slave nodes' centroid lies on the obstacle's "
                     "line: give \"point\" and \"normal\" instead");
  if (side < 0) normal = {-normal[0], -normal[1]};
  return {p0[0], p0[1], normal[0], normal[1]};
}

/// Dofs of the local subdomains at `nodes` (sorted; all components).
void add_node_dofs(const std::vector<NodeTag>& nodes, const std::vector<SubdomainLayout>& layouts,
                   std::vector<std::vector<int>>& dofs) {
  for (size_t k = 0; k < layouts.size(); ++k)
    for (size_t i = 0; i < layouts[k].dofs.size(); ++i)
      if (std::binary_search(nodes.begin(), nodes.end(), layouts[k].dofs[i].node))
        dofs[k].push_back(static_cast<int>(i));
}

/// The friction law's value `mu` (Coulomb's coefficient or Tresca's bound) at the dofs of
/// `nodes` (sorted: a contact entry's slave curve), 0 at the other dofs: one per contact entry.
void set_friction(const std::vector<NodeTag>& nodes, double mu, const std::vector<SubdomainLayout>& layouts,
                  std::vector<std::vector<double>>& field) {
  field.resize(layouts.size());
  for (size_t k = 0; k < layouts.size(); ++k) {
    if (field[k].empty()) field[k].assign(layouts[k].dofs.size(), 0.0);
    for (size_t i = 0; i < layouts[k].dofs.size(); ++i)
      if (std::binary_search(nodes.begin(), nodes.end(), layouts[k].dofs[i].node)) field[k][i] = mu;
  }
}

}  // namespace

ContactInput build_contact(const ProblemFile& problem, const GmshMesh& mesh, const std::vector<SubdomainLayout>& layouts,
                           long& segments_here, long& segments_total) {
  ContactInput contact;
  if (problem.contact.empty()) return contact;
  const bool solid = problem.dimension() == 3;
  const EdgeMap edges = problem.components == 2 ? edges_of(layouts) : EdgeMap();
  const FaceMap faces = solid ? faces_of(layouts) : FaceMap();
  const int boundary = problem.dimension() - 1;  // slave and master groups: curves, surfaces in 3D
  const size_t n = layouts.size();
  contact.slave_dofs.resize(n);
  const auto& units = contact_discretizations();
  std::map<ContactKind, std::vector<std::vector<int>>> lists;  // of the list kinds' keys, per subdomain
  bool rigid_given = false;
  const ContactSpec& first = problem.contact.front();
  if (first.search_distance) contact.search_distance = *first.search_distance;
  // The list kind's own keys (one value per problem: checked below), stored by the kind.
  if (!first.rigid())
    for (const auto& [option, value] : first.options) units.at(static_cast<size_t>(first.kind))->read_option(option, value, contact);
  // Coulomb: a coefficient per entry, Tresca: a bound per entry (0, no friction, for an
  // entry without one); one law per problem.
  const bool coulomb = std::any_of(problem.contact.begin(), problem.contact.end(),
                                   [](const ContactSpec& c) { return c.friction.has_value(); });
  const bool tresca = std::any_of(problem.contact.begin(), problem.contact.end(),
                                  [](const ContactSpec& c) { return c.slip_bound.has_value(); });
  if (coulomb && tresca)
    throw InputError(problem.path + ": contact: friction (Coulomb) in one entry and slip_bound (Tresca) in another: "
                     "one law per problem");
  if (coulomb) contact.friction = 0.0;
  if (tresca) contact.slip_bound = 0.0;
  for (size_t i = 0; i < problem.contact.size(); ++i) {
    const ContactSpec& c = problem.contact[i];
    const std::string key = "contact[" + std::to_string(i) + "]";
    if (c.search_distance != first.search_distance || c.options != first.options)
      throw InputError(problem.path + ": " + key +
                       ": search_distance, gap and contact_normal must be those of contact[0] (one value per problem)");
    const std::vector<NodeTag> slaves =
        from_group(problem, key + ".slave", [&] { return mesh.nodes(boundary, c.slave); });
    add_node_dofs(slaves, layouts, contact.slave_dofs);
    if (c.friction) set_friction(slaves, *c.friction, layouts, contact.friction_field);
    if (c.slip_bound) set_friction(slaves, *c.slip_bound, layouts, contact.slip_bound_field);
    if (c.rigid()) {  // a kind's own key, stored by the kind as its fetiSetup argument is
      if (rigid_given)
        throw InputError(problem.path + ": " + key + ": a second obstacle (one rigid obstacle per problem)");
      rigid_given = true;
      const auto& [kind, values] = *c.kind_parameters.begin();
      const ContactDiscretization& unit = *units.at(static_cast<size_t>(kind));
      const KindInput& spec = *unit.input();
      unit.read_input(c.line_curve > 0 ? line_from_curve(problem, mesh, c, key + "." + spec.file_key + "." + spec.line_key)
                                       : values,
                      problem.dimension(), contact);
    } else {  // a list kind's key: its entries read from the mesh group it names
      const ContactDiscretization& unit = *units.at(static_cast<size_t>(c.kind));
      const ListInput& spec = *unit.list_input();
      std::vector<std::vector<int>>& list = lists[c.kind];
      list.resize(n);
      // The entries of a group (its physical tag, `where` in messages) as the kind's list takes them.
      const auto add_group = [&](int group, const std::string& where) {
        if (spec.file_entries == MeshEntries::node_dofs) {
          add_node_dofs(from_group(problem, where, [&] { return mesh.nodes(boundary, group); }), layouts, list);
        } else if (spec.file_entries == MeshEntries::triangles) {
          const auto triangles = from_group(problem, where, [&] { return mesh.faces(group); });
          segments_total += static_cast<long>(triangles.size());
          segments_here += add_master_faces(triangles, mesh, layouts, faces, list);
        } else {
          const auto segments = from_group(problem, where, [&] { return mesh.segments(group); });
          segments_total += static_cast<long>(segments.size());
          segments_here += add_master_segments(segments, mesh, layouts, edges, list);
        }
      };
      add_group(c.master, key + "." + spec.file_key);
      if (unit.lists_slave_group(contact)) add_group(c.slave, key + ".slave");
    }
  }
  std::vector<int> ids;
  for (const SubdomainLayout& layout : layouts) ids.push_back(layout.id);
  for (const auto& [kind, list] : lists) units.at(static_cast<size_t>(kind))->read_list(list, ids, contact);
  return contact;
}

}  // namespace ffeti::native
