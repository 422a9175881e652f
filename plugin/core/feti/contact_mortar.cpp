// Mortar contact rows (three dimensions): one row per slave node, its normal gap weighted by
// its shape function over the slave faces that master faces cover (ContactInput::slave_faces).
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

/// One slave node's row in the making: int phi_j n.(u_m - u_s) <= int phi_j n.(x_s - x_m)
/// summed over the (slave face, master face) pairs, n each master face's normal.
struct MortarRow {
  std::map<std::pair<int, int>, double> coefficients;  ///< per (subdomain, dof)
  double gap = 0;
  double weight = 0;  ///< int phi_j over the covered part
};

double dot(const Point3& p, const Point3& q) { return p[0] * q[0] + p[1] * q[1] + p[2] * q[2]; }

Point3 unit_normal(const Triangle3& t) {
  Point3 n{};
  for (size_t d = 0; d < 3; ++d) {
    const size_t d1 = (d + 1) % 3, d2 = (d + 2) % 3;
    n[d] = (t[1][d1] - t[0][d1]) * (t[2][d2] - t[0][d2]) - (t[1][d2] - t[0][d2]) * (t[2][d1] - t[0][d1]);
  }
  const double length = std::sqrt(dot(n, n));
  return {n[0] / length, n[1] / length, n[2] / length};
}

bool by_identity(const FaceRecord& a, const FaceRecord& b) {
  return std::tie(a.subdomain, a.dofs) < std::tie(b.subdomain, b.dofs);
}

/// Adds one (slave face, master face) pair's integrals to the rows of the slave's corners.
void add_pair(const FaceRecord& slave, const FaceRecord& master, const MortarIntegrals& in,
              const std::array<size_t, 3>& corner_rows, std::vector<MortarRow>& pending) {
  const Point3& n = in.normal;
  for (size_t j = 0; j < 3; ++j) {
    MortarRow& row = pending[corner_rows[j]];
    for (size_t k = 0; k < 3; ++k) {
      row.weight += in.D[j][k];
      for (size_t i = 0; i < 3; ++i) {
        row.coefficients[{slave.subdomain, slave.dofs[3 * k + i]}] -= in.D[j][k] * n[i];
        row.coefficients[{master.subdomain, master.dofs[3 * k + i]}] += in.M[j][k] * n[i];
      }
    }
    row.gap += dot(n, in.G[j]);
  }
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

  // The master faces a slave face may see lie in the prism it sweeps along its normal
  // within the search distance (no farther than the diagonal of all contact faces).
  Point3 lo_all{INFINITY, INFINITY, INFINITY}, hi_all{-INFINITY, -INFINITY, -INFINITY};
  for (const FaceRecord& f : faces)
    for (const Point3& p : f.corners)
      for (size_t d = 0; d < 3; ++d) lo_all[d] = std::min(lo_all[d], p[d]), hi_all[d] = std::max(hi_all[d], p[d]);
  const double reach =
      std::min(contact.search_distance, std::hypot(hi_all[0] - lo_all[0], hi_all[1] - lo_all[1], hi_all[2] - lo_all[2]));
  std::vector<MortarRow> pending(nodes.size());
  for (const FaceRecord& f : slaves) {
    std::array<size_t, 3> corner_rows{};
    for (size_t c = 0; c < 3; ++c) corner_rows[c] = node_at.at(key(f.body, f.corners[c]));  // corners are slave dofs
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
      double gap = 0;
      for (const Point3& g : in.G) gap += dot(in.normal, g);
      if (std::abs(gap / in.area) > contact.search_distance) return;  // its mean normal gap
      add_pair(f, m, in, corner_rows, pending);
    });
  }

  for (size_t j = 0; j < nodes.size(); ++j) {
    const MortarRow& pending_row = pending[j];
    if (!(pending_row.weight > 0)) continue;  // no master covers its faces: no contact possible
    const SlaveNode& node = nodes[j];
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::mortar;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    geometry.s = {node.x_dof->x, node.x_dof->y};
    // Divided by int phi_j, so that the multiplier is a force like the other rows'.
    Row row{{}, pending_row.gap / pending_row.weight + node.x_dof->gap, RowKind::contact, false, geometry,
            -1, node.x_dof->friction};
    for (const auto& [dof, coefficient] : pending_row.coefficients)
      if (coefficient != 0) row.entries.push_back({dof.first, dof.second, coefficient / pending_row.weight});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
