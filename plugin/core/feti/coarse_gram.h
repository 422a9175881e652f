// The coarse problem's Gram matrices: GG' (every projection) and G_X G_X' over fewer of G's
// columns, the free rows' G_F G_F' (no bounded column) and each primal recovery's G_S G_S'
// (the bounded columns holding with equality). The bounded columns (contact and friction
// rows) meet only the rigid modes of the subdomains on a contact surface, C, so
//     G_X G_X' = GG' - U U',   U: the dropped columns of G, zero outside the rows of C.
// With C eliminated last, P GG' P' = L L' with L = [L_II 0; L_CI L_CC], and
//     P G_X G_X' P' = [L_II 0; L_CI I] diag(I, S_X) [L_II' L_CI'; 0 I],  S_X = L_CC L_CC' - U_C U_C':
// one sparse factor of GG' serves every such Gram matrix. A solve is a forward solve with L,
// a dense solve with S_X (order |C|: the contact surface's modes), a backward solve; a new X
// costs a dense Cholesky factor of S_X instead of a sparse factor of a matrix the size of GG'
// (at 8192 3D subdomains, 49,152 modes of which 3072 on the contact: 17 s each with the
// reference BLAS against 0.7 s; docs/log.md). Where C is too large for dense blocks, or the
// coarse problem so small that its sparse factors cost nothing, each G_X G_X' is factorized
// on its own.
#pragma once

#include "factor/cholmod_factor.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <memory>
#include <vector>

namespace ffeti {

/// A Gram matrix A = G_X G_X' of the coarse space over a subset X of G's columns: its null
/// space and solves A x = y for y in its range.
class PartialGram {
 public:
  virtual ~PartialGram() = default;
  /// Orthonormal basis of Ker A (r x k; no columns when A is regular).
  const Eigen::MatrixXd& kernel() const { return kernel_; }
  /// The solution of A x = y orthogonal to Ker A, for y in the range of A. Returns a buffer of
  /// the object, valid until the next call (no allocation per solve; not thread-safe).
  virtual const Vec& solve(const Vec& y) const = 0;

 protected:
  void remove_kernel(Vec& x) const {
    if (kernel_.cols() > 0) x.noalias() -= kernel_ * (kernel_.transpose() * x);
  }
  Eigen::MatrixXd kernel_;
};

/// How a Gram matrix over fewer columns is found regular or singular. `search`: its null space
/// is searched for (pivoted Cholesky or inverse iteration, semidefinite_kernel.h): the
/// decision of record, for the free rows' G_F G_F', singular wherever a body floats, whose
/// null space they need. `factor_first`: a Cholesky factor whose pivots' cheap condition
/// estimate exceeds 1e-12 is trusted (each primal recovery: one factor); a nearly singular
/// one goes on to the search.
enum class RankDecision { search, factor_first };

/// How the Gram matrices over fewer columns are factorized (tests force either).
enum class GramLayout { automatic, contact_last, separate };

class CoarseGram {
 public:
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

  /// Factorizes GG' (`upper`: its upper triangle). G's columns from `first_bounded` on are
  /// bounded. Keeps a reference to G.
  CoarseGram(const RowMatrix& G, int first_bounded, const Eigen::SparseMatrix<double>& upper,
             GramLayout layout = GramLayout::automatic);

  /// Whether GG' was found positive definite by its factorization (then solve applies).
  bool factored() const { return factored_; }
  /// CHOLMOD's cheap estimate (min diag L / max diag L)^2 of GG'.
  double reciprocal_condition() const { return factor_.reciprocal_condition(); }
  /// x = (GG')^{-1} b.
  void solve(const Vec& b, Vec& x) const { factor_.solve(b, x); }
  /// G_X G_X' for X the columns with kept[j] != 0 (every free column kept). Precondition: factored().
  std::unique_ptr<PartialGram> over_columns(const Vec& kept, RankDecision rank) const;
  const RowMatrix& G() const { return G_; }

  /// True when GG' is factored with the contact modes last (over_columns works on S_X).
  bool contact_last() const { return contact_last_; }
  /// Bytes held: GG''s factor and the contact modes' dense blocks.
  double held_bytes() const;

 private:
  friend class SchurGram;
  const RowMatrix& G_;
  int first_bounded_;
  bool factored_ = false, contact_last_ = false;
  std::vector<int> contact_modes_;  // C: the rows of G that meet a bounded column, in the factor's order (contact_last_)
  Eigen::MatrixXd trailing_;        // L_CC
  Eigen::MatrixXd schur_;           // L_CC L_CC': GG''s Schur complement on C
  CholmodFactor factor_{FactorKind::automatic, InterfaceOrdering::fill_reducing, FactorOf::coarse_problem};
};

}  // namespace ffeti
