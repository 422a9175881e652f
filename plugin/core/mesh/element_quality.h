// The one definition of a flat element, shared by both front ends: ffeti-solve checks the
// gmsh cells it reads, and ffeti.idp's ffetiCheckMesh3 and ffetiCheckMesh (through
// fetiFlatTetrahedron() and fetiFlatTriangle()) the FreeFEM meshes it splits or reads
// coordinates from. fetiSetup sees matrices, not elements, and cannot check it.
#pragma once

#include <array>

namespace ffeti {

/// |volume| / (longest edge)^3: a regular tetrahedron has 1/(6 sqrt 2) = 0.118, cube()'s
/// 0.032, the Hertz sphere's gmsh mesh at h = 0.1 at least 0.009, the sphere-on-block
/// example's (meshes/sphere-block.geo) 0.013. Zero for a degenerate one.
double tetrahedron_flatness(const std::array<std::array<double, 3>, 4>& corners);

/// Below this a tetrahedron is flat: its four vertices nearly in a plane (FreeFEM refuses
/// exactly coplanar ones when it reads a mesh, not nearly coplanar ones), its P1 stiffness
/// of order L^4 / V swamps the rest of the matrix and the answer means nothing.
constexpr double kFlatTetrahedron = 1e-6;

/// |area| / (longest edge)^2 of a triangle in space (a plane mesh has z = 0): a regular
/// triangle has sqrt(3) / 4 = 0.433, square()'s halves 0.25. Zero for a degenerate one.
double triangle_flatness(const std::array<std::array<double, 3>, 3>& corners);

/// Below this a triangle is flat: its three vertices nearly on a line (FreeFEM refuses
/// exactly collinear ones when it reads a mesh, not nearly collinear ones; a mesh moved by a
/// design step makes them), its P1 stiffness of order L^2 / A swamps the rest.
constexpr double kFlatTriangle = 1e-6;

}  // namespace ffeti
