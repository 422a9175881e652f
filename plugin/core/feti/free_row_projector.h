// The coarse constraints G mu = 0 met by the unbounded multipliers alone. Only contact
// rows carry bounds; gluing and Dirichlet rows are free. The free columns G_F of G span
// its row space except for the rigid modes of whole floating bodies, which gluing cannot
// hold and only contact forces balance (W: an orthonormal basis of Ker G_F', one vector
// for a floating membrane, three for a floating elastic body). The oblique projector
//     T = I - E_F G_F' (G_F G_F')^+ (I - W W') G
// corrects any mu by free multipliers only (bounds stay satisfied) so that G T mu lies in
// Im W: each subdomain's imbalance, less its body's share, is carried by gluing forces. The
// remaining rows C = W'G act on contact multipliers only (W'G_F = 0), and
//     {mu : G mu = 0, mu_I >= l} = {T nu : C nu = 0, nu_I >= l},  nu_I = mu_I,
// so the dual QP keeps its bounds and only the few rows of C are left to an augmented
// Lagrangian (none when no body floats as a whole). See docs/algorithms.md.
#pragma once

#include "feti/coarse_gram.h"
#include "qp/qp_types.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <memory>

namespace ffeti {

class FreeRowProjector {
 public:
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

  /// `gram`: of the natural coarse space G (full row rank), whose first `free_columns`
  /// columns are the unbounded multipliers. Keeps references to both.
  FreeRowProjector(const CoarseGram& gram, int free_columns);

  /// Rows of C (the floating bodies' rigid modes).
  int remaining() const { return static_cast<int>(W_.cols()); }
  /// C = W'G, k x m: nonzero on contact columns only.
  const Eigen::MatrixXd& remaining_rows() const { return C_; }
  /// W, r x k: the orthonormal basis of Ker G_F' (rows: G's, the subdomains' rigid modes).
  const Eigen::MatrixXd& remaining_basis() const { return W_; }
  /// y = T x.
  void apply(const Vec& x, Vec& y) const;
  /// y = T' x.
  void apply_transpose(const Vec& x, Vec& y) const;
  /// y = x less its component in Ker T = Im E_F G_F': the orthogonal projector onto the
  /// subspace on which T is one to one. With M an approximate inverse of P F P, this
  /// projector, then P M P, then it again approximate the inverse of T'PFPT there.
  void project_out_kernel(const Vec& x, Vec& y) const;
  /// ||G T x|| without T: G T x = W C x and W has orthonormal columns, so it is ||C x||.
  double remaining_norm(const Vec& x) const { return C_.rows() ? (C_ * x).norm() : 0.0; }
  /// y = C'(CC')^{-1} C x: the orthogonal projector onto Im C' (zero when C is empty).
  void project_remaining_range(const Vec& x, Vec& y) const;
  /// y = P T x, P = I - G'(GG')^{-1} G, without a coarse solve: G T x = W W'G x = W C x, so
  /// P T x = T x - G' Z C x with Z = (GG')^{-1} W, found once (k solves); T x when no body
  /// floats (k = 0). Precondition: the coarse Gram matrix GG' is factored.
  void apply_projected(const Vec& x, Vec& y) const;
  /// y = T'P x = (P T)' x = T'x - C' Z' G x.
  void apply_projected_transpose(const Vec& x, Vec& y) const;

 private:
  void remove_body_modes(Vec& v) const;  // v <- (I - W W') v

  const RowMatrix& G_;
  RowMatrix G_F_;                            // the free columns of G
  std::unique_ptr<PartialGram> free_gram_;  // G_F G_F': (G_F G_F')^+ y for y in Im G_F, allocation-free
  Eigen::MatrixXd W_;                        // orthonormal basis of Ker G_F'
  Eigen::MatrixXd C_;                     // W'G
  Eigen::MatrixXd Z_;                     // (GG')^{-1} W
  Eigen::LLT<Eigen::MatrixXd> solver_C_;  // of C C'
  Eigen::Index free_ = 0;
};

}  // namespace ffeti
