#include "sens/contact_derivative.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ffeti {
std::vector<RowDerivative> contact_row_derivatives(const Constraints& constraints,
                                                   const std::vector<int>& global_ids,
                                                   const NodeVelocities& velocities, const std::vector<bool>& in_use,
                                                   const Communicator& comm) {
  std::vector<RowDerivative> result(constraints.geometry.size());
  bool moves_here = false;
  for (const auto* field : velocities)
    for (const auto& v : *field) moves_here = moves_here || !v.empty();
  if (comm.max(moves_here ? 1.0 : 0.0) == 0) return result;

  // Each rank sends (row, node, vx, vy, vz, given) for the nodes of its subdomains; given:
  // the subdomain has a velocity array at all (an empty one means "does not move").
  std::map<int, size_t> local_index;
  for (size_t k = 0; k < global_ids.size(); ++k) local_index[global_ids[k]] = k;
  const auto has = [](const std::vector<std::vector<double>>& v, size_t k) { return k < v.size() && !v[k].empty(); };
  const auto component = [&](const std::vector<std::vector<double>>& v, size_t k, int dof) {
    return has(v, k) ? v[k][static_cast<size_t>(dof)] : 0.0;
  };
  std::vector<double> packed;
  for (size_t row = 0; row < result.size(); ++row) {
    const auto nodes = constraints.geometry[row]->moving_nodes();
    for (size_t node = 0; node < nodes.size(); ++node) {
      const auto it = local_index.find(nodes[node][0]);
      if (it == local_index.end()) continue;
      bool given = false;
      packed.insert(packed.end(), {double(row), double(node)});
      for (const auto* field : velocities) {
        given = given || has(*field, it->second);
        packed.push_back(component(*field, it->second, nodes[node][1]));
      }
      packed.push_back(given ? 1.0 : 0.0);
    }
  }
  const std::vector<double> all = comm.allgather(packed);
  std::vector<NodeMotion> velocity;
  std::vector<std::vector<int>> missing;  // per node, the subdomain of a node without velocities (or -1)
  for (const auto& g : constraints.geometry) {
    const size_t nodes = g->moving_nodes().size();
    velocity.emplace_back(nodes);
    missing.emplace_back(nodes, -1);
  }
  for (size_t p = 0; p + 6 <= all.size(); p += 6) {
    const auto row = static_cast<size_t>(all[p]), node = static_cast<size_t>(all[p + 1]);
    velocity[row][node] = {all[p + 2], all[p + 3], all[p + 4]};
    if (all[p + 5] == 0) missing[row][node] = constraints.geometry[row]->moving_nodes()[node][0];
  }
  // A row some of whose nodes move while the subdomain of another gave no velocity at all:
  // most likely a velocity the script forgot (its gradient would be silently wrong), so
  // refuse; a subdomain that does not move passes zeros, or nothing on every row it touches.
  for (size_t row = 0; row < result.size(); ++row) {
    bool moving = false;
    for (const Point3& w : velocity[row]) moving = moving || w[0] != 0 || w[1] != 0 || w[2] != 0;
    for (int subdomain : missing[row])
      if (moving && subdomain >= 0) {
        const ContactRowGeometry& g = *constraints.geometry[row];
        const Point3& s = g.slave_position();
        throw InputError(std::string(g.three_d() ? "velocityX, velocityY, velocityZ" : "velocityX, velocityY") +
                         ": the contact row of the slave node at (" + std::to_string(s[0]) + ", " +
                         std::to_string(s[1]) + (g.three_d() ? ", " + std::to_string(s[2]) : std::string()) +
                         ") moves, but subdomain " + std::to_string(subdomain) +
                         ", which holds one of its nodes, has no velocity: give velocities for every subdomain "
                         "holding nodes of moving contact rows (zeros where they stand still)");
      }
  }

  // Velocities below round-off of the design's fastest node (a sin(pi x) at x = 1) count as
  // still there: their rows' contributions are as small, whichever side they would take.
  double fastest = 0;
  for (const NodeMotion& v : velocity)
    for (const Point3& w : v) fastest = std::max(fastest, std::hypot(w[0], w[1], w[2]));
  for (NodeMotion& v : velocity) v.reference_speed = fastest;
  for (size_t row = 0; row < result.size(); ++row) {
    if (!in_use[row]) continue;
    const ContactRowGeometry& g = *constraints.geometry[row];
    NodeMotion significant(g.moving_nodes().size());
    significant.reference_speed = fastest;
    for (size_t node = 0; node < g.moving_nodes().size(); ++node) {
      const Point3& w = velocity[row][node];
      if (std::hypot(w[0], w[1], w[2]) > 1e-12 * fastest) significant[node] = w;
    }
    result[row].one_sided = g.one_sided_under(significant);
    const std::string reason = g.unverified_motion(significant);  // the same on every rank
    if (!reason.empty()) {
      const Point3& s = g.slave_position();
      throw InputError("velocityX, velocityY, velocityZ: the contact row of the slave node at (" + std::to_string(s[0]) +
                       ", " + std::to_string(s[1]) + ", " + std::to_string(s[2]) + "): " + reason);
    }
  }
  for (size_t row = 0; row < result.size(); ++row) {
    const ContactRowGeometry& g = *constraints.geometry[row];
    const auto& v = velocity[row];
    const double step = difference_step(g, v);
    if (step == 0) continue;
    const RowAt plus = g.row_at(v, step), minus = g.row_at(v, -step);
    RowDerivative& d = result[row];
    for (size_t k = 0; k < plus.dofs.size(); ++k) {
      const double coefficient = (plus.coefficients[k] - minus.coefficients[k]) / (2 * step);
      if (coefficient != 0 && plus.dofs[k][0] >= 0) d.entries.push_back({plus.dofs[k][0], plus.dofs[k][1], coefficient});
    }
    d.rhs = (plus.gap - minus.gap) / (2 * step);
  }
  return result;
}

}  // namespace ffeti
