// A test mesh: the unit box cut into n x n x n cubes of six tetrahedra each (Kuhn's
// subdivision), used by the mesh utilities' tests.
#pragma once

#include <vector>

namespace ffeti {

/// The n x n x n cubes of the unit box, each cut into the six tetrahedra around its main
/// diagonal (one per order of the axes), listed so that tetrahedra 6c + t and 6c + t + 1
/// (mod 6) of cube c share a face and any other two of the cube share only the diagonal.
/// Conforming across cubes: every cube's diagonal runs the same way.
std::vector<int> kuhn_box(int n);

}  // namespace ffeti
