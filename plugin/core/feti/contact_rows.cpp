// The contact rows of the slave nodes (both dofs of each): against the nearest master
// segment of another body or against the rigid obstacle.
#include "feti/constraint_rows.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace ffeti {
namespace {

/// Master segments bucketed in a uniform grid (cells about the mean segment length), so that
/// the nearest segment of a slave is found ring by ring around its cell, in time independent
/// of the number of segments, instead of testing every segment.
class SegmentGrid {
 public:
  explicit SegmentGrid(const std::vector<SegmentRecord>& segments) : segments_(segments) {
    double length = 0;
    lo_x_ = lo_y_ = INFINITY;
    double hi_x = -INFINITY, hi_y = -INFINITY;
    for (const SegmentRecord& seg : segments) {
      length += std::hypot(seg.bx - seg.ax, seg.by - seg.ay);
      lo_x_ = std::min({lo_x_, seg.ax, seg.bx}), hi_x = std::max({hi_x, seg.ax, seg.bx});
      lo_y_ = std::min({lo_y_, seg.ay, seg.by}), hi_y = std::max({hi_y, seg.ay, seg.by});
    }
    constexpr double kMaxCellsPerSide = 2048;
    cell_ = std::max({length / static_cast<double>(segments.size()), (hi_x - lo_x_) / kMaxCellsPerSide,
                      (hi_y - lo_y_) / kMaxCellsPerSide, 1e-300});
    nx_ = static_cast<int>((hi_x - lo_x_) / cell_) + 1, ny_ = static_cast<int>((hi_y - lo_y_) / cell_) + 1;
    cells_.resize(static_cast<size_t>(nx_) * static_cast<size_t>(ny_));
    for (size_t k = 0; k < segments.size(); ++k) {
      const SegmentRecord& seg = segments[k];
      for (int j = cell_y(std::min(seg.ay, seg.by)); j <= cell_y(std::max(seg.ay, seg.by)); ++j)
        for (int i = cell_x(std::min(seg.ax, seg.bx)); i <= cell_x(std::max(seg.ax, seg.bx)); ++i)
          cells_[index(i, j)].push_back(static_cast<int>(k));
    }
  }

  /// The segment of a body other than `body` nearest to (x, y), closer than `reach`; of
  /// equally near ones the smallest (subdomain, dofs), so that the choice does not depend
  /// on the order of the segments (which follows the ranks). nullptr if there is none.
  const SegmentRecord* nearest(double x, double y, int body, double reach) const {
    const SegmentRecord* best = nullptr;
    double best_distance = reach;
    const auto visit = [&](int i, int j) {
      if (i < 0 || j < 0 || i >= nx_ || j >= ny_) return;
      for (int k : cells_[index(i, j)]) {
        const SegmentRecord& seg = segments_[static_cast<size_t>(k)];
        if (seg.body == body) continue;
        const double dx = seg.bx - seg.ax, dy = seg.by - seg.ay, length_sq = dx * dx + dy * dy;
        const double xi = std::clamp(((x - seg.ax) * dx + (y - seg.ay) * dy) / length_sq, 0.0, 1.0);
        const double distance = std::hypot(x - (seg.ax + xi * dx), y - (seg.ay + xi * dy));
        if (distance < best_distance ||
            (best && distance == best_distance && std::tie(seg.subdomain, seg.dofs) < std::tie(best->subdomain, best->dofs)))
          best = &seg, best_distance = distance;
      }
    };
    // The cells at Chebyshev distance r from the point's (clamped) cell, ring after ring:
    // those of ring r lie at least (r - 1) cells from the point.
    const int ci = cell_x(x), cj = cell_y(y);
    for (int r = 0; r <= std::max(nx_, ny_) && (r - 1) * cell_ <= best_distance; ++r) {
      if (r == 0) {
        visit(ci, cj);
        continue;
      }
      for (int i = std::max(ci - r, 0); i <= std::min(ci + r, nx_ - 1); ++i) visit(i, cj - r), visit(i, cj + r);
      for (int j = std::max(cj - r + 1, 0); j <= std::min(cj + r - 1, ny_ - 1); ++j) visit(ci - r, j), visit(ci + r, j);
    }
    return best;
  }

 private:
  int cell_x(double x) const { return std::clamp(static_cast<int>(std::floor((x - lo_x_) / cell_)), 0, nx_ - 1); }
  int cell_y(double y) const { return std::clamp(static_cast<int>(std::floor((y - lo_y_) / cell_)), 0, ny_ - 1); }
  size_t index(int i, int j) const { return static_cast<size_t>(j) * static_cast<size_t>(nx_) + static_cast<size_t>(i); }

  const std::vector<SegmentRecord>& segments_;
  double lo_x_, lo_y_, cell_;
  int nx_, ny_;
  std::vector<std::vector<int>> cells_;
};

}  // namespace

void add_node_to_segment_rows(const std::vector<DofRecord>& records, const std::vector<SegmentRecord>& segments,
                              const ContactInput& contact, double snap, std::vector<Row>& rows) {
  const SegmentGrid grid(segments);
  for (const SlaveNode& node : slave_nodes(records, snap)) {
    const double sx = node.x_dof->x, sy = node.x_dof->y;
    const SegmentRecord* best = grid.nearest(sx, sy, node.x_dof->body, contact.search_distance);
    if (!best) continue;  // no master segment within reach: no contact possible here
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::node_to_segment;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    for (size_t k = 0; k < 4; ++k) geometry.master[k] = {best->subdomain, best->dofs[k]};
    geometry.s = {sx, sy}, geometry.a = {best->ax, best->ay}, geometry.b = {best->bx, best->by};
    const LinearizedRow linear = node_to_segment_row(geometry.s, geometry.a, geometry.b);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->friction};
    const std::array<int, 2> dofs[6] = {geometry.slave[0], geometry.slave[1], geometry.master[0],
                                        geometry.master[1], geometry.master[2], geometry.master[3]};
    for (size_t k = 0; k < 6; ++k)
      if (linear.coefficients[k] != 0) row.entries.push_back({dofs[k][0], dofs[k][1], linear.coefficients[k]});
    rows.push_back(std::move(row));
  }
}

namespace {

/// A rigid ball: each slave node against the tangent plane at its nearest point.
void add_ball_rows(const std::vector<DofRecord>& records, const ContactInput& contact, double snap,
                   std::vector<Row>& rows) {
  const Point3& c = contact.obstacle_point;
  for (const SlaveNode& node : slave_nodes(records, snap, contact.three_d ? 3 : 2)) {
    const Point3 s{node.x_dof->x, node.x_dof->y, node.x_dof->z};
    const double distance = std::hypot(s[0] - c[0], s[1] - c[1], s[2] - c[2]);
    if (!(distance > 1e-12 * contact.obstacle_radius))
      throw InputError("obstacleBall: the slave node at (" + std::to_string(s[0]) + ", " + std::to_string(s[1]) + ", " +
                       std::to_string(s[2]) + ") is the ball's centre: it has no normal");
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::ball;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    if (contact.three_d) geometry.slave_z = {node.z_dof->subdomain, node.z_dof->dof};
    geometry.s = {s[0], s[1]};
    geometry.s3 = s;
    geometry.corners[0] = c;
    geometry.corners[1] = {contact.obstacle_radius, 0, 0};
    Row row{{}, distance - contact.obstacle_radius + node.x_dof->gap, RowKind::contact, false, geometry, -1,
            node.x_dof->friction};
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    for (size_t k = 0; k < (contact.three_d ? 3u : 2u); ++k)
      if (s[k] != c[k]) row.entries.push_back({slave[k]->subdomain, slave[k]->dof, -(s[k] - c[k]) / distance});
    rows.push_back(std::move(row));
  }
}

}  // namespace

void add_obstacle_rows(const std::vector<DofRecord>& records, const ContactInput& contact, double snap,
                       std::vector<Row>& rows) {
  if (contact.obstacle_radius > 0) return add_ball_rows(records, contact, snap, rows);
  const auto& normal = contact.obstacle_normal;
  const double norm = contact.three_d ? std::hypot(normal[0], normal[1], normal[2]) : std::hypot(normal[0], normal[1]);
  if (!(norm > 0)) throw InputError("obstacle: the normal must not be zero");
  const Point3 n{normal[0] / norm, normal[1] / norm, normal[2] / norm};
  for (const SlaveNode& node : slave_nodes(records, snap, contact.three_d ? 3 : 2)) {
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::obstacle;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    geometry.s = {node.x_dof->x, node.x_dof->y};
    geometry.a = {contact.obstacle_point[0], contact.obstacle_point[1]}, geometry.b = {n[0], n[1]};
    // -n.u_s <= n.(s - point): in the plane the row the sensitivity analysis differentiates,
    // in 3D the same with z.
    LinearizedRow linear = obstacle_row(geometry.s, geometry.a, geometry.b);
    if (contact.three_d) {
      linear.coefficients[2] = -n[2];
      linear.gap += n[2] * (node.x_dof->z - contact.obstacle_point[2]);
      geometry.slave_z = {node.z_dof->subdomain, node.z_dof->dof};
      geometry.s3 = {node.x_dof->x, node.x_dof->y, node.x_dof->z};
      geometry.corners[0] = contact.obstacle_point;
      geometry.corners[1] = n;
    }
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->friction};
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    for (size_t k = 0; k < (contact.three_d ? 3u : 2u); ++k)
      if (linear.coefficients[k] != 0) row.entries.push_back({slave[k]->subdomain, slave[k]->dof, linear.coefficients[k]});
    rows.push_back(std::move(row));
  }
}

void add_friction_rows(const std::vector<DofRecord>& records, std::vector<Row>& rows) {
  const size_t count = rows.size();
  for (size_t i = 0; i < count; ++i) {
    if (rows[i].kind != RowKind::contact) continue;
    const ContactRowGeometry& g = rows[i].geometry;
    const bool on_segment = g.kind == ContactRowGeometry::Kind::node_to_segment;
    const LinearizedRow slip = on_segment ? node_to_segment_slip(g.s, g.a, g.b) : obstacle_slip(g.b);
    const std::array<int, 2> dofs[6] = {g.slave[0], g.slave[1], g.master[0], g.master[1], g.master[2], g.master[3]};
    Row row{{}, 0.0, RowKind::friction, false, g, static_cast<int>(i), rows[i].friction};
    for (size_t k = 0; k < (on_segment ? 6u : 2u); ++k) {
      if (slip.coefficients[k] == 0) continue;
      // A fixed dof leaves the row, its prescribed motion moving to the right-hand side
      // (it is there from the first load step on and adds nothing to later increments). In
      // Total FETI too: its Dirichlet row already holds it, and a row on it alone would
      // repeat that row (B would lose full rank).
      if (const DofRecord* fixed = fixed_record(records, dofs[k][0], dofs[k][1]))
        row.rhs -= slip.coefficients[k] * fixed->value;
      else
        row.entries.push_back({dofs[k][0], dofs[k][1], slip.coefficients[k]});
    }
    if (!row.entries.empty()) rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
