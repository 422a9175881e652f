// A factor's inverse restricted to a few of its columns, formed once and held dense: the
// explicit form of a solve that only ever reads and writes those columns (the FETI dual
// operator's K_s^+ on a subdomain's interface). Applying it is a dense symmetric
// matrix-vector product that streams t(t+1)/2 values, where a sparse triangular solve reads
// its factor's values and indices twice (L, then L') at a fraction of the memory's rate
// (docs/results/model-problem.md: 4-6 GB/s against STREAM's 26; docs/results/dual-operator.md).
#pragma once

#include "factor/cholmod_factor.h"

#include <Eigen/Dense>

#include <vector>

namespace ffeti {

/// A symmetric t x t matrix held as its lower triangle in panels of kPanelWidth columns:
/// per panel, its diagonal block's lower triangle packed, then its rows below that block,
/// each row's kPanelWidth values together. A product reads each such row once for both of
/// its uses (the row's dot with the panel's x, and the row times its x added to the panel's
/// sum), so the values stream through once per product. t(t+1)/2 values: half the memory
/// of a full matrix, and what a product reads.
class PackedSymmetric {
 public:
  /// Columns per panel: one row of a panel is a cache line's worth (64 bytes, not aligned to
  /// one), and the panel's x and its sum stay in registers (8 against 4 and 16: docs/log.md,
  /// 2026-12-07).
  static constexpr Eigen::Index kPanelWidth = 8;

  PackedSymmetric() = default;
  /// The lower triangle of `full` (its upper one is not read).
  explicit PackedSymmetric(const Eigen::MatrixXd& full);

  Eigen::Index size() const { return size_; }
  /// Bytes held, and read by each product: t(t+1)/2 doubles.
  double bytes() const { return static_cast<double>(values_.size() * sizeof(double)); }

  /// y = S x.
  void apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;
  /// Y = S X for a block of columns, in one pass over the values.
  void apply(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  /// S as a full matrix (tests, reports).
  Eigen::MatrixXd full() const;

 private:
  using RowMajorBlock = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  struct Panel {
    const double* diagonal;  ///< the diagonal block's lower triangle, column after column
    Eigen::Index width;
    Eigen::Map<const RowMajorBlock> below;  ///< rows p + width .. t-1 of its columns
  };
  /// The panel starting at column p, whose values begin at `next` (moved past them).
  Panel panel(Eigen::Index p, const double*& next) const;

  Eigen::Index size_ = 0;
  std::vector<double> values_;
};

/// The t x t matrix S(a, b) = (A^{-1})(columns[a], columns[b]) for the factor's A, with zero
/// rows and columns where columns[k] < 0 (a generalized inverse that is zero on some dofs:
/// a semidefinite subdomain's fixing dofs). Where a simplicial factor ordered those columns
/// last (interface_solves), from L's block on them alone (closed under the elimination
/// tree's ancestors): A^{-1} there is L_II^{-T} D^{-1} L_II^{-1}, 2/3 t^3 dense flops. Otherwise by block solves with the
/// identity's columns, `width` at a time (each block one pass over the factor, 4 nnz(L)
/// width flops), on the caller's workspace (thread-safe across workspaces). Its lower
/// triangle is kept.
PackedSymmetric dense_interface_inverse(const CholmodFactor& factor, const std::vector<int>& columns,
                                        CholmodSolveWorkspace& workspace, Eigen::Index width = 64);

/// Whether a held inverse beats solving: it forms from the factor's interface block
/// (`from_interface_block`: a simplicial factor with the interface last, 2/3 t^3 dense flops,
/// about a third of the factorization's time on the 2D model problem) and its bytes
/// (PackedSymmetric::bytes, read once per product) are at most those one triangular pass
/// of the solve reads (`solve_pass_bytes`). A solve's two passes read those bytes twice
/// where the factor does not stay in cache, at a third of the dense product's rate or less,
/// so the multiplication is at least twice as cheap and memory grows by at most what the
/// factor's pass holds. Formed by block solves instead (3D supernodal factors) a block cost
/// 9 times the factorization on the 3D cubes, repaid after ~600 multiplications: never
/// automatic (docs/results/dual-operator.md).
bool explicit_inverse_pays(double packed_bytes, double solve_pass_bytes, bool from_interface_block);

/// PackedSymmetric::bytes of a t x t matrix, before forming it.
double packed_symmetric_bytes(Eigen::Index t);

}  // namespace ffeti
