// Kernels (null spaces) of subdomain stiffness matrices.
#pragma once

#include "factor/cholmod_factor.h"

#include <Eigen/Dense>

#include <vector>

namespace ffeti {

/// Candidate kernel from geometry: for a scalar field (every component 0) the constants;
/// for 2D vector fields (components 0 and 1) the three rigid modes (1,0), (0,1), (-y,x);
/// with z (3D vector fields, components 0..2) the three translations and the three
/// rotations. Coordinates are centred first so that the rotations are well scaled.
Eigen::MatrixXd candidate_kernel(const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<int>& component, const std::vector<double>& z = {});

/// The true kernel inside span(candidates): the orthonormal basis of
/// {R c : ||K R c|| <= tol ||K||}, from the SVD of K R. A subdomain with Dirichlet dofs
/// eliminated gets an empty basis, a symmetry condition on one component a smaller one.
/// Reads K's lower triangle only.
Eigen::MatrixXd kernel_in_span(const SparseMatrix& K, const Eigen::MatrixXd& candidates);

/// r dofs where the kernel basis R (n x r) restricted to them is best conditioned
/// (column-pivoted QR of R'). Removing them from K leaves a regular matrix.
std::vector<int> fixing_dofs(const Eigen::MatrixXd& R);

}  // namespace ffeti
