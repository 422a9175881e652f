// The null space of a symmetric positive semidefinite matrix A, and k rows whose deletion
// leaves a regular principal block (k = dim Ker A), as the coarse problem of Total FETI
// needs them for G_F G_F' (one row per rigid mode of a floating subdomain; its null space:
// the rigid modes of whole floating bodies, a handful).
//
// Small A: LAPACK's Cholesky with complete pivoting (dpstrf), dense, the rank decision of
// record. Large A: dense costs O(r^3) time and 2 r^2 doubles (8192 subdomains of 3D
// elasticity, r = 49,152: 38 GB), so instead a sparse Cholesky factor of A + shift I and
// block inverse iteration from random vectors, its Ritz values below the same relative
// threshold deciding the rank; a block whose every vector lies in the null space is doubled
// until one does not. The deleted rows: the pivots of a column-pivoted QR of W' (W_I
// regular, so A with rows and columns I deleted is regular: an x in its null space, padded
// with zeros, would be a null vector W c with W_I c = 0).
#pragma once

#include "base/linear_algebra.h"

#include <Eigen/Dense>

#include <vector>

namespace ffeti {

struct SemidefiniteKernel {
  Eigen::MatrixXd basis;          ///< r x k, orthonormal columns spanning Ker A
  std::vector<int> deleted_rows;  ///< k rows (and columns) whose removal leaves A regular
};

/// An orthonormal basis of the span of X's columns (X of full column rank), by Householder QR.
Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& X);

/// Rows up to which the dense rank-revealing factorization is used (about 1 s here).
constexpr Eigen::Index kDenseKernelLimit = 2500;

/// Ker A with `relative_tolerance` on pivots (dense) or Ritz values (sparse) relative to
/// A's largest diagonal entry. `dense_limit`: the size above which the sparse method runs.
SemidefiniteKernel semidefinite_kernel(const SparseMatrix& A, double relative_tolerance,
                                       Eigen::Index dense_limit = kDenseKernelLimit);

/// Ker A of a dense A by the sparse method's block inverse iteration, A + shift I factored by
/// Eigen's blocked Cholesky: at 3072 rows 0.7 s against 5.9 s for LAPACK's pivoted Cholesky
/// (dpstrf) with the reference BLAS. For the coarse problem's dense Schur complements.
SemidefiniteKernel semidefinite_kernel_by_iteration(const Eigen::MatrixXd& A, double relative_tolerance);

}  // namespace ffeti
