// The integrals of mortar contact over the overlap of one slave and one master triangle
// (three dimensions, linear faces). Node-to-face rows pass a slave's force to the master
// nodes by its projection's weights, which are not the master mesh's consistent loads of a
// pressure: a uniform pressure across a non-matching interface comes out uneven. Mortar
// rows weight the gap with the slave's shape functions, integrated over the overlap, and
// pass a uniform pressure exactly (the patch test).
#pragma once

#include "constraints/contact/contact_linearization.h"

#include <array>

namespace ffeti {

using Triangle3 = std::array<Point3, 3>;

/// Over the overlap of the master triangle and the slave triangle projected on the master's
/// plane along the master's unit normal n (both ordered so that (b - a) x (c - a) points
/// out of their body), integrated on that plane, with phi the slave's and psi the master's
/// linear shape functions, x_s(x) the slave point and x_m(x) the master point over x:
/// D[j][k] = int phi_j phi_k, M[j][m] = int phi_j psi_m, G[j] = int phi_j (x_s - x_m),
/// area = int 1, normal = n (n.G[j] weights the normal gap). The gap and the contact force
/// are the master's normal ones, as on a rigid plane: a curved slave on a flat master
/// gets no tangential force. The integrands are at most quadratic, so the 3-point rule on
/// a fan of the overlap polygon is exact. All zero where the triangles do not overlap or
/// the slave stands edge-on to the master's plane.
struct MortarIntegrals {
  std::array<std::array<double, 3>, 3> D{}, M{};
  std::array<Point3, 3> G{};
  double area = 0;
  Point3 normal{};
};
MortarIntegrals integrate_mortar_pair(const Triangle3& slave, const Triangle3& master);

}  // namespace ffeti
