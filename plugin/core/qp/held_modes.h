// The equality modes that only the bounded blocks hold, balanced by a rigid-plastic model:
// SMALBE's multiplier step where its own crawls. In the FETI dual with friction, C x = 0 is
// the balance of each floating body's rigid modes; a body's slides and turn along a flat
// contact move its friction rows only (boxes, discs), so only friction holds them. Near the
// onset of sliding nearly every pair slips and the dual function is nearly flat along those
// modes: SMALBE's update nu += rho Q x moves the multiplier (the body's slide) by a few per
// cent of what it needs per outer round, always the same way, for hundreds of rounds
// ([log](docs/log.md), 2026-12-06).
//
// The model holds the gradient g of the Lagrangian (the slips, -g) fixed but for the held
// modes' own motion U beta and lets every bounded block take the force a rigid-plastic
// contact would, the point x(y) of its set minimizing y'x at y = g + U beta (a slipping
// pair: its bound along the slip). The held modes balance where U'x(y) = 0, the maximum of
// the concave Phi(beta) = min over the bounded sets of (g + U beta)'x, whose gradient is
// U'x(y): a small dense problem (k' modes: two slides and a turn per body in 3D, one slide
// in the plane), solved by Newton steps with an exact line search.
#pragma once

#include "qp/constraint_set.h"

#include <Eigen/Dense>

namespace ffeti::qp {

class HeldModes {
 public:
  /// C: the equality part's rows (k x n, full row rank); `set`: the constraint set (kept by
  /// reference). U: an orthonormal basis of the vectors C'a that vanish on every free and
  /// half-line component (empty when no mode is held by bounded blocks alone).
  HeldModes(const Eigen::MatrixXd& C, const ConstraintSet& set);

  bool empty() const { return U_.cols() == 0; }
  /// The modes' basis (n x k').
  const Eigen::MatrixXd& basis() const { return U_; }
  /// The change d = U beta of the multiplier term nu that balances the held modes in the
  /// model at g (the gradient of L(x, nu, 0)): U'x(g + d) = 0 to round-off where the model
  /// is smooth, its maximum otherwise. False where Phi has no maximum (the bounded blocks
  /// cannot hold the modes) or g is not finite.
  bool balance(const Vec& g, Vec& d) const;

 private:
  /// Phi at y = g + U beta; its maximizing points into x.
  double value(const Vec& y, Vec& x) const { return set_.linear_minimum(y, x); }
  /// The line search along U p from y: the t >= 0 where p'U'x(y + t U p) changes sign
  /// (Phi concave: that slope falls with t). Negative where it does not within reach.
  double exact_step(const Vec& y, const Vec& Up, Vec& x) const;

  const ConstraintSet& set_;
  Eigen::MatrixXd U_;
};

}  // namespace ffeti::qp
