// Mortar contact rows (three dimensions): one row per slave node, its gap weighted by its
// shape function over the slave faces that master faces cover (ContactInput::slave_faces).
#include "feti/constraint_rows.h"
#include "feti/face_grid.h"
#include "feti/mortar_integration.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace ffeti {
namespace {

using NodeKey = std::tuple<int, long long, long long, long long>;  // body, snapped position
using CornerDofs = std::array<int, 4>;                             // subdomain, x, y, z dofs

/// One slave node's row in the making: the integrals of its shape function.
struct MortarRow {
  Point3 normal_sum{};                          ///< area-weighted outward normals of its faces
  std::map<CornerDofs, double> slave, master;   ///< int phi_j phi_k, int phi_j psi_m per node
  Point3 gap{};                                 ///< int phi_j (x_s - x_m)
  double weight = 0;                            ///< int phi_j over the covered part
};

CornerDofs corner_dofs(const FaceRecord& f, size_t corner) {
  return {f.subdomain, f.dofs[3 * corner], f.dofs[3 * corner + 1], f.dofs[3 * corner + 2]};
}

double dot(const Point3& p, const Point3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }

Point3 sum(const std::array<Point3, 3>& v) {
  return {v[0][0] + v[1][0] + v[2][0], v[0][1] + v[1][1] + v[2][1], v[0][2] + v[1][2] + v[2][2]};
}

/// (b - a) x (c - a), not normalized: twice the area times the unit normal.
Point3 area_normal(const Triangle3& t) {
  Point3 n{};
  for (size_t d = 0; d < 3; ++d) {
    const size_t d1 = (d + 1) % 3, d2 = (d + 2) % 3;
    n[d] = (t[1][d1] - t[0][d1]) * (t[2][d2] - t[0][d2]) - (t[1][d2] - t[0][d2]) * (t[2][d1] - t[0][d1]);
  }
  return n;
}

Point3 unit_normal(const Triangle3& t) {
  const Point3 n = area_normal(t);
  const double length = std::sqrt(dot(n, n));
  return {n[0] / length, n[1] / length, n[2] / length};
}

bool by_identity(const FaceRecord& a, const FaceRecord& b) {
  return std::tie(a.subdomain, a.dofs) < std::tie(b.subdomain, b.dofs);
}

}  // namespace

void add_mortar_rows(const std::vector<DofRecord>& records, const std::vector<FaceRecord>& faces,
                     const ContactInput& contact, double snap, std::vector<Row>& rows) {
  // Sorted, so that the sums and the rows do not depend on how faces are spread over ranks.
  std::vector<FaceRecord> slaves, masters;
  for (const FaceRecord& f : faces) (f.slave ? slaves : masters).push_back(f);
  std::sort(slaves.begin(), slaves.end(), by_identity);
  std::sort(masters.begin(), masters.end(), by_identity);
  const FaceGrid grid(masters);

  const std::vector<SlaveNode> nodes = slave_nodes(records, snap, 3);
  std::map<NodeKey, size_t> node_at;
  const auto key = [snap](int body, const Point3& p) {
    return NodeKey{body, std::llround(p[0] / snap), std::llround(p[1] / snap), std::llround(p[2] / snap)};
  };
  for (size_t j = 0; j < nodes.size(); ++j)
    node_at[key(nodes[j].x_dof->body, {nodes[j].x_dof->x, nodes[j].x_dof->y, nodes[j].x_dof->z})] = j;
  std::vector<MortarRow> pending(nodes.size());
  std::vector<std::array<size_t, 3>> face_nodes;
  for (const FaceRecord& f : slaves) {
    std::array<size_t, 3> at{};
    for (size_t c = 0; c < 3; ++c) at[c] = node_at.at(key(f.body, f.corners[c]));  // corners are slave dofs
    face_nodes.push_back(at);
    const Point3 n = area_normal(f.corners);
    for (size_t c = 0; c < 3; ++c)
      for (size_t d = 0; d < 3; ++d) pending[at[c]].normal_sum[d] += n[d];
  }

  // The master faces a slave face may see lie in the prism it sweeps along its normal
  // within the search distance (no farther than the diagonal of all contact faces).
  Point3 lo_all{INFINITY, INFINITY, INFINITY}, hi_all{-INFINITY, -INFINITY, -INFINITY};
  for (const FaceRecord& f : faces)
    for (const Point3& p : f.corners)
      for (size_t d = 0; d < 3; ++d) lo_all[d] = std::min(lo_all[d], p[d]), hi_all[d] = std::max(hi_all[d], p[d]);
  const double reach =
      std::min(contact.search_distance, std::hypot(hi_all[0] - lo_all[0], hi_all[1] - lo_all[1], hi_all[2] - lo_all[2]));
  for (size_t t = 0; t < slaves.size(); ++t) {
    const FaceRecord& f = slaves[t];
    const Point3 n = unit_normal(f.corners);
    Point3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
    for (const Point3& p : f.corners)
      for (const double side : {-reach, reach})
        for (size_t d = 0; d < 3; ++d)
          lo[d] = std::min({lo[d], p[d], p[d] + side * n[d]}), hi[d] = std::max({hi[d], p[d], p[d] + side * n[d]});
    grid.for_each_in_box(lo, hi, [&](const FaceRecord& m) {
      if (m.body == f.body || dot(unit_normal(m.corners), n) >= 0) return;  // only masters facing the slave
      const MortarIntegrals in = integrate_mortar_pair(f.corners, m.corners);
      if (!(in.area > 0)) return;
      const double mean_gap = dot(sum(in.G), n) / in.area;
      if (std::abs(mean_gap) > contact.search_distance) return;
      for (size_t c = 0; c < 3; ++c) {
        MortarRow& row = pending[face_nodes[t][c]];
        for (size_t k = 0; k < 3; ++k) {
          row.slave[corner_dofs(f, k)] += in.D[c][k];
          row.master[corner_dofs(m, k)] += in.M[c][k];
          row.weight += in.D[c][k];
        }
        for (size_t d = 0; d < 3; ++d) row.gap[d] += in.G[c][d];
      }
    });
  }

  for (size_t j = 0; j < nodes.size(); ++j) {
    const MortarRow& pending_row = pending[j];
    const double norm = std::sqrt(dot(pending_row.normal_sum, pending_row.normal_sum));
    // A node whose faces no master covers (to rounding) has no row: no contact possible.
    if (!(pending_row.weight > 1e-9 * norm)) continue;
    const Point3 nu{-pending_row.normal_sum[0] / norm, -pending_row.normal_sum[1] / norm,
                    -pending_row.normal_sum[2] / norm};
    const SlaveNode& node = nodes[j];
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::mortar;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    geometry.s = {node.x_dof->x, node.x_dof->y};
    Row row{{}, dot(nu, pending_row.gap) / pending_row.weight + node.x_dof->gap, RowKind::contact, false, geometry,
            -1, node.x_dof->friction};
    for (const auto& [terms, sign] : {std::pair{&pending_row.slave, -1.0}, std::pair{&pending_row.master, 1.0}})
      for (const auto& [dofs, integral] : *terms)
        for (size_t i = 0; i < 3; ++i)
          if (nu[i] != 0 && integral != 0)
            row.entries.push_back({dofs[0], dofs[1 + i], sign * integral / pending_row.weight * nu[i]});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
