#include "constraints/contact/node_to_segment.h"

#include "constraints/constraint_rows.h"
#include "constraints/input_checks.h"

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

Point moved(const Point& p, const Point3& velocity, double t) { return {p[0] + t * velocity[0], p[1] + t * velocity[1]}; }

}  // namespace

const ListInput* NodeToSegment::list_input() const {
  static const ListInput spec{"contactSegments", 4, "4 dofs per segment (a_x, a_y, b_x, b_y)", "master", 2,
                              MeshEntries::segments};
  return &spec;
}

void NodeToSegment::read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                              ContactInput& contact) const {
  contact.input_of<NodeToSegmentInput>().segments = list_entries<4>(*list_input(), lists, ids);
}

void NodeToSegment::check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                                  const ContactInput& contact, int dimension) const {
  const auto& segments = contact.input_of<NodeToSegmentInput>().segments;
  if (any_entry(segments)) require(kind(), Feature::rows, dimension, list_input()->argument);
  check_entry_dofs(segments, ids, subdomains, list_input()->argument);
}

RowAt NodeToSegmentGeometry::row_at(const NodeMotion& v, double t) const {
  const LinearizedRow r = node_to_segment_row(moved(s, v[0], t), moved(a, v[1], t), moved(b, v[2], t), false);
  return {dofs(), {r.coefficients.begin(), r.coefficients.end()}, r.gap};
}

double NodeToSegmentGeometry::length() const { return std::hypot(b[0] - a[0], b[1] - a[1]); }

Point3 NodeToSegmentGeometry::normal() const {
  const double l = length();
  return {(b[1] - a[1]) / l, -(b[0] - a[0]) / l, 0.0};  // as node_to_segment_row's
}

std::vector<RowAt> NodeToSegmentGeometry::slip_rows() const {
  const LinearizedRow slip = node_to_segment_slip(s, a, b);
  return {{dofs(), {slip.coefficients.begin(), slip.coefficients.end()}, slip.gap}};
}

void NodeToSegment::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  const SegmentGrid grid(in.segments);
  for (const SlaveNode& node : slave_nodes(in.records, in.snap)) {
    const double sx = node.x_dof->x, sy = node.x_dof->y;
    const SegmentRecord* best = grid.nearest(sx, sy, node.x_dof->body, in.contact.search_distance);
    // No master segment within reach: no row, but a slave over a segment beyond it is
    // watched for penetration after the solve, as in node to face.
    const bool beyond_reach = !best && std::isfinite(in.contact.search_distance);
    if (beyond_reach) best = grid.nearest(sx, sy, node.x_dof->body, INFINITY);
    if (!best) continue;
    if (beyond_reach) {
      const double dx = best->bx - best->ax, dy = best->by - best->ay;
      const double xi = ((sx - best->ax) * dx + (sy - best->ay) * dy) / (dx * dx + dy * dy);
      if (xi < -1e-9 || xi > 1 + 1e-9) continue;
    }
    std::array<DofRef, 4> master;
    for (size_t k = 0; k < 4; ++k) master[k] = {best->subdomain, best->dofs[k]};
    const auto geometry = std::make_shared<const NodeToSegmentGeometry>(
        std::array<DofRef, 2>{{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}},
        master, Point{sx, sy}, Point{best->ax, best->ay}, Point{best->bx, best->by});
    const LinearizedRow linear = node_to_segment_row(geometry->s, geometry->a, geometry->b);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->law_value, beyond_reach};
    if (beyond_reach && row.rhs < 0) continue;  // behind the segment from the start
    const std::vector<DofRef> dofs = geometry->dofs();
    for (size_t k = 0; k < 6; ++k)
      if (linear.coefficients[k] != 0) row.entries.push_back({dofs[k][0], dofs[k][1], linear.coefficients[k]});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
