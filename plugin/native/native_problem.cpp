#include "native/native_problem.h"

#include "feti/errors.h"
#include "feti/option_names.h"

#include <algorithm>
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

/// Reads one subdomain's system and checks it against its mesh part.
SubdomainInput read_subdomain(const ProblemFile& problem, const GmshMesh& mesh, int s, SubdomainLayout& layout) {
  const SubdomainSpec& spec = problem.subdomains[static_cast<size_t>(s)];
  layout.id = s;
  for (int surface : spec.surfaces) {
    const std::vector<Triangle> part = mesh.triangles(surface, spec.partition);
    layout.triangles.insert(layout.triangles.end(), part.begin(), part.end());
  }
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
  for (const Triangle& t : layout.triangles) element_nodes.insert(t.nodes.begin(), t.nodes.end());
  const RowIndex rows = index_rows(layout.dofs);
  if (rows.size() != layout.dofs.size())
    throw InputError(map_file + ": " + entry(s) + ": a node and component appear on two rows");
  for (const DofLocation& dof : layout.dofs)
    if (!element_nodes.count(dof.node))
      throw InputError(map_file + ": " + entry(s) + ": node " + std::to_string(dof.node) +
                       " has a row but is not a vertex of the subdomain's triangles (physical surfaces of " +
                       entry(s) + ".surfaces): the mesh and the system do not match");
  for (NodeTag node : element_nodes)
    for (int c = 0; c < problem.components; ++c)
      if (!rows.count({node, c}))
        throw InputError(map_file + ": " + entry(s) + ": node " + std::to_string(node) + " component " +
                         std::to_string(c) + " has no row: the mesh and the system do not match");
  for (const DofLocation& dof : layout.dofs) {
    const auto position = mesh.position(dof.node);
    sub.x.push_back(position[0]);
    sub.y.push_back(position[1]);
    if (problem.components > 1) sub.component.push_back(dof.component);
  }
  sub.body = spec.body;
  for (const DirichletSpec& d : problem.dirichlet) {
    const std::vector<NodeTag> nodes = mesh.nodes(d.dim, d.group);
    for (size_t i = 0; i < layout.dofs.size(); ++i) {
      const DofLocation& dof = layout.dofs[i];
      const bool component = d.components.empty() ||
                             std::find(d.components.begin(), d.components.end(), dof.component) != d.components.end();
      if (component && std::binary_search(nodes.begin(), nodes.end(), dof.node)) {
        sub.dirichlet_dofs.push_back(static_cast<int>(i));
        sub.dirichlet_values.push_back(d.value);
      }
    }
  }
  return sub;
}

/// Each triangle edge of the local subdomains: (subdomain position, opposite vertex).
using EdgeMap = std::map<std::pair<NodeTag, NodeTag>, std::pair<size_t, NodeTag>>;

EdgeMap edges_of(const std::vector<SubdomainLayout>& layouts) {
  EdgeMap edges;
  for (size_t k = 0; k < layouts.size(); ++k)
    for (const Triangle& t : layouts[k].triangles)
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
long add_master_segments(const GmshMesh& mesh, int group, const std::vector<SubdomainLayout>& layouts,
                         const EdgeMap& edges, ContactInput& contact, long& total) {
  long found = 0;
  const auto segments = mesh.segments(group);
  total += static_cast<long>(segments.size());
  for (const auto& [a, b] : segments) {
    const auto edge = edges.find({std::min(a, b), std::max(a, b)});
    if (edge == edges.end()) continue;
    const auto [k, c] = edge->second;
    const auto pa = mesh.position(a), pb = mesh.position(b), pc = mesh.position(c);
    const double left = (pb[0] - pa[0]) * (pc[1] - pa[1]) - (pb[1] - pa[1]) * (pc[0] - pa[0]);
    const NodeTag first = left > 0 ? a : b, second = left > 0 ? b : a;
    const RowIndex rows = index_rows(layouts[k].dofs);
    contact.master_segments[k].push_back(
        {rows.at({first, 0}), rows.at({first, 1}), rows.at({second, 0}), rows.at({second, 1})});
    ++found;
  }
  return found;
}

/// Dofs of the local subdomains at the nodes of curve `group` (all components).
void add_node_dofs(const GmshMesh& mesh, int group, const std::vector<SubdomainLayout>& layouts,
                   std::vector<std::vector<int>>& dofs) {
  const std::vector<NodeTag> nodes = mesh.nodes(1, group);
  for (size_t k = 0; k < layouts.size(); ++k)
    for (size_t i = 0; i < layouts[k].dofs.size(); ++i)
      if (std::binary_search(nodes.begin(), nodes.end(), layouts[k].dofs[i].node))
        dofs[k].push_back(static_cast<int>(i));
}

ContactInput build_contact(const ProblemFile& problem, const GmshMesh& mesh, const std::vector<SubdomainLayout>& layouts,
                           long& segments_here, long& segments_total) {
  ContactInput contact;
  if (problem.contact.empty()) return contact;
  const EdgeMap edges = problem.components > 1 ? edges_of(layouts) : EdgeMap();
  const size_t n = layouts.size();
  contact.slave_dofs.resize(n);
  const ContactSpec& first = problem.contact.front();
  contact.search_distance = first.search_distance;
  contact.gap = first.gap;
  for (size_t i = 0; i < problem.contact.size(); ++i) {
    const ContactSpec& c = problem.contact[i];
    const std::string name = problem.path + ": contact[" + std::to_string(i) + "]";
    if (c.search_distance != first.search_distance || c.gap != first.gap)
      throw InputError(name + ": search_distance and gap must be those of contact[0] (one value per problem)");
    add_node_dofs(mesh, c.slave, layouts, contact.slave_dofs);
    if (c.obstacle) {
      if (contact.obstacle) throw InputError(name + ": a second obstacle (one rigid obstacle per problem)");
      contact.obstacle = true;
      contact.obstacle_point = c.obstacle_point;
      contact.obstacle_normal = c.obstacle_normal;
    } else if (problem.components == 1) {  // node to node, matching meshes
      contact.master_dofs.resize(n);
      add_node_dofs(mesh, c.master, layouts, contact.master_dofs);
    } else {
      contact.master_segments.resize(n);
      segments_here += add_master_segments(mesh, c.master, layouts, edges, contact, segments_total);
    }
  }
  return contact;
}

FetiSetupSettings setup_settings(const SolverSpec& s, bool vector_field) {
  FetiSetupSettings settings;
  settings.variant = variant_from_name(s.variant.empty() ? default_variant_name(vector_field) : s.variant);
  settings.factor = factor_from_name(s.factor);
  settings.threads = checked_threads(s.threads);
  settings.dirichlet_preconditioner = dirichlet_preconditioner_from_name(s.preconditioner);
  return settings;
}

DualSolveSettings solve_settings(const SolverSpec& s) {
  DualSolveSettings settings;
  settings.tolerance = s.tol;
  settings.max_hessian = static_cast<int>(std::min<long>(s.maxit, 1L << 30));
  settings.smalbe.variant = algorithm_from_name(s.algorithm);
  settings.mprgp.expansion = expansion_from_name(s.expansion);
  settings.stopping = stop_from_name(s.stop);
  if (s.rho) settings.smalbe.rho_factor = *s.rho;
  if (s.M) settings.smalbe.M_factor = *s.M;
  if (s.eta) settings.smalbe.eta_factor = *s.eta;
  if (s.gamma) settings.mprgp.gamma = *s.gamma;
  settings.validate();
  return settings;
}

}  // namespace

std::string resolve(const ProblemFile& problem, const std::string& path) {
  return path.empty() || path[0] == '/' ? path : problem.directory + "/" + path;
}

NativeInput build_input(const ProblemFile& problem, const GmshMesh& mesh, const std::vector<int>& ids) {
  NativeInput input;
  try {  // the core's messages name the option; say where it was written
    input.setup = setup_settings(problem.solver, problem.components > 1);
    input.solve = solve_settings(problem.solver);
  } catch (const InputError& error) {
    throw InputError(problem.path + ": solver." + error.what());
  }
  for (int s : ids) {
    input.layouts.emplace_back();
    input.subdomains.push_back(read_subdomain(problem, mesh, s, input.layouts.back()));
  }
  input.contact = build_contact(problem, mesh, input.layouts, input.master_segments_here, input.master_segments_total);
  return input;
}

}  // namespace ffeti::native
