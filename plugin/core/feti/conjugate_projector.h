// The conjugate projector of a dual problem whose subdomains have no kernel (K + c M of a
// time step: docs/algorithms.md, "Transient contact"): the subdomains' rigid modes on the
// equality rows, C = B_E R, span the directions F is weakest in when the step is long (Keff
// nearly floats). With E = C'FC and P = I - C E^+ C'F (F-orthogonal onto the complement of
// span C), lambda = C E^+ C'd + P mu, and mu solves the same QP with F P in place of F and
// P'd in place of d. C is zero on the contact and friction rows, so P leaves those entries
// as they are and their bounds hold for mu as for lambda (Dostal, Kozubek, Brzobohaty et
// al., TFETI with preconditioning by the conjugate projector).
#pragma once

#include "feti/dual_operator.h"

#include <Eigen/Dense>

namespace ffeti {

class ConjugateProjector {
 public:
  /// `C` (dual rows x rigid modes, the same on every rank); F applied to its columns once
  /// (collective). Modes whose E = C'FC is zero (a subdomain no equality row touches) are
  /// left out by the pseudo-inverse.
  ConjugateProjector(Eigen::MatrixXd C, const DualOperator& F);

  /// y = P x = x - C E^+ (FC)' x.
  void project(const Vec& x, Vec& y) const;
  /// y = P' x = x - FC E^+ C' x.
  void project_transposed(const Vec& x, Vec& y) const;
  /// lambda_0 = C E^+ C' d: the part of the solution in span C.
  Vec base(const Vec& d) const;

 private:
  Vec solve_E(const Vec& r) const;  // E^+ r
  // Sparse: a mode's column touches its subdomain's rows, F spreads it to the neighbours'
  // (dense, their products cost more than F itself: 128 subdomains of the membranes).
  SparseMatrix C_, FC_;
  Eigen::MatrixXd E_vectors_;       // E's eigenvectors kept (eigenvalue above round-off)
  Vec E_inverse_values_;
};

}  // namespace ffeti
