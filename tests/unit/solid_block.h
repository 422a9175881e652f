// A P1 elastic block of tetrahedra for the 3D tests: the element stiffness written out
// independently of the plugin (which takes K as given), and a structured block whose top
// face is moved rigidly.
#pragma once

#include "constraints/problem_input.h"

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace ffeti {

/// P1 elasticity of one tetrahedron, dofs 3k + c: its kernel is the six rigid motions.
Eigen::MatrixXd tetrahedron_stiffness(const std::array<Eigen::Vector3d, 4>& p, double young = 1, double poisson = 0.3);

/// The box [x0, x0 + size_x] x [0, size_y] x [0, size_z] cut into cells[0] x cells[1] x
/// cells[2] cubes of six tetrahedra each (Kuhn's, conforming between cubes), E = 1000,
/// nu = 0.3, dofs 3k + c of node k (x fastest, then y, then z), then turned by `turn`
/// radians about the z axis. The top face (z = size_z) is fixed at `top` (a displacement,
/// turned as well); no load.
SubdomainInput solid_block(double x0, const std::array<double, 3>& size, const std::array<int, 3>& cells,
                           const std::array<double, 3>& top, double turn = 0);

/// The stiffness of the unit cube solid_block(x0, ...) of cells^3 cubes with its top face's
/// dofs eliminated, compressed: a positive definite 3D elasticity matrix for factor tests.
SparseMatrix clamped_block_stiffness(int cells, double x0 = 0);

/// Per subdomain every dof of the nodes on the face z = 0 (contact slaves).
std::vector<std::vector<int>> bottom_dofs(const std::vector<SubdomainInput>& subdomains);

}  // namespace ffeti
