// MPRGP: modified proportioning with reduced gradient projections (Dostal 1997), for
//   min 1/2 x'Ax - b'x  subject to  l_i <= x_i <= u_i  (l_i = kUnbounded, u_i = +infinity:
//   no bound; the frictionless dual has lower bounds only, friction's tangential rows both),
// and with disc blocks (isotropic friction in 3D) Dostal's MPGP, its generalisation to
// separable convex sets. Written once against qp::ConstraintSet (qp/constraint_set.h): the
// projection, free and chopped gradients, reduced free gradient, feasible step and the
// curved faces' corrections come from the set's kinds (qp/bound_sets.h, qp/disc_set.h).
#pragma once

#include "qp/problem.h"

namespace ffeti {

/// How MPRGP expands the active set when a CG step would leave the feasible set.
enum class MprgpExpansion {
  fixed_step,            ///< the feasible part of the CG step, then a projected free-gradient step abar
  projected_cg_restart,  ///< the whole CG step projected, kept if it decreases f at least as much as
                         ///< the fixed step is guaranteed to; otherwise the fixed step (Kruzik et al.
                         ///< 2020); CG restarts from the free gradient after it
  projected_cg,          ///< the same step, and after a kept one the CG recurrence goes on in the
                         ///< new face (its last direction restricted to the free set), each step
                         ///< until the next restart checked against the fixed step's decrease
};

struct MprgpSettings {
  double gamma = 1.0;         ///< proportioning threshold Gamma > 0
  double step_factor = 1.9;   ///< fixed step abar = step_factor / ||A||, in (0, 2]
  MprgpExpansion expansion = MprgpExpansion::projected_cg;
  int settle_rounds = 0;      ///< face solves settling the start first (settle_start); 0: none

  /// Throws std::invalid_argument naming the offending member.
  void validate() const;
};

using MprgpResult = QpResult;

/// Minimizes the problem (its free, half-line, box and disc blocks; no equality part) from the
/// start x (projected onto the bounds first; then, unless it passes the stop test, settled
/// by `settings.settle_rounds` face solves); x is the last iterate on return. Needs
/// `problem.hessian_norm`, an upper estimate of ||A||_2. `stop` receives x, g = Ax - b and
/// ||gP(x)||_2. Multiplies at most what the budget has left on entry, and charges it with
/// what it spent on return. With a preconditioner M (symmetric positive definite), the conjugate
/// gradient steps are preconditioned in face: their directions come from M applied to the
/// free gradient, restricted to the free set (an SPD preconditioner of the face's reduced
/// problem); the expansion and proportioning steps, and so the convergence guarantees, are
/// unchanged. With box blocks this is Dostal's MPRGP for bounds on both sides: the free set
/// excludes both bounds, the chopped gradient points into the box, the reduced free
/// gradient and the feasible step respect both. With disc blocks this is MPGP: the same
/// steps with the disc's geometry (qp/disc_set.h), the tangent of a pair on its circle free: CG
/// moves such a pair along it with the circle's curvature added to A and projects it back
/// (g then known to 1e-2 ||gP|| between recomputations and at every stop decision), a pair
/// whose circle curves more than 0.3 ||A|| holds its tangent instead, the fixed step
/// goes along g - beta, and proportioning releases pairs radially into their discs (with
/// held stiff pairs, the projected step P(x - abar (g - phi)) that also turns them).
MprgpResult mprgp(const qp::Problem& problem, const MprgpSettings& settings, Vec& x, qp::Budget& budget,
                  const StopTest& stop, const Monitor& monitor = {});

/// The same, continued from an iterate whose gradient is known: if `gradient_is_current`,
/// g on entry must equal Ax - b at the (feasible) x, saving one multiplication (SMALBE's
/// inner solves after a multiplier update); g = Ax - b at the last iterate on return.
/// `settings` as validated by its caller (SMALBE checks its inner settings once per call,
/// not once per inner solve).
/// With `inexact_gradient` (discs only make it nonzero) g may be off by up to that bound, in
/// and out: g is recomputed only when the bound exceeds 1e-2 ||gP||, not on every return.
MprgpResult mprgp_with_gradient(const qp::Problem& problem, const MprgpSettings& settings, Vec& x, Vec& g,
                                bool gradient_is_current, qp::Budget& budget, const StopTest& stop,
                                const Monitor& monitor = {}, double* inexact_gradient = nullptr);

}  // namespace ffeti
