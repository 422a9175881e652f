#include "sens/contact_derivative.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ffeti {
namespace {

using Kind = ContactRowGeometry::Kind;

/// The nodes whose motion moves a row: the slave, and for node to segment the segment's
/// ends, each named by its x dof.
std::vector<std::array<int, 2>> moving_nodes(const ContactRowGeometry& g) {
  if (g.kind == Kind::obstacle) return {g.slave[0]};
  if (g.kind == Kind::node_to_segment) return {g.slave[0], g.master[0], g.master[2]};
  return {};
}

Point moved(const Point& p, const Point& velocity, double t) {
  return {p[0] + t * velocity[0], p[1] + t * velocity[1]};
}

}  // namespace

std::vector<RowDerivative> contact_row_derivatives(const Constraints& constraints,
                                                   const std::vector<int>& global_ids,
                                                   const std::vector<std::vector<double>>& velocity_x,
                                                   const std::vector<std::vector<double>>& velocity_y,
                                                   const Communicator& comm) {
  std::vector<RowDerivative> result(constraints.geometry.size());
  bool moves_here = false;
  for (const auto& v : velocity_x) moves_here = moves_here || !v.empty();
  for (const auto& v : velocity_y) moves_here = moves_here || !v.empty();
  if (comm.max(moves_here ? 1.0 : 0.0) == 0) return result;

  // Each rank sends (row, node, vx, vy, given) for the nodes of its subdomains; given: the
  // subdomain has a velocity array at all (an empty one means "does not move").
  std::map<int, size_t> local_index;
  for (size_t k = 0; k < global_ids.size(); ++k) local_index[global_ids[k]] = k;
  const auto has = [](const std::vector<std::vector<double>>& v, size_t k) { return k < v.size() && !v[k].empty(); };
  const auto component = [&](const std::vector<std::vector<double>>& v, size_t k, int dof) {
    return has(v, k) ? v[k][static_cast<size_t>(dof)] : 0.0;
  };
  std::vector<double> packed;
  for (size_t row = 0; row < result.size(); ++row) {
    const auto nodes = moving_nodes(constraints.geometry[row]);
    for (size_t node = 0; node < nodes.size(); ++node) {
      const auto it = local_index.find(nodes[node][0]);
      if (it == local_index.end()) continue;
      const bool given = has(velocity_x, it->second) || has(velocity_y, it->second);
      packed.insert(packed.end(), {double(row), double(node), component(velocity_x, it->second, nodes[node][1]),
                                   component(velocity_y, it->second, nodes[node][1]), given ? 1.0 : 0.0});
    }
  }
  const std::vector<double> all = comm.allgather(packed);
  std::vector<std::array<Point, 3>> velocity(result.size(), {Point{0, 0}, Point{0, 0}, Point{0, 0}});
  std::vector<std::array<int, 3>> missing(result.size(), {-1, -1, -1});  // subdomain of a node without velocities
  for (size_t p = 0; p + 5 <= all.size(); p += 5) {
    const auto row = static_cast<size_t>(all[p]), node = static_cast<size_t>(all[p + 1]);
    velocity[row][node] = {all[p + 2], all[p + 3]};
    if (all[p + 4] == 0) missing[row][node] = moving_nodes(constraints.geometry[row])[node][0];
  }
  // A row some of whose nodes move while the subdomain of another gave no velocity at all:
  // most likely a velocity the script forgot (its gradient would be silently wrong), so
  // refuse; a subdomain that does not move passes zeros, or nothing on every row it touches.
  for (size_t row = 0; row < result.size(); ++row) {
    bool moving = false;
    for (const Point& w : velocity[row]) moving = moving || w[0] != 0 || w[1] != 0;
    for (int subdomain : missing[row])
      if (moving && subdomain >= 0) {
        const ContactRowGeometry& g = constraints.geometry[row];
        throw InputError("velocityX, velocityY: the contact row of the slave node at (" + std::to_string(g.s[0]) +
                         ", " + std::to_string(g.s[1]) + ") moves, but subdomain " + std::to_string(subdomain) +
                         ", which holds one of its nodes, has no velocity: give velocities for every subdomain "
                         "holding nodes of moving contact rows (zeros where they stand still)");
      }
  }

  for (size_t row = 0; row < result.size(); ++row) {
    const ContactRowGeometry& g = constraints.geometry[row];
    if (g.kind == Kind::node_to_node) continue;
    const auto& v = velocity[row];
    double speed = 0;
    for (const Point& w : v) speed = std::max(speed, std::hypot(w[0], w[1]));
    if (speed == 0) continue;
    const auto linearized = [&](double t) {
      return g.kind == Kind::obstacle ? obstacle_row(moved(g.s, v[0], t), g.a, g.b)
                                      : node_to_segment_row(moved(g.s, v[0], t), moved(g.a, v[1], t),
                                                            moved(g.b, v[2], t), false);
    };
    // The obstacle row is linear in the slave position: any step is exact.
    const double length = g.kind == Kind::obstacle ? 1.0 : std::hypot(g.b[0] - g.a[0], g.b[1] - g.a[1]);
    const double step = 1e-6 * length / speed;
    const LinearizedRow plus = linearized(step), minus = linearized(-step);
    const std::array<int, 2> dofs[6] = {g.slave[0], g.slave[1], g.master[0], g.master[1], g.master[2], g.master[3]};
    RowDerivative& d = result[row];
    for (size_t k = 0; k < 6; ++k) {
      const double coefficient = (plus.coefficients[k] - minus.coefficients[k]) / (2 * step);
      if (coefficient != 0 && dofs[k][0] >= 0) d.entries.push_back({dofs[k][0], dofs[k][1], coefficient});
    }
    d.rhs = (plus.gap - minus.gap) / (2 * step);
  }
  return result;
}

}  // namespace ffeti
