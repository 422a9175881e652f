#include "native/native_problem.h"

#include "base/errors.h"
#include "feti/options.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace ffeti::native {
namespace {

std::string entry(int s) { return "subdomains[" + std::to_string(s) + "]"; }

/// The rows of each (node, component) of one subdomain.
using RowIndex = std::map<std::pair<NodeTag, int>, int>;

RowIndex index_rows(const std::vector<DofLocation>& dofs) {
  RowIndex rows;
  for (size_t i = 0; i < dofs.size(); ++i) rows[{dofs[i].node, dofs[i].component}] = static_cast<int>(i);
  return rows;
}

/// A physical group's nodes or segments, a missing group named by the problem file's key.
template <class Lookup>
auto from_group(const ProblemFile& problem, const std::string& key, Lookup lookup) {
  try {
    return lookup();
  } catch (const InputError& error) {
    throw InputError(problem.path + ": " + key + ": " + error.what());
  }
}

/// "triangle" or "tetrahedron": the cells of the problem's dimension, for messages.
std::string cell_word(const ProblemFile& problem) { return problem.dimension() == 3 ? "tetrahedron" : "triangle"; }
std::string cells_word(const ProblemFile& problem) { return problem.dimension() == 3 ? "tetrahedra" : "triangles"; }
/// The problem file's key of the subdomains' groups.
std::string regions_key(const ProblemFile& problem) { return problem.dimension() == 3 ? ".volumes" : ".surfaces"; }

/// "components": 3 reads tetrahedra of physical volumes; a mesh with no physical volume (a
/// plane mesh) would fail later on a group that is not there, with a message that does not
/// say why, and a volume mesh read as a plane one would drop z: both refused here.
void check_mesh_dimension(const ProblemFile& problem, const GmshMesh& mesh) {
  if (problem.components == 3 && mesh.dimension() < 3)
    throw InputError(problem.path + ": components: 3 (a solid) needs a volume mesh with physical volumes; " +
                     mesh.path() + " has physical groups of dimension " + std::to_string(mesh.dimension()) +
                     " at most (a plane mesh: use \"components\": 2 and \"surfaces\")");
  if (problem.components < 3 && mesh.dimension() == 3)  // a solid's surfaces read as plane triangles: z dropped
    throw InputError(problem.path + ": components: " + std::to_string(problem.components) + " (a plane problem) with " +
                     mesh.path() + ", a volume mesh (it has physical volumes): a solid needs \"components\": 3 and "
                     "\"volumes\"");
}

/// The mesh split as the problem file says, on every rank alike (each reads the whole mesh):
/// the cells of each subdomain, and the body of every node.
struct MeshSplit {
  std::vector<std::vector<Element>> cells;  ///< per subdomain
  std::map<NodeTag, int> body_of_node;
};

/// Refuses a cell in two subdomains (or twice in one: a group listed twice) and a node
/// shared by two bodies, which would glue or double what the user meant apart.
MeshSplit split_mesh(const ProblemFile& problem, const GmshMesh& mesh) {
  MeshSplit split;
  std::map<std::size_t, int> owner;
  for (size_t s = 0; s < problem.subdomains.size(); ++s) {
    const SubdomainSpec& spec = problem.subdomains[s];
    auto& cells = split.cells.emplace_back();
    for (int region : spec.regions) {
      const std::vector<Element> part = from_group(problem, entry(static_cast<int>(s)) + regions_key(problem), [&] {
        return mesh.cells(problem.dimension(), region, spec.partition);
      });
      cells.insert(cells.end(), part.begin(), part.end());
    }
    for (const Element& t : cells) {
      const auto [it, fresh] = owner.emplace(t.tag, static_cast<int>(s));
      if (!fresh)
        throw InputError(problem.path + ": " + entry(it->second) + " and " + entry(static_cast<int>(s)) +
                         " both hold " + cell_word(problem) + " " + std::to_string(t.tag) +
                         " (a " + (problem.dimension() == 3 ? "volume" : "surface") +
                         " or partition listed twice?): each " + cell_word(problem) + " belongs to one subdomain");
      for (NodeTag node : t.nodes) {
        const auto [body, first] = split.body_of_node.emplace(node, spec.body);
        if (!first && body->second != spec.body)
          throw InputError(problem.path + ": node " + std::to_string(node) + " belongs to bodies " +
                           std::to_string(body->second) + " and " + std::to_string(spec.body) + " (" +
                           entry(static_cast<int>(s)) + "): bodies must not share nodes");
      }
    }
  }
  return split;
}

/// The prescribed value of each fixed (node, component), from every "dirichlet" entry. A
/// group without a node in the subdomains, or two entries fixing one dof to different
/// values, are errors.
std::map<std::pair<NodeTag, int>, double> dirichlet_values(const ProblemFile& problem, const GmshMesh& mesh,
                                                         const MeshSplit& split) {
  std::map<std::pair<NodeTag, int>, std::pair<double, size_t>> fixed;  // value and the entry that set it
  for (size_t i = 0; i < problem.dirichlet.size(); ++i) {
    const DirichletSpec& d = problem.dirichlet[i];
    const std::string key = "dirichlet[" + std::to_string(i) + "]";
    const std::vector<NodeTag> nodes = from_group(problem, key + ".group", [&] { return mesh.nodes(d.dim, d.group); });
    std::vector<int> components = d.components;
    if (components.empty())
      for (int c = 0; c < problem.components; ++c) components.push_back(c);
    bool touches = false;
    for (NodeTag node : nodes) {
      if (!split.body_of_node.count(node)) continue;
      touches = true;
      for (int c : components) {
        const auto [it, fresh] = fixed.emplace(std::make_pair(node, c), std::make_pair(d.value, i));
        if (!fresh && it->second.first != d.value)
          throw InputError(problem.path + ": " + key + " and dirichlet[" + std::to_string(it->second.second) +
                           "] fix node " + std::to_string(node) + " component " + std::to_string(c) +
                           " to different values");
      }
    }
    if (!touches)
      throw InputError(problem.path + ": " + key + ".group: physical group " + std::to_string(d.group) +
                       " has no node in the subdomains");
  }
  std::map<std::pair<NodeTag, int>, double> values;
  for (const auto& [dof, value] : fixed) values[dof] = value.first;
  return values;
}

/// The bodies the nodes of boundary group `group` (a curve, a surface in 3D) lie on; a node
/// in no subdomain is an error.
std::set<int> bodies_of_group(const ProblemFile& problem, const GmshMesh& mesh, const MeshSplit& split, int group,
                              const std::string& key) {
  std::set<int> bodies;
  const bool solid = problem.dimension() == 3;
  for (NodeTag node : from_group(problem, key, [&] { return mesh.nodes(problem.dimension() - 1, group); })) {
    const auto body = split.body_of_node.find(node);
    if (body == split.body_of_node.end())
      throw InputError(problem.path + ": " + key + ": node " + std::to_string(node) + " of " +
                       (solid ? "surface " : "curve ") + std::to_string(group) + " lies in no subdomain");
    bodies.insert(body->second);
  }
  return bodies;
}

/// Slave and master on the same body would give no contact row at all: refused.
void check_contact_bodies(const ProblemFile& problem, const GmshMesh& mesh, const MeshSplit& split) {
  for (size_t i = 0; i < problem.contact.size(); ++i) {
    const ContactSpec& c = problem.contact[i];
    const std::string key = "contact[" + std::to_string(i) + "]";
    const std::set<int> slave = bodies_of_group(problem, mesh, split, c.slave, key + ".slave");
    if (c.obstacle) continue;
    const std::string kind = problem.dimension() == 3 ? "surface " : "curve ";
    for (int body : bodies_of_group(problem, mesh, split, c.master, key + ".master"))
      if (slave.count(body))
        throw InputError(problem.path + ": " + key + ": the slave " + kind + std::to_string(c.slave) +
                         " and the master " + kind + std::to_string(c.master) + " both lie on body " +
                         std::to_string(body) + " (contact acts between different bodies)");
  }
}

/// A P1 stiffness matrix couples two rows only where their nodes are one node or share a
/// cell (every pair of a simplex's nodes is an edge). A dof map that contradicts this (two
/// rows swapped, the map of another system) would solve a plausible but wrong problem:
/// refused, naming the first such entry.
void check_couplings(const SparseMatrix& K, const SubdomainLayout& layout, const std::string& where,
                     const std::string& cell) {
  std::set<std::pair<NodeTag, NodeTag>> edges;
  for (const Element& t : layout.cells)
    for (size_t i = 0; i < t.nodes.size(); ++i)
      for (size_t j = i + 1; j < t.nodes.size(); ++j)
        edges.insert({std::min(t.nodes[i], t.nodes[j]), std::max(t.nodes[i], t.nodes[j])});
  for (Eigen::Index j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
      if (it.value() == 0) continue;
      const DofLocation& a = layout.dofs[static_cast<size_t>(it.row())];
      const DofLocation& b = layout.dofs[static_cast<size_t>(j)];
      if (a.node == b.node || edges.count({std::min(a.node, b.node), std::max(a.node, b.node)})) continue;
      throw InputError(where + ": the matrix couples row " + std::to_string(it.row()) + " (node " +
                       std::to_string(a.node) + ") and row " + std::to_string(j) + " (node " + std::to_string(b.node) +
                       "), whose nodes share no " + cell + " of the subdomain: the dof map does not fit the matrix "
                       "(rows swapped, or the map of another system)");
    }
}

/// Reads one subdomain's system and checks it against its mesh part.
SubdomainInput read_subdomain(const ProblemFile& problem, const GmshMesh& mesh, int s, std::vector<Element> cells,
                              const std::map<std::pair<NodeTag, int>, double>& fixed, SubdomainLayout& layout) {
  const SubdomainSpec& spec = problem.subdomains[static_cast<size_t>(s)];
  layout.id = s;
  layout.cells = std::move(cells);
  const std::string matrix_file = resolve(problem, spec.matrix), rhs_file = resolve(problem, spec.rhs);
  const std::string map_file = resolve(problem, spec.dofs.getdp_pre.empty() ? spec.dofs.explicit_file : spec.dofs.getdp_pre);
  SubdomainInput sub;
  sub.K = read_matrix(matrix_file);
  sub.f = read_vector(rhs_file);
  layout.dofs = spec.dofs.getdp_pre.empty() ? read_explicit_dof_map(map_file, problem.components)
                                           : read_getdp_dof_map(map_file, spec.dofs.system, problem.components);
  if (sub.K.rows() != sub.f.size() || sub.K.rows() != static_cast<Eigen::Index>(layout.dofs.size()))
    throw InputError(problem.path + ": " + entry(s) + ": sizes differ: " + matrix_file + " has " +
                     std::to_string(sub.K.rows()) + " rows, " + rhs_file + " " + std::to_string(sub.f.size()) +
                     " entries, the dof map " + map_file + " " + std::to_string(layout.dofs.size()) + " rows");
  std::set<NodeTag> element_nodes;
  for (const Element& t : layout.cells) element_nodes.insert(t.nodes.begin(), t.nodes.end());
  layout.rows = index_rows(layout.dofs);
  if (layout.rows.size() != layout.dofs.size())
    throw InputError(map_file + ": " + entry(s) + ": a node and component appear on two rows");
  for (const DofLocation& dof : layout.dofs)
    if (!element_nodes.count(dof.node))
      throw InputError(map_file + ": " + entry(s) + ": node " + std::to_string(dof.node) +
                       " has a row but is not a vertex of the subdomain's " + cells_word(problem) + " (physical " +
                       (problem.dimension() == 3 ? "volumes" : "surfaces") + " of " + entry(s) + regions_key(problem) +
                       "): the mesh and the system do not match");
  for (NodeTag node : element_nodes)
    for (int c = 0; c < problem.components; ++c)
      if (!layout.rows.count({node, c}))
        throw InputError(map_file + ": " + entry(s) + ": node " + std::to_string(node) + " component " +
                         std::to_string(c) + " has no row: the mesh and the system do not match");
  check_couplings(sub.K, layout, map_file + ": " + entry(s), cell_word(problem));
  for (size_t i = 0; i < layout.dofs.size(); ++i) {
    const DofLocation& dof = layout.dofs[i];
    const auto position = mesh.position(dof.node);
    sub.x.push_back(position[0]);
    sub.y.push_back(position[1]);
    if (problem.dimension() == 3) sub.z.push_back(position[2]);  // a third coordinate makes the core's problem 3D
    if (problem.components > 1) sub.component.push_back(dof.component);
    const auto value = fixed.find({dof.node, dof.component});
    if (value != fixed.end()) {
      sub.dirichlet_dofs.push_back(static_cast<int>(i));
      sub.dirichlet_values.push_back(value->second);
    }
  }
  sub.body = spec.body;
  return sub;
}

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

/// The master segments of curve `group` that lie on the local subdomains, as dofs of the
/// subdomain holding the segment's triangle, oriented with that triangle on the left (the
/// core's convention, whatever the curve's orientation in the mesh). Returns how many of
/// the curve's segments are here; the caller checks that every rank together found all.
long add_master_segments(const std::vector<std::array<NodeTag, 2>>& segments, const GmshMesh& mesh,
                         const std::vector<SubdomainLayout>& layouts, const EdgeMap& edges, ContactInput& contact) {
  long found = 0;
  for (const auto& [a, b] : segments) {
    const auto edge = edges.find({std::min(a, b), std::max(a, b)});
    if (edge == edges.end()) continue;
    const auto [k, c] = edge->second;
    const auto pa = mesh.position(a), pb = mesh.position(b), pc = mesh.position(c);
    const double left = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
    const NodeTag first = left > 0 ? a : b, second = left > 0 ? b : a;
    const RowIndex& rows = layouts[k].rows;
    contact.master_segments[k].push_back(
        {rows.at({first, 0}), rows.at({first, 1}), rows.at({second, 0}), rows.at({second, 1})});
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

/// The master triangles of surface `group` that lie on the local subdomains, as the 9 dofs
/// of the subdomain holding the triangle's tetrahedron, ordered so that (b - a) x (c - a)
/// points away from that tetrahedron (out of its body: the core's convention, whatever the
/// surface's orientation in the mesh). Returns how many are here; the caller checks that
/// every rank together found all.
long add_master_faces(const std::vector<std::array<NodeTag, 3>>& triangles, const GmshMesh& mesh,
                      const std::vector<SubdomainLayout>& layouts, const FaceMap& faces, ContactInput& contact) {
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
    const RowIndex& rows = layouts[k].rows;
    std::array<int, 9> dofs{};
    for (size_t corner = 0; corner < 3; ++corner)
      for (int c = 0; c < 3; ++c) dofs[3 * corner + static_cast<size_t>(c)] = rows.at({corners[corner], c});
    contact.master_faces[k].push_back(dofs);
    ++found;
  }
  return found;
}

/// The line of a straight obstacle curve, its normal pointing to the slave nodes' side.
/// InputError if the curve is not straight or the slave nodes' centroid lies on it.
void obstacle_from_curve(const ProblemFile& problem, const GmshMesh& mesh, const ContactSpec& c, const std::string& key,
                         ContactInput& contact) {
  const auto nodes = from_group(problem, key + ".obstacle.curve", [&] { return mesh.nodes(1, c.obstacle_curve); });
  const auto p0 = mesh.position(nodes.front());
  std::array<double, 3> far = p0;
  for (NodeTag node : nodes) {
    const auto p = mesh.position(node);
    if (std::hypot(p[0] - p0[0], p[1] - p0[1]) > std::hypot(far[0] - p0[0], far[1] - p0[1])) far = p;
  }
  const double length = std::hypot(far[0] - p0[0], far[1] - p0[1]);
  if (!(length > 0)) throw InputError(problem.path + ": " + key + ".obstacle.curve: the curve has no length");
  std::array<double, 2> normal{-(far[1] - p0[1]) / length, (far[0] - p0[0]) / length};
  auto offset = [&](const std::array<double, 3>& p) { return normal[0] * (p[0] - p0[0]) + normal[1] * (p[1] - p0[1]); };
  for (NodeTag node : nodes)
    if (std::abs(offset(mesh.position(node))) > 1e-9 * length)
      throw InputError(problem.path + ": " + key + ".obstacle.curve: curve " + std::to_string(c.obstacle_curve) +
                       " is not straight (node " + std::to_string(node) + " lies off the line): a rigid obstacle is a line");
  std::array<double, 3> centroid{0, 0, 0};  // z unused: a plane problem
  const auto slaves = mesh.nodes(1, c.slave);
  for (NodeTag node : slaves)
    for (int k = 0; k < 2; ++k) centroid[k] += mesh.position(node)[k] / static_cast<double>(slaves.size());
  const double side = offset(centroid);
  if (std::abs(side) <= 1e-9 * length)
    throw InputError(problem.path + ": " + key + ".obstacle.curve: the slave nodes' centroid lies on the obstacle's "
                     "line: give \"point\" and \"normal\" instead");
  if (side < 0) normal = {-normal[0], -normal[1]};
  contact.obstacle_point = {p0[0], p0[1], 0.0};
  contact.obstacle_normal = {normal[0], normal[1], 0.0};
}

/// Dofs of the local subdomains at `nodes` (sorted; all components).
void add_node_dofs(const std::vector<NodeTag>& nodes, const std::vector<SubdomainLayout>& layouts,
                   std::vector<std::vector<int>>& dofs) {
  for (size_t k = 0; k < layouts.size(); ++k)
    for (size_t i = 0; i < layouts[k].dofs.size(); ++i)
      if (std::binary_search(nodes.begin(), nodes.end(), layouts[k].dofs[i].node))
        dofs[k].push_back(static_cast<int>(i));
}

/// Coulomb's coefficient `mu` at the dofs of `nodes` (sorted: a contact entry's slave curve),
/// 0 at the other dofs: one coefficient per contact entry.
void set_friction(const std::vector<NodeTag>& nodes, double mu, const std::vector<SubdomainLayout>& layouts,
                  std::vector<std::vector<double>>& field) {
  field.resize(layouts.size());
  for (size_t k = 0; k < layouts.size(); ++k) {
    if (field[k].empty()) field[k].assign(layouts[k].dofs.size(), 0.0);
    for (size_t i = 0; i < layouts[k].dofs.size(); ++i)
      if (std::binary_search(nodes.begin(), nodes.end(), layouts[k].dofs[i].node)) field[k][i] = mu;
  }
}

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
  const ContactSpec& first = problem.contact.front();
  if (first.search_distance) contact.search_distance = *first.search_distance;
  contact.gap = first.gap.value_or(0.0);
  // Coulomb: a coefficient per entry (0 for an entry without one); Tresca: one bound.
  const bool coulomb = std::any_of(problem.contact.begin(), problem.contact.end(),
                                   [](const ContactSpec& c) { return c.friction.has_value(); });
  if (coulomb) contact.friction = 0.0;
  contact.slip_bound = first.slip_bound.value_or(-1.0);
  for (size_t i = 0; i < problem.contact.size(); ++i) {
    const ContactSpec& c = problem.contact[i];
    const std::string key = "contact[" + std::to_string(i) + "]";
    if (c.search_distance != first.search_distance || c.gap != first.gap || c.slip_bound != first.slip_bound)
      throw InputError(problem.path + ": " + key +
                       ": search_distance, gap and slip_bound must be those of contact[0] (one value per problem)");
    const std::vector<NodeTag> slaves =
        from_group(problem, key + ".slave", [&] { return mesh.nodes(boundary, c.slave); });
    add_node_dofs(slaves, layouts, contact.slave_dofs);
    if (c.friction) set_friction(slaves, *c.friction, layouts, contact.friction_field);
    if (c.obstacle) {
      if (contact.obstacle)
        throw InputError(problem.path + ": " + key + ": a second obstacle (one rigid obstacle per problem)");
      contact.obstacle = true;
      contact.obstacle_point = c.obstacle_point;  // z entries 0 in a plane problem
      contact.obstacle_normal = c.obstacle_normal;
      if (c.obstacle_curve > 0) obstacle_from_curve(problem, mesh, c, key, contact);
    } else if (problem.components == 1) {  // node to node, matching meshes
      contact.master_dofs.resize(n);
      add_node_dofs(from_group(problem, key + ".master", [&] { return mesh.nodes(boundary, c.master); }), layouts,
                    contact.master_dofs);
    } else if (solid) {  // node to face
      contact.master_faces.resize(n);
      const auto triangles = from_group(problem, key + ".master", [&] { return mesh.faces(c.master); });
      segments_total += static_cast<long>(triangles.size());
      segments_here += add_master_faces(triangles, mesh, layouts, faces, contact);
    } else {
      contact.master_segments.resize(n);
      const auto segments = from_group(problem, key + ".master", [&] { return mesh.segments(c.master); });
      segments_total += static_cast<long>(segments.size());
      segments_here += add_master_segments(segments, mesh, layouts, edges, contact);
    }
  }
  return contact;
}

}  // namespace

std::vector<int> balanced_subdomains(const std::vector<std::vector<Element>>& triangles, int rank, int ranks) {
  // Largest first to the rank with the fewest cells so far (ties: the lower index and
  // rank), the same on every rank: round robin by index once put 7,020 of 7,748 unknowns
  // on one of two ranks.
  std::vector<int> order(triangles.size());
  for (size_t s = 0; s < order.size(); ++s) order[s] = static_cast<int>(s);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return triangles[static_cast<size_t>(a)].size() > triangles[static_cast<size_t>(b)].size();
  });
  std::vector<size_t> load(static_cast<size_t>(ranks), 0);
  std::vector<int> mine;
  for (int s : order) {
    const auto lightest = static_cast<int>(std::min_element(load.begin(), load.end()) - load.begin());
    load[static_cast<size_t>(lightest)] += triangles[static_cast<size_t>(s)].size();
    if (lightest == rank) mine.push_back(s);
  }
  std::sort(mine.begin(), mine.end());
  return mine;
}

NativeInput build_input(const ProblemFile& problem, const GmshMesh& mesh, int rank, int ranks) {
  NativeInput input;
  try {  // the core's messages name the option; say where it was written
    input.setup = problem.solver.setup(problem.components > 1);
    const SolverSettings solver = problem.solver.solve(input.setup.variant);
    input.solve = solver.solve;
    input.verbosity = solver.verbosity;
  } catch (const InputError& error) {
    throw InputError(problem.path + ": solver." + error.what());
  }
  check_mesh_dimension(problem, mesh);
  MeshSplit split = split_mesh(problem, mesh);
  const auto fixed = dirichlet_values(problem, mesh, split);
  check_contact_bodies(problem, mesh, split);
  input.ids = balanced_subdomains(split.cells, rank, ranks);
  for (int s : input.ids) {
    input.layouts.emplace_back();
    input.subdomains.push_back(
        read_subdomain(problem, mesh, s, std::move(split.cells[static_cast<size_t>(s)]), fixed, input.layouts.back()));
  }
  input.contact = build_contact(problem, mesh, input.layouts, input.master_segments_here, input.master_segments_total);
  return input;
}

}  // namespace ffeti::native
