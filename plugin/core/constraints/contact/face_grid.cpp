#include "constraints/contact/face_grid.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace ffeti {
namespace {

double squared_distance(const Point3& p, const Point3& q) { return dot(minus(p, q), minus(p, q)); }

}  // namespace

FaceGrid::FaceGrid(const std::vector<FaceRecord>& faces) : faces_(faces) {
  lo_.fill(INFINITY);
  Point3 hi{-INFINITY, -INFINITY, -INFINITY};
  double size = 0;
  for (const FaceRecord& f : faces) {
    for (const Point3& p : f.corners)
      for (size_t i = 0; i < 3; ++i) lo_[i] = std::min(lo_[i], p[i]), hi[i] = std::max(hi[i], p[i]);
    size += std::sqrt(squared_distance(f.corners[0], f.corners[1]));
  }
  if (faces.empty()) lo_.fill(0), hi.fill(0);
  constexpr double kMaxCellsPerSide = 256;
  cell_ = size / static_cast<double>(std::max<size_t>(faces.size(), 1));
  for (size_t i = 0; i < 3; ++i) cell_ = std::max(cell_, (hi[i] - lo_[i]) / kMaxCellsPerSide);
  cell_ = std::max(cell_, 1e-300);
  // At most about 8 cells per face: faces spread over a box's volume (a sphere's surface)
  // would otherwise fill up to 257^3 cells, most of them empty.
  const auto cells = [&] {
    double product = 1;
    for (size_t i = 0; i < 3; ++i) product *= std::floor((hi[i] - lo_[i]) / cell_) + 1;
    return product;
  };
  while (cells() > 8.0 * static_cast<double>(faces.size()) + 64) cell_ *= 1.25;
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

const FaceRecord* FaceGrid::nearest(const Point3& s, int body, double reach, double* distance) const {
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
  if (distance) *distance = best_distance;
  return best;
}

void FaceGrid::for_each_in_box(const Point3& lo, const Point3& hi,
                               const std::function<void(const FaceRecord&)>& visit) const {
  std::array<int, 3> from{}, to{};
  for (size_t i = 0; i < 3; ++i) from[i] = index_of(lo[i], i), to[i] = index_of(hi[i], i);
  std::vector<int> found;
  for (int z = from[2]; z <= to[2]; ++z)
    for (int y = from[1]; y <= to[1]; ++y)
      for (int x = from[0]; x <= to[0]; ++x) {
        const auto& cell = cells_[flat(x, y, z)];
        found.insert(found.end(), cell.begin(), cell.end());
      }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  for (int k : found) {
    const FaceRecord& f = faces_[static_cast<size_t>(k)];
    bool meets = true;
    for (size_t i = 0; i < 3 && meets; ++i) {
      const double low = std::min({f.corners[0][i], f.corners[1][i], f.corners[2][i]});
      const double high = std::max({f.corners[0][i], f.corners[1][i], f.corners[2][i]});
      meets = low <= hi[i] && high >= lo[i];
    }
    if (meets) visit(f);
  }
}

int FaceGrid::index_of(double v, size_t axis) const {
  // Clamped before the conversion: a point far from small faces would overflow an int.
  const double cell = std::floor((v - lo_[axis]) / cell_);
  return static_cast<int>(std::clamp(cell, 0.0, static_cast<double>(count_[axis] - 1)));
}

size_t FaceGrid::flat(int x, int y, int z) const {
  return (static_cast<size_t>(z) * static_cast<size_t>(count_[1]) + static_cast<size_t>(y)) *
             static_cast<size_t>(count_[0]) + static_cast<size_t>(x);
}

}  // namespace ffeti
