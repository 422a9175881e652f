#include "native/result_files.h"

#include "base/errors.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <set>

namespace ffeti::native {
namespace {

std::ofstream open_output(const std::string& path) {
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write this output file");
  out << std::setprecision(17);
  return out;
}

/// Each slave node's share of its slave surfaces (3D): a third of the area of each triangle
/// at it, the integral of its P1 hat function there.
std::map<NodeTag, double> tributary_areas(const ProblemFile& problem, const GmshMesh& mesh) {
  std::map<NodeTag, double> share;
  std::set<std::array<NodeTag, 3>> counted;  // a triangle of two slave surfaces counts once
  for (const ContactSpec& c : problem.contact)
    for (const auto& corners : mesh.faces(c.slave)) {
      std::array<NodeTag, 3> key = corners;
      std::sort(key.begin(), key.end());
      if (!counted.insert(key).second) continue;
      const auto a = mesh.position(corners[0]), b = mesh.position(corners[1]), d = mesh.position(corners[2]);
      const Eigen::Vector3d u(b[0] - a[0], b[1] - a[1], b[2] - a[2]), v(d[0] - a[0], d[1] - a[1], d[2] - a[2]);
      const double third = u.cross(v).norm() / 6;  // area / 3
      for (NodeTag node : corners) share[node] += third;
    }
  return share;
}

/// Each slave node's share of its slave curves: half the length of each segment at it.
std::map<NodeTag, double> tributary_lengths(const ProblemFile& problem, const GmshMesh& mesh) {
  if (problem.dimension() == 3) return tributary_areas(problem, mesh);
  std::map<NodeTag, double> share;
  std::set<std::pair<NodeTag, NodeTag>> counted;  // a segment of two slave curves counts once
  for (const ContactSpec& c : problem.contact)
    for (const auto& [a, b] : mesh.segments(c.slave)) {
      if (!counted.insert({std::min(a, b), std::max(a, b)}).second) continue;
      const auto pa = mesh.position(a), pb = mesh.position(b);
      const double half = 0.5 * std::hypot(pb[0] - pa[0], pb[1] - pa[1]);
      share[a] += half;
      share[b] += half;
    }
  return share;
}

/// Von Mises stress of one P1 tetrahedron (constant strain): grad u = [u_i - u_0] J^-1 with
/// J = [p_i - p_0], i = 1..3 (columns).
double von_mises_3d(const MaterialSpec& material, const std::array<std::array<double, 3>, 4>& p,
                    const std::array<std::array<double, 3>, 4>& u) {
  Eigen::Matrix3d J, D;
  for (int i = 0; i < 3; ++i)
    for (int r = 0; r < 3; ++r) {
      J(r, i) = p[static_cast<size_t>(i + 1)][static_cast<size_t>(r)] - p[0][static_cast<size_t>(r)];
      D(r, i) = u[static_cast<size_t>(i + 1)][static_cast<size_t>(r)] - u[0][static_cast<size_t>(r)];
    }
  const Eigen::Matrix3d gradient = D * J.inverse();  // (du_r / dx_c)
  const Eigen::Matrix3d strain = 0.5 * (gradient + gradient.transpose());
  const double E = material.young, nu = material.poisson;
  const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  const Eigen::Matrix3d stress = lambda * strain.trace() * Eigen::Matrix3d::Identity() + 2 * mu * strain;
  const Eigen::Matrix3d deviator = stress - stress.trace() / 3 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * deviator.cwiseProduct(deviator).sum());  // sqrt(3/2 s:s)
}

/// Von Mises stress of one P1 triangle (constant strain).
double von_mises(const MaterialSpec& material, const std::array<std::array<double, 2>, 3>& p,
                 const std::array<std::array<double, 2>, 3>& u) {
  // Gradients of the P1 basis functions from the triangle's edge vectors.
  const double area2 = (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
  double exx = 0, eyy = 0, gxy = 0;
  for (int i = 0; i < 3; ++i) {
    const auto& a = p[(i + 1) % 3];
    const auto& b = p[(i + 2) % 3];
    const double dx = (a[1] - b[1]) / area2, dy = (b[0] - a[0]) / area2;
    exx += dx * u[i][0];
    eyy += dy * u[i][1];
    gxy += dy * u[i][0] + dx * u[i][1];
  }
  const double E = material.young, nu = material.poisson;
  const double mu = E / (2 * (1 + nu));
  double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  if (material.plane_stress) lambda = 2 * lambda * mu / (lambda + 2 * mu);
  const double sxx = (lambda + 2 * mu) * exx + lambda * eyy;
  const double syy = lambda * exx + (lambda + 2 * mu) * eyy;
  const double sxy = mu * gxy;
  const double szz = material.plane_stress ? 0.0 : lambda * (exx + eyy);
  return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx)) +
                   3 * sxy * sxy);
}

/// Von Mises stress of each cell of the bodies with a material (displacements: plane
/// triangles, or tetrahedra of a solid).
std::vector<ElementStress> element_stresses(const ProblemFile& problem, const GmshMesh& mesh,
                                            const NodalResults& results) {
  std::vector<ElementStress> stresses;
  if (problem.components < 2) return stresses;
  const int dimension = problem.dimension();
  for (const SubdomainSpec& sub : problem.subdomains) {
    const auto& material = problem.bodies[static_cast<size_t>(sub.body)].material;
    if (!material) continue;
    for (int region : sub.regions)
      for (const Element& t : mesh.cells(dimension, region, sub.partition)) {
        std::array<double, 3> centroid{0, 0, 0};
        for (NodeTag node : t.nodes)
          for (size_t k = 0; k < 3; ++k) centroid[k] += mesh.position(node)[k];
        for (double& c : centroid) c /= static_cast<double>(t.nodes.size());
        double value = 0;
        if (dimension == 3) {
          std::array<std::array<double, 3>, 4> points, displacements;
          for (size_t i = 0; i < 4; ++i) {
            points[i] = mesh.position(t.nodes[i]);
            displacements[i] = results.displacement.at(t.nodes[i]);
          }
          value = von_mises_3d(*material, points, displacements);
        } else {
          std::array<std::array<double, 2>, 3> points, displacements;
          for (size_t i = 0; i < 3; ++i) {
            const auto p = mesh.position(t.nodes[i]);
            const auto& u = results.displacement.at(t.nodes[i]);
            points[i] = {p[0], p[1]};
            displacements[i] = {u[0], u[1]};
          }
          value = von_mises(*material, points, displacements);
          centroid[2] = 0;
        }
        stresses.push_back({t.tag, sub.body, centroid[0], centroid[1], centroid[2], value});
      }
  }
  return stresses;
}

}  // namespace

GatheredSolution gather_solution(const FetiResult& result, const std::vector<SubdomainLayout>& layouts,
                                 int subdomain_count, const Communicator& comm) {
  std::vector<long long> local_dofs;  // per subdomain: id, rows, then (node, component) per row
  std::vector<double> local_values;
  for (size_t k = 0; k < layouts.size(); ++k) {
    local_dofs.push_back(layouts[k].id);
    local_dofs.push_back(static_cast<long long>(layouts[k].dofs.size()));
    for (const DofLocation& dof : layouts[k].dofs) {
      local_dofs.push_back(static_cast<long long>(dof.node));
      local_dofs.push_back(dof.component);
    }
    local_values.insert(local_values.end(), result.u[k].data(), result.u[k].data() + result.u[k].size());
  }
  const std::vector<long long> dofs = comm.allgather(local_dofs);
  const std::vector<double> values = comm.allgather(local_values);
  GatheredSolution solution;
  solution.dofs.resize(static_cast<size_t>(subdomain_count));
  solution.u.resize(static_cast<size_t>(subdomain_count));
  size_t at = 0, value_at = 0;
  while (at < dofs.size()) {
    const auto id = static_cast<size_t>(dofs[at]);
    const auto rows = static_cast<size_t>(dofs[at + 1]);
    at += 2;
    for (size_t i = 0; i < rows; ++i, at += 2)
      solution.dofs[id].push_back({static_cast<NodeTag>(dofs[at]), static_cast<int>(dofs[at + 1])});
    solution.u[id] = Eigen::Map<const Vec>(values.data() + value_at, static_cast<Eigen::Index>(rows));
    value_at += rows;
  }
  return solution;
}

NodalResults nodal_results(const ProblemFile& problem, const GmshMesh& mesh, const GatheredSolution& solution,
                           const std::vector<ContactMultiplier>& contact) {
  NodalResults results;
  std::map<std::pair<NodeTag, int>, std::pair<double, int>> sums;  // (node, component) -> (sum, copies)
  for (size_t s = 0; s < solution.dofs.size(); ++s)
    for (size_t i = 0; i < solution.dofs[s].size(); ++i) {
      const DofLocation& dof = solution.dofs[s][i];
      auto& [sum, copies] = sums[{dof.node, dof.component}];
      sum += solution.u[s][static_cast<Eigen::Index>(i)];
      ++copies;
      results.body[dof.node] = problem.subdomains[s].body;
    }
  for (const auto& [key, value] : sums) results.displacement[key.first][static_cast<size_t>(key.second)] = value.first / value.second;

  // Exact positions: the rows' came from the mesh (z = 0 in a plane problem, as the rows').
  const bool solid = problem.dimension() == 3;
  std::map<std::array<double, 3>, NodeTag> slave_at;
  for (const ContactSpec& c : problem.contact)
    for (NodeTag node : mesh.nodes(problem.dimension() - 1, c.slave)) {
      auto p = mesh.position(node);
      if (!solid) p[2] = 0;
      slave_at[p] = node;
    }
  const std::map<NodeTag, double> share = tributary_lengths(problem, mesh);
  for (const ContactMultiplier& row : contact) {
    const auto node = slave_at.find({row.x, row.y, solid ? row.z : 0.0});
    if (node == slave_at.end()) continue;  // a row of another kind at this position: none expected
    const NodeTag at = node->second;
    results.contact_force[at] += row.lambda;
    results.friction_force[at] += row.tangential;
    results.friction_force_2[at] += row.second_tangential;
    results.slip[at] = row.slip, results.slip_2[at] = row.second_slip;
    results.normal[at] = row.normal, results.tangent_1[at] = row.tangents[0], results.tangent_2[at] = row.tangents[1];
    results.contact_state[at] = static_cast<int>(row.state);
  }
  for (const auto& [node, force] : results.contact_force) {
    const auto length = share.find(node);
    results.contact_pressure[node] = length != share.end() && length->second > 0 ? force / length->second : 0.0;
  }
  results.stresses = element_stresses(problem, mesh, results);
  return results;
}

void write_views(const std::string& path, const ProblemFile& problem, const GmshMesh& mesh,
                 const NodalResults& results) {
  if (!std::ofstream(path)) throw InputError(path + ": cannot write this output file");
  std::vector<int> views;
  auto node_view = [&](const std::string& name, const std::map<NodeTag, double>& values) {
    if (values.empty()) return;
    std::vector<std::size_t> tags;
    std::vector<double> data;
    for (const auto& [node, value] : values) {
      tags.push_back(node);
      data.push_back(value);
    }
    views.push_back(gmsh::view::add(name));
    gmsh::view::addHomogeneousModelData(views.back(), 0, mesh.model_name(), "NodeData", tags, data, 0, 1);
  };
  {
    std::vector<std::size_t> tags;
    std::vector<double> data;
    for (const auto& [node, u] : results.displacement) {
      tags.push_back(node);
      if (problem.components == 1) data.push_back(u[0]);
      else data.insert(data.end(), {u[0], u[1], u[2]});  // u[2] = 0 in a plane problem
    }
    views.push_back(gmsh::view::add("displacement"));
    gmsh::view::addHomogeneousModelData(views.back(), 0, mesh.model_name(), "NodeData", tags, data, 0,
                                        problem.components == 1 ? 1 : 3);
  }
  const auto vector_view = [&](const std::string& name, const std::map<NodeTag, Point3>& values) {
    if (values.empty()) return;
    std::vector<std::size_t> tags;
    std::vector<double> data;
    for (const auto& [node, v] : values) {
      tags.push_back(node);
      data.insert(data.end(), v.begin(), v.end());
    }
    views.push_back(gmsh::view::add(name));
    gmsh::view::addHomogeneousModelData(views.back(), 0, mesh.model_name(), "NodeData", tags, data, 0, 3);
  };
  node_view("contact pressure", results.contact_pressure);
  std::map<NodeTag, double> active;
  for (const auto& [node, force] : results.contact_force) active[node] = force > 0 ? 1.0 : 0.0;
  node_view("active set", active);
  const bool solid = problem.dimension() == 3;
  if (std::any_of(problem.contact.begin(), problem.contact.end(),
                  [](const ContactSpec& c) { return c.friction || c.slip_bound; })) {
    node_view(solid ? "friction force along t1" : "friction force", results.friction_force);
    if (solid) node_view("friction force along t2", results.friction_force_2);
    node_view(solid ? "slip along t1" : "slip", results.slip);
    if (solid) node_view("slip along t2", results.slip_2);
    vector_view("contact normal", results.normal);  // with friction only: the views' order stays otherwise
    vector_view("tangent t1", results.tangent_1);
    if (solid) vector_view("tangent t2", results.tangent_2);
    std::map<NodeTag, double> state(results.contact_state.begin(), results.contact_state.end());
    node_view("contact state (0 open, 1 stick, 2 slip)", state);
  }

  std::vector<std::size_t> element_tags;
  std::vector<double> stress;
  for (const ElementStress& e : results.stresses) {
    element_tags.push_back(e.tag);
    stress.push_back(e.von_mises);
  }
  if (!element_tags.empty()) {
    views.push_back(gmsh::view::add("von Mises"));
    gmsh::view::addHomogeneousModelData(views.back(), 0, mesh.model_name(), "ElementData", element_tags, stress, 0, 1);
  }
  for (size_t k = 0; k < views.size(); ++k) {
    gmsh::option::setNumber("PostProcessing.SaveMesh", k == 0);  // the mesh once, before the first view
    gmsh::view::write(views[k], path, k > 0);
  }
}

void write_table(const std::string& path, const ProblemFile& problem, const GmshMesh& mesh, const NodalResults& results) {
  std::ofstream out = open_output(path);
  const bool solid = problem.components == 3;
  out << (solid ? "node,body,x,y,z,u_x,u_y,u_z," : "node,body,x,y,u_x,u_y,")
      << (solid ? "contact_row,contact_force,contact_pressure,active,friction_force,state,friction_force_2,slip,slip_2,"
                  "n_x,n_y,n_z,t1_x,t1_y,t1_z,t2_x,t2_y,t2_z\n"
                : "contact_row,contact_force,contact_pressure,active,friction_force,state,slip,n_x,n_y,t1_x,t1_y\n");
  const auto vector = [&](const std::map<NodeTag, Point3>& values, NodeTag node, bool slave) {
    const Point3 v = slave ? values.at(node) : Point3{0, 0, 0};
    out << ',' << v[0] << ',' << v[1];
    if (solid) out << ',' << v[2];
  };
  for (const auto& [node, u] : results.displacement) {
    const auto p = mesh.position(node);
    const auto force = results.contact_force.find(node);
    const bool slave = force != results.contact_force.end();
    out << node << ',' << results.body.at(node) << ',' << p[0] << ',' << p[1] << ',';
    if (solid) out << p[2] << ',';
    out << u[0] << ',' << u[1] << ',';
    if (solid) out << u[2] << ',';
    out << slave << ',' << (slave ? force->second : 0.0) << ',' << (slave ? results.contact_pressure.at(node) : 0.0) << ','
        << (slave && force->second > 0 ? 1 : 0) << ',' << (slave ? results.friction_force.at(node) : 0.0) << ','
        << (slave ? results.contact_state.at(node) : 0);
    if (solid) out << ',' << (slave ? results.friction_force_2.at(node) : 0.0);
    out << ',' << (slave ? results.slip.at(node) : 0.0);
    if (solid) out << ',' << (slave ? results.slip_2.at(node) : 0.0);
    vector(results.normal, node, slave);
    vector(results.tangent_1, node, slave);
    if (solid) vector(results.tangent_2, node, slave);
    out << '\n';
  }
}

void write_stress_table(const std::string& path, const ProblemFile& problem, const NodalResults& results) {
  std::ofstream out = open_output(path);
  const bool solid = problem.components == 3;
  out << (solid ? "element,body,x,y,z,von_mises\n" : "element,body,x,y,von_mises\n");
  for (const ElementStress& e : results.stresses) {
    out << e.tag << ',' << e.body << ',' << e.x << ',' << e.y << ',';
    if (solid) out << e.z << ',';
    out << e.von_mises << '\n';
  }
}

void write_getdp_solution(const std::string& path, const ProblemFile& problem, const GatheredSolution& solution) {
  std::map<int, size_t> subdomain_of_system;  // one .pre, each system once: read_problem_file checked it
  for (size_t s = 0; s < problem.subdomains.size(); ++s) subdomain_of_system[problem.subdomains[s].dofs.system] = s;
  std::ofstream out = open_output(path);
  out << "$ResFormat /* ffeti-solve, ascii */\n1.1 0\n$EndResFormat\n";
  for (const auto& [system, s] : subdomain_of_system) {
    out << "$Solution  /* DofData #" << system << " */\n" << system << " 0 0 0\n";
    for (Eigen::Index i = 0; i < solution.u[s].size(); ++i) out << solution.u[s][i] << '\n';
    out << "$EndSolution\n";
  }
}

}  // namespace ffeti::native
