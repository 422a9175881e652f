// The integrals of mortar contact over the overlap of one slave and one master triangle
// (three dimensions, linear faces). Node-to-face rows pass a slave's force to the master
// nodes by its projection's weights, which are not the master mesh's consistent loads of a
// pressure: a uniform pressure across a non-matching interface comes out uneven. Mortar
// rows weight the gap with the slave's shape functions, integrated over the overlap, and
// pass a uniform pressure exactly (the patch test).
#pragma once

#include "feti/contact_linearization.h"

#include <array>

namespace ffeti {

using Triangle3 = std::array<Point3, 3>;

/// Over the part of the slave triangle that the master triangle covers, the master
/// projected on the slave's plane along the slave's unit normal (corners ordered so that
/// (b - a) x (c - a) points out of the slave's body), with phi the slave's and psi the
/// master's linear shape functions and x_m(x) the master point that projects on x:
/// D[j][k] = int phi_j phi_k, M[j][m] = int phi_j psi_m, G[j] = int phi_j (x - x_m(x)),
/// area = int 1. The integrands are at most quadratic, so the 3-point rule on a fan of the
/// overlap polygon is exact. All zero where the triangles do not overlap or the master
/// stands edge-on to the slave's plane.
struct MortarIntegrals {
  std::array<std::array<double, 3>, 3> D{}, M{};
  std::array<Point3, 3> G{};
  double area = 0;
};
MortarIntegrals integrate_mortar_pair(const Triangle3& slave, const Triangle3& master);

}  // namespace ffeti
