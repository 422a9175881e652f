#include "native/native_problem.h"

#include "native/contact_input.h"
#include "native/mesh_groups.h"

#include "base/errors.h"
#include "constraints/contact/contact_discretization.h"
#include "service/options.h"

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
    if (c.rigid()) continue;
    const std::string kind = problem.dimension() == 3 ? "surface " : "curve ";
    const std::string master_key = contact_discretizations().at(static_cast<size_t>(c.kind))->list_input()->file_key;
    for (int body : bodies_of_group(problem, mesh, split, c.master, key + "." + master_key))
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
