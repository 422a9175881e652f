// Sparse Cholesky factor of a symmetric positive definite matrix through CHOLMOD:
// analyze (fill-reducing ordering, once per pattern), factorize (per numeric matrix),
// solve (many times, on preallocated workspace).
#pragma once

#include "base/linear_algebra.h"
#include "factor/shared_analyses.h"

#include <cholmod.h>

#include <vector>

namespace ffeti {

/// `automatic` lets CHOLMOD choose after its analysis: supernodal (dense blocks through the
/// BLAS) when the flops per factor nonzero reach supernodal_switch(), simplicial below
/// (2D subdomains of a few thousand dofs: several times faster, docs/results/model-problem.md).
enum class FactorKind { simplicial, supernodal, automatic };

/// Where the columns a dual-operator solve reads (the interface: where B_s touches the
/// subdomain) go in the elimination order. `fill_reducing`: CHOLMOD's ordering alone, every
/// solve reads all of L. `interface_last`: the interface eliminated last (CAMD), so that a
/// solve on it reads only its block of L (about t^2/2 entries for t interface columns), for
/// a costlier factorization (the Schur complement on the interface is formed: 2-5 times
/// the flops on 2D subdomains) and a larger factor. `automatic`: interface last where the
/// extra flops per factor entry a pass no longer reads stay below a measured bound, so that
/// the ordering pays for itself within ~90 multiplications (2D subdomains, not 3D ones,
/// whose interfaces are large against their volume). Simplicial factors only: a supernodal
/// factor keeps the fill-reducing ordering.
enum class InterfaceOrdering { fill_reducing, interface_last, automatic };

/// What a factor is of: a subdomain's matrix (its stiffness, or a block of it) counts in
/// factorizations_in_process(); the coarse problem's small Gram matrices (GG', G_S G_S') do not.
enum class FactorOf { subdomain, coarse_problem };

/// Whether `automatic` orders the interface last: a pass of F then reads the factor's
/// entries below the interface block only (`fill_entries` of the fill-reducing factor less
/// `saved_entries`), for `extra_flops` more in the factorization. It pays where the saved
/// entries are at least a third of the factor (a subset solve costs ~1.45 times a whole solve
/// per entry it reads, measured on the large contact zone's subdomains) and cost at most 300
/// extra flops each (docs/algorithms.md).
bool interface_ordering_pays(double fill_entries, double saved_entries, double extra_flops);

/// What a solve writes besides its result: CHOLMOD's dense workspaces, its own
/// cholmod_common (CHOLMOD's solves use the common's scratch space) and the interface
/// solve's right-hand side. A factor may be solved from several threads at once, each with
/// a workspace of its own (subdomains that share one factor: SharedFactors).
class CholmodSolveWorkspace {
 public:
  CholmodSolveWorkspace();
  ~CholmodSolveWorkspace();
  CholmodSolveWorkspace(const CholmodSolveWorkspace&) = delete;
  CholmodSolveWorkspace& operator=(const CholmodSolveWorkspace&) = delete;

 private:
  friend class CholmodFactor;
  struct Buffers {  // reused by cholmod_solve2 while the block width stays the same
    cholmod_dense* solution = nullptr;
    cholmod_dense* y = nullptr;
    cholmod_dense* e = nullptr;
  };
  cholmod_common common_;
  Buffers vector_, block_, interface_;
  Eigen::MatrixXd supernodal_rhs_, supernodal_below_;  ///< supernodal solves' permuted columns and scratch
  cholmod_dense* interface_rhs_ = nullptr;  ///< dense n-vector, written only on the interface
  cholmod_sparse* reached_ = nullptr;       ///< Xset: the columns a solve_on_interface reached
};

/// Owns one cholmod_common, so distinct objects may be used from distinct threads.
/// Not copyable. A solve without a workspace argument uses the factor's own, so is not
/// thread-safe on the same object; solves given distinct workspaces are.
class CholmodFactor {
 public:
  explicit CholmodFactor(FactorKind kind = FactorKind::simplicial,
                         InterfaceOrdering ordering = InterfaceOrdering::fill_reducing,
                         FactorOf of = FactorOf::subdomain);
  ~CholmodFactor();
  CholmodFactor(const CholmodFactor&) = delete;
  CholmodFactor& operator=(const CholmodFactor&) = delete;

  /// Factorizes A (its lower triangle is read; A must be square and compressed).
  /// Returns -1 on success, else the column at which A was found not positive definite.
  /// The symbolic analysis runs on the first call (or a new size); with `shared`, it is
  /// copied from there when a matrix of A's pattern was analyzed before, and kept there
  /// otherwise.
  ///
  /// `interface` (sorted, distinct columns of A; may be empty): the columns
  /// solve_on_interface reads and writes, ordered as the InterfaceOrdering given at
  /// construction says (a second analysis where the first comes out simplicial).
  int factorize(const SparseMatrix& A, SharedAnalyses* shared = nullptr, const std::vector<int>& interface = {});

  /// Factorizes A (supernodal LL') with the columns `last` eliminated last, in that order, the
  /// others first in a fill-reducing order of their own block. Then L's last block is the
  /// Cholesky factor of the Schur complement of A on `last` (trailing_block). Returns like
  /// factorize.
  int factorize_with_last(const SparseMatrix& A, const std::vector<int>& last);
  /// L's block on the last columns of factorize_with_last (dense, lower triangular).
  Eigen::MatrixXd trailing_block() const;
  /// The two halves of a solve with an LL' factor A = P'LL'P: y = L^{-1} P b, and x = P'L^{-T} y.
  /// In the factor's own workspace (not thread-safe).
  void forward(const Vec& b, Vec& y) const;
  void backward(const Vec& y, Vec& x) const;

  /// x(interface) of A x = b, b zero outside the interface given to factorize, its values
  /// there `b_on_interface` (in the interface's order). CHOLMOD reads only the columns of L
  /// that the interface reaches in the elimination tree. Precondition: interface_solves().
  void solve_on_interface(const Eigen::VectorXd& b_on_interface, Eigen::VectorXd& x_on_interface) const {
    solve_on_interface(b_on_interface, x_on_interface, own_workspace_);
  }
  void solve_on_interface(const Eigen::VectorXd& b_on_interface, Eigen::VectorXd& x_on_interface,
                          CholmodSolveWorkspace& workspace) const;
  /// True when the factor was ordered with its interface last (solve_on_interface applies).
  bool interface_solves() const { return interface_set_ != nullptr; }

  /// x = A^{-1} b. Precondition: the last factorize succeeded.
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) const { solve(b, x, own_workspace_); }
  void solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, CholmodSolveWorkspace& workspace) const;
  /// X = A^{-1} B for a block of right-hand sides in one pass over the factor: the factor
  /// is read once for all columns, cheaper per column than column after column.
  void solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) const { solve(b, x, own_workspace_); }
  void solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x, CholmodSolveWorkspace& workspace) const;
  /// Numeric factorizations of subdomain matrices (FactorOf::subdomain) run by every
  /// CholmodFactor of this process so far (all threads): lets callers prove that a phase
  /// factorized no subdomain.
  static long factorizations_in_process();

  Eigen::Index size() const { return size_; }
  double factor_nonzeros() const;  ///< nnz(L), for reports
  /// Bytes one triangular solve (forward or backward) reads of the factor: its values and
  /// the integer indices that locate them (simplicial: a row index per entry and a start
  /// and count per column; supernodal: dense blocks of values, a row index per block row and
  /// a few pointers per supernode). A Hessian multiplication reads it at least once (twice,
  /// L then L', where it does not stay in cache): the memory-bandwidth bound of a solve.
  double factor_bytes() const;
  /// Of factor_bytes, what one triangular solve_on_interface reads: the interface block's
  /// columns of L (0 without interface solves).
  double interface_bytes() const;
  bool supernodal() const { return factor_ && factor_->is_super; }
  /// CHOLMOD's factor itself, read-only (null before a factorization): for the dense kernels
  /// of factor/ that read L's layout (dense_interface_inverse).
  const cholmod_factor* cholmod() const { return factor_; }
  /// The analysis' flop count of the factorization and nnz(L) without the supernodes'
  /// padding (CHOLMOD's Common->fl and ->lnz): what an automatic choice judged.
  double analysis_flops() const { return analysis_flops_; }
  double analysis_nonzeros() const { return analysis_nonzeros_; }
  /// CHOLMOD's cheap estimate (min diag L / max diag L)^2; ~eps for a numerically singular A.
  double reciprocal_condition() const;

 private:
  mutable cholmod_common common_;
  InterfaceOrdering ordering_;
  FactorOf of_;
  cholmod_factor* factor_ = nullptr;
  void solve_columns(const double* b, Eigen::Index rows, Eigen::Index cols, double* x, CholmodSolveWorkspace& w,
                     CholmodSolveWorkspace::Buffers& buffers) const;

  int factorize_numeric(cholmod_sparse& view);  // on the factor's analysis; returns like factorize
  void triangular_solve(int system, const Vec& b, Vec& x) const;  // CHOLMOD_L or CHOLMOD_Lt, no permutation

  /// The analysis with the interface last (CAMD), or null where `automatic` keeps the
  /// fill-reducing one (common_ holds the latter's statistics on entry).
  cholmod_factor* analyze_interface_last(cholmod_sparse& A, const std::vector<int>& interface);

  mutable CholmodSolveWorkspace own_workspace_;
  cholmod_sparse* interface_set_ = nullptr;  ///< the interface as CHOLMOD's Bset (a pattern column)
  Eigen::Index size_ = 0;
  Eigen::Index last_columns_ = 0;  ///< of factorize_with_last
  mutable Vec permuted_;           ///< forward's and backward's permuted vector
  double analysis_flops_ = 0, analysis_nonzeros_ = 0;
};

}  // namespace ffeti
