// A factor's inverse restricted to a few of its columns, formed once and held dense: the
// explicit form of a solve that only ever reads and writes those columns (the FETI dual
// operator's K_s^+ on a subdomain's interface). Applying it is a dense symmetric
// matrix-vector product that streams t(t+1)/2 values at the memory's rate, where a sparse
// triangular solve reads its factor's values and indices twice (L, then L') at a third to a
// fifth of that rate (docs/results/dual-operator.md).
#pragma once

#include "factor/cholmod_factor.h"

#include <Eigen/Dense>

#include <vector>

namespace ffeti {

/// A symmetric t x t matrix held as its lower triangle, packed column after column
/// (column j holds rows j..t-1): half the memory of a full matrix, and what a product reads.
class PackedSymmetric {
 public:
  PackedSymmetric() = default;
  /// The lower triangle of `full` (its upper one is not read).
  explicit PackedSymmetric(const Eigen::MatrixXd& full);

  Eigen::Index size() const { return size_; }
  /// Bytes held, and read by each product: t(t+1)/2 doubles.
  double bytes() const { return static_cast<double>(values_.size() * sizeof(double)); }

  /// y = S x. Per column j, one dot product and one update on the same t - j values, the
  /// second from L1: on this machine as fast as Eigen's selfadjointView product on full
  /// storage (which holds twice the memory) and faster than a full GEMV (twice the bytes).
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  /// Y = S X for a block of columns, in one pass over the values.
  void apply(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  /// S as a full matrix (tests, reports).
  Eigen::MatrixXd full() const;

 private:
  Eigen::Index size_ = 0;
  std::vector<double> values_;
};

/// The t x t matrix S(a, b) = (A^{-1})(columns[a], columns[b]) for the factor's A, with zero
/// rows and columns where columns[k] < 0 (a generalized inverse that is zero on some dofs:
/// a semidefinite subdomain's fixing dofs). Formed by block solves with the identity's
/// columns, `width` at a time (each block one pass over the factor), on the caller's
/// workspace (thread-safe across workspaces). Symmetric to round-off; its lower triangle is
/// kept. Cost: ceil(t / width) block solves.
PackedSymmetric dense_interface_inverse(const CholmodFactor& factor, const std::vector<int>& columns,
                                        CholmodSolveWorkspace& workspace, Eigen::Index width = 64);

/// Whether a held inverse beats solving: its bytes (PackedSymmetric::bytes, read once per
/// product) at most the bytes one triangular pass of the solve reads (`solve_pass_bytes`,
/// the interface block or the whole factor). A solve's two passes read those bytes twice
/// where the factor does not stay in cache, at a third to a fifth of the dense product's
/// rate, so this is a multiplication at least twice as cheap in bytes; and memory grows by at
/// most what the factor's pass holds (docs/algorithms.md).
bool explicit_inverse_pays(double packed_bytes, double solve_pass_bytes);

/// PackedSymmetric::bytes of a t x t matrix, before forming it.
double packed_symmetric_bytes(Eigen::Index t);

}  // namespace ffeti
