// Triangular solves with a CHOLMOD supernodal LL' factor through Eigen's dense kernels.
//
// CHOLMOD's own supernodal solve runs each supernode's dense triangle and the block below it
// through the BLAS (dtrsv and dgemv for one right-hand side, dtrsm and dgemm for several).
// With the reference BLAS the set-up installs (docs/dependencies.md: OpenBLAS is left to the
// user), Eigen's vectorized kernels do the same arithmetic faster: with the coarse factor of
// 8192 elastic boxes 0.064 against 0.105 s for one right-hand side, 0.16 against 0.43 s for
// eight (docs/log.md, 2026-11-28). The supernodes are read as CHOLMOD lays them out
// (cholmod_factor: super, pi, px, s, x); only the BLAS calls are replaced.
#pragma once

#include <cholmod.h>

#include <Eigen/Dense>

namespace ffeti {

/// A rows x cols view of `scratch`, which only grows: the supernodes' blocks differ in size,
/// and resizing a matrix to each would allocate at every supernode of every solve.
inline Eigen::Map<Eigen::MatrixXd> scratch_block(Eigen::MatrixXd& scratch, Eigen::Index rows, Eigen::Index cols) {
  if (scratch.size() < rows * cols) scratch.resize(rows * cols, 1);
  return {scratch.data(), rows, cols};
}

/// X <- L^{-1} X, the columns of X in the factor's own (permuted) numbering.
/// `scratch`: grown as needed (scratch_block). Precondition: factor.is_super (then LL').
void supernodal_forward(const cholmod_factor& factor, Eigen::Ref<Eigen::MatrixXd> X, Eigen::MatrixXd& scratch);

/// X <- L^{-T} X, likewise.
void supernodal_backward(const cholmod_factor& factor, Eigen::Ref<Eigen::MatrixXd> X, Eigen::MatrixXd& scratch);

}  // namespace ffeti
