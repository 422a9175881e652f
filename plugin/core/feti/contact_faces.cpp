// Node-to-face contact rows (three dimensions): each slave node against the nearest master
// triangle of another body, found through a uniform grid of the faces' boxes.
#include "feti/constraint_rows.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace ffeti {
namespace {

double squared_distance(const Point3& p, const Point3& q) {
  return (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]);
}

/// Master faces bucketed in a uniform grid (cells about the mean face size, at most 256 per
/// side): the nearest face of a slave is found shell by shell around its cell.
class FaceGrid {
 public:
  explicit FaceGrid(const std::vector<FaceRecord>& faces) : faces_(faces) {
    lo_.fill(INFINITY);
    Point3 hi{-INFINITY, -INFINITY, -INFINITY};
    double size = 0;
    for (const FaceRecord& f : faces) {
      for (const Point3& p : f.corners)
        for (size_t i = 0; i < 3; ++i) lo_[i] = std::min(lo_[i], p[i]), hi[i] = std::max(hi[i], p[i]);
      size += std::sqrt(squared_distance(f.corners[0], f.corners[1]));
    }
    constexpr double kMaxCellsPerSide = 256;
    cell_ = size / static_cast<double>(std::max<size_t>(faces.size(), 1));
    for (size_t i = 0; i < 3; ++i) cell_ = std::max(cell_, (hi[i] - lo_[i]) / kMaxCellsPerSide);
    cell_ = std::max(cell_, 1e-300);
    for (size_t i = 0; i < 3; ++i) count_[i] = static_cast<int>((hi[i] - lo_[i]) / cell_) + 1;
    cells_.resize(static_cast<size_t>(count_[0]) * static_cast<size_t>(count_[1]) * static_cast<size_t>(count_[2]));
    for (size_t k = 0; k < faces.size(); ++k) {
      std::array<int, 3> from{}, to{};
      for (size_t i = 0; i < 3; ++i) {
        double low = INFINITY, high = -INFINITY;
        for (const Point3& p : faces[k].corners) low = std::min(low, p[i]), high = std::max(high, p[i]);
        from[i] = index_of(low, i), to[i] = index_of(high, i);
      }
      for (int z = from[2]; z <= to[2]; ++z)
        for (int y = from[1]; y <= to[1]; ++y)
          for (int x = from[0]; x <= to[0]; ++x) cells_[flat(x, y, z)].push_back(static_cast<int>(k));
    }
  }

  /// The face of a body other than `body` nearest to s, closer than `reach`; of equally near
  /// ones the smallest (subdomain, dofs), independent of the ranks' order. nullptr if none.
  const FaceRecord* nearest(const Point3& s, int body, double reach) const {
    const FaceRecord* best = nullptr;
    double best_distance = reach;
    const auto visit = [&](int x, int y, int z) {
      if (x < 0 || y < 0 || z < 0 || x >= count_[0] || y >= count_[1] || z >= count_[2]) return;
      for (int k : cells_[flat(x, y, z)]) {
        const FaceRecord& f = faces_[static_cast<size_t>(k)];
        if (f.body == body) continue;
        const std::array<double, 3> w = closest_point_weights(s, f.corners[0], f.corners[1], f.corners[2]);
        Point3 p{};
        for (size_t i = 0; i < 3; ++i) p[i] = w[0] * f.corners[0][i] + w[1] * f.corners[1][i] + w[2] * f.corners[2][i];
        const double distance = std::sqrt(squared_distance(s, p));
        if (distance < best_distance ||
            (best && distance == best_distance && std::tie(f.subdomain, f.dofs) < std::tie(best->subdomain, best->dofs)))
          best = &f, best_distance = distance;
      }
    };
    // Shells of cells at Chebyshev distance r from the point's (clamped) cell: those of shell
    // r lie at least (r - 1) cells from the point.
    const int cx = index_of(s[0], 0), cy = index_of(s[1], 1), cz = index_of(s[2], 2);
    const int most = std::max({count_[0], count_[1], count_[2]});
    for (int r = 0; r <= most && (r - 1) * cell_ <= best_distance; ++r)
      for (int z = cz - r; z <= cz + r; ++z)
        for (int y = cy - r; y <= cy + r; ++y)
          for (int x = cx - r; x <= cx + r; ++x)
            if (std::max({std::abs(x - cx), std::abs(y - cy), std::abs(z - cz)}) == r) visit(x, y, z);
    return best;
  }

 private:
  int index_of(double v, size_t axis) const {
    return std::clamp(static_cast<int>(std::floor((v - lo_[axis]) / cell_)), 0, count_[axis] - 1);
  }
  size_t flat(int x, int y, int z) const {
    return (static_cast<size_t>(z) * static_cast<size_t>(count_[1]) + static_cast<size_t>(y)) *
               static_cast<size_t>(count_[0]) + static_cast<size_t>(x);
  }

  const std::vector<FaceRecord>& faces_;
  Point3 lo_{};
  double cell_ = 1;
  std::array<int, 3> count_{};
  std::vector<std::vector<int>> cells_;
};

}  // namespace

void add_node_to_face_rows(const std::vector<DofRecord>& records, const std::vector<FaceRecord>& faces,
                           const ContactInput& contact, double snap, std::vector<Row>& rows) {
  const FaceGrid grid(faces);
  for (const SlaveNode& node : slave_nodes(records, snap, 3)) {
    const Point3 s{node.x_dof->x, node.x_dof->y, node.x_dof->z};
    const FaceRecord* face = grid.nearest(s, node.x_dof->body, contact.search_distance);
    if (!face) continue;  // no master face within reach: no contact possible here
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::node_to_face;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    geometry.s = {s[0], s[1]};
    const LinearizedFaceRow linear = node_to_face_row(s, face->corners[0], face->corners[1], face->corners[2]);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->friction};
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    for (size_t i = 0; i < 3; ++i)
      if (linear.coefficients[i] != 0) row.entries.push_back({slave[i]->subdomain, slave[i]->dof, linear.coefficients[i]});
    for (size_t k = 0; k < 9; ++k)
      if (linear.coefficients[3 + k] != 0) row.entries.push_back({face->subdomain, face->dofs[k], linear.coefficients[3 + k]});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
