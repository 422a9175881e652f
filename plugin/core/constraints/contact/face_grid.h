// Contact faces (triangles, three dimensions) bucketed in a uniform grid, so that the faces
// near a point or a box are found in time independent of the number of faces: node-to-face
// contact asks for the nearest face of each slave node, mortar contact for the faces that
// may overlap each slave face.
#pragma once

#include "constraints/constraint_records.h"
#include "constraints/contact/contact_linearization.h"

#include <array>
#include <functional>
#include <vector>

namespace ffeti {

class FaceGrid {
 public:
  /// Cells about the mean face size, at most 256 per side. `faces` must outlive the grid.
  explicit FaceGrid(const std::vector<FaceRecord>& faces);

  /// The face of a body other than `body` nearest to s, closer than `reach`; of equally near
  /// ones the smallest (subdomain, dofs), independent of the ranks' order. nullptr if none.
  /// `distance` (if given) receives its distance to s.
  const FaceRecord* nearest(const Point3& s, int body, double reach, double* distance = nullptr) const;

  /// Calls `visit` once for each face whose box meets the box [lo, hi] (face indices in
  /// increasing order, so that sums over them do not depend on the cells' order).
  void for_each_in_box(const Point3& lo, const Point3& hi, const std::function<void(const FaceRecord&)>& visit) const;

 private:
  int index_of(double v, size_t axis) const;
  size_t flat(int x, int y, int z) const;

  const std::vector<FaceRecord>& faces_;
  Point3 lo_{};
  double cell_ = 1;
  std::array<int, 3> count_{};
  std::vector<std::vector<int>> cells_;
};

}  // namespace ffeti
