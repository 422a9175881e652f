#include "sens/contact_derivative.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ffeti {
namespace {

using Kind = ContactRowGeometry::Kind;

bool three_d(const ContactRowGeometry& g) { return g.slave_z[0] >= 0; }

/// The nodes whose motion moves a row, each named by its x dof: the slave, and the
/// segment's ends (node to segment) or the face's corners (node to face).
std::vector<std::array<int, 2>> moving_nodes(const ContactRowGeometry& g) {
  if (g.kind == Kind::obstacle || g.kind == Kind::ball) return {g.slave[0]};
  if (g.kind == Kind::node_to_segment) return {g.slave[0], g.master[0], g.master[2]};
  if (g.kind == Kind::node_to_face) return {g.slave[0], g.face[0], g.face[3], g.face[6]};
  return {};
}

Point3 moved(const Point3& p, const Point3& velocity, double t) {
  return {p[0] + t * velocity[0], p[1] + t * velocity[1], p[2] + t * velocity[2]};
}
Point moved(const Point& p, const Point3& velocity, double t) { return {p[0] + t * velocity[0], p[1] + t * velocity[1]}; }

/// A row's linear condition at the nodes moved by t times their velocities (`v`, in
/// moving_nodes' order), keeping its pairing: coefficients of `dofs`, and the gap.
struct RowAt {
  std::vector<std::array<int, 2>> dofs;
  std::vector<double> coefficients;
  double gap = 0;
};

RowAt row_at(const ContactRowGeometry& g, const std::array<Point3, 4>& v, double t) {
  RowAt row;
  if (g.kind == Kind::ball) {  // -n.u_s <= |s - c| - radius, n = (s - c)/|s - c|: n moves with s
    const Point3 s = moved(g.s3, v[0], t), &c = g.corners[0];
    const double distance = std::hypot(s[0] - c[0], s[1] - c[1], s[2] - c[2]);
    row.dofs = {g.slave[0], g.slave[1], g.slave_z};
    for (size_t i = 0; i < 3; ++i) row.coefficients.push_back(-(s[i] - c[i]) / distance);
    row.gap = distance - g.corners[1][0];
  } else if (g.kind == Kind::obstacle && three_d(g)) {  // -n.u_s <= n.(s - point): only the gap moves
    const Point3& n = g.corners[1];
    const Point3 s = moved(g.s3, v[0], t);
    row.dofs = {g.slave[0], g.slave[1], g.slave_z};
    row.coefficients = {-n[0], -n[1], -n[2]};
    for (size_t i = 0; i < 3; ++i) row.gap += n[i] * (s[i] - g.corners[0][i]);
  } else if (g.kind == Kind::obstacle) {
    const LinearizedRow r = obstacle_row(moved(g.s, v[0], t), g.a, g.b);
    row.dofs = {g.slave[0], g.slave[1]};
    row.coefficients = {r.coefficients[0], r.coefficients[1]};
    row.gap = r.gap;
  } else if (g.kind == Kind::node_to_segment) {
    const LinearizedRow r = node_to_segment_row(moved(g.s, v[0], t), moved(g.a, v[1], t), moved(g.b, v[2], t), false);
    row.dofs = {g.slave[0], g.slave[1], g.master[0], g.master[1], g.master[2], g.master[3]};
    row.coefficients.assign(r.coefficients.begin(), r.coefficients.end());
    row.gap = r.gap;
  } else {  // node to face
    const LinearizedFaceRow r = node_to_face_row(moved(g.s3, v[0], t), moved(g.corners[0], v[1], t),
                                                 moved(g.corners[1], v[2], t), moved(g.corners[2], v[3], t), false);
    row.dofs = {g.slave[0], g.slave[1], g.slave_z};
    row.dofs.insert(row.dofs.end(), g.face.begin(), g.face.end());
    row.coefficients.assign(r.coefficients.begin(), r.coefficients.end());
    row.gap = r.gap;
  }
  return row;
}

/// The length the row's geometry is measured in: the step of the differences scales with it.
double row_length(const ContactRowGeometry& g) {
  if (g.kind == Kind::node_to_segment) return std::hypot(g.b[0] - g.a[0], g.b[1] - g.a[1]);
  if (g.kind == Kind::node_to_face) {
    const Point3 &a = g.corners[0], &b = g.corners[1];
    return std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  }
  if (g.kind == Kind::ball) return g.corners[1][0];
  return 1.0;  // the obstacle row is linear in the slave position: any step is exact
}

}  // namespace

std::vector<RowDerivative> contact_row_derivatives(const Constraints& constraints,
                                                   const std::vector<int>& global_ids,
                                                   const NodeVelocities& velocities, const Communicator& comm) {
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
    const auto nodes = moving_nodes(constraints.geometry[row]);
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
  std::vector<std::array<Point3, 4>> velocity(result.size());
  std::vector<std::array<int, 4>> missing(result.size(), {-1, -1, -1, -1});  // subdomain of a node without velocities
  for (size_t p = 0; p + 6 <= all.size(); p += 6) {
    const auto row = static_cast<size_t>(all[p]), node = static_cast<size_t>(all[p + 1]);
    velocity[row][node] = {all[p + 2], all[p + 3], all[p + 4]};
    if (all[p + 5] == 0) missing[row][node] = moving_nodes(constraints.geometry[row])[node][0];
  }
  // A row some of whose nodes move while the subdomain of another gave no velocity at all:
  // most likely a velocity the script forgot (its gradient would be silently wrong), so
  // refuse; a subdomain that does not move passes zeros, or nothing on every row it touches.
  for (size_t row = 0; row < result.size(); ++row) {
    bool moving = false;
    for (const Point3& w : velocity[row]) moving = moving || w[0] != 0 || w[1] != 0 || w[2] != 0;
    for (int subdomain : missing[row])
      if (moving && subdomain >= 0) {
        const ContactRowGeometry& g = constraints.geometry[row];
        throw InputError(std::string(three_d(g) ? "velocityX, velocityY, velocityZ" : "velocityX, velocityY") +
                         ": the contact row of the slave node at (" + std::to_string(g.s[0]) + ", " +
                         std::to_string(g.s[1]) + (three_d(g) ? ", " + std::to_string(g.s3[2]) : std::string()) +
                         ") moves, but subdomain " + std::to_string(subdomain) +
                         ", which holds one of its nodes, has no velocity: give velocities for every subdomain "
                         "holding nodes of moving contact rows (zeros where they stand still)");
      }
  }

  for (size_t row = 0; row < result.size(); ++row) {
    const ContactRowGeometry& g = constraints.geometry[row];
    if (g.kind == Kind::node_to_node) continue;
    const auto& v = velocity[row];
    double speed = 0;
    for (const Point3& w : v) speed = std::max(speed, std::hypot(w[0], w[1], w[2]));
    if (speed == 0) continue;
    const double step = 1e-6 * row_length(g) / speed;
    const RowAt plus = row_at(g, v, step), minus = row_at(g, v, -step);
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
