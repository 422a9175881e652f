// MPRGP: modified proportioning with reduced gradient projections (Dostal 1997), for
//   min 1/2 x'Ax - b'x  subject to  l_i <= x_i <= u_i  (l_i = kUnbounded, u_i = +infinity:
//   no bound; the frictionless dual has lower bounds only, friction's tangential rows both).
#pragma once

#include "qp/qp_types.h"

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
  int max_hessian = 20000;    ///< limit on Hessian multiplications in this call
  MprgpExpansion expansion = MprgpExpansion::projected_cg;
  int settle_rounds = 0;      ///< face solves settling the start first (settle_start); 0: none

  /// Throws std::invalid_argument naming the offending member.
  void validate() const;
};

using MprgpResult = QpResult;

/// Projected gradient gP = phi + beta of ALGORITHMS.md section 4:
/// gP_i = g_i where x_i is free (unbounded or x_i > l_i), min(g_i, 0) where x_i = l_i.
Vec projected_gradient(const Vec& x, const Vec& g, const Vec& lower);
/// The same for box bounds: max(g_i, 0) where x_i = u_i.
Vec projected_gradient(const Vec& x, const Vec& g, const Bounds& bounds);
/// ||gP||_inf without forming gP (stopping tests call it every iteration).
double projected_gradient_max(const Vec& x, const Vec& g, const Bounds& bounds);

/// Sets the components of x below their bound to it; returns how many there were.
int project_onto_bounds(Vec& x, const Vec& lower);
/// The same for box bounds (components above u_i set to it).
int project_onto_bounds(Vec& x, const Bounds& bounds);

/// Bounded components of x above their bound: for the FETI dual, the contact rows with a
/// positive multiplier (the contact set).
int off_bound_count(const Vec& x, const Vec& lower);

/// Minimizes the QP from the start x (projected onto the bounds first; then, unless it
/// passes the stop test, settled by `settings.settle_rounds` face solves). On return x is the
/// last iterate and g = Ax - b at it. If `gradient_is_current` is true, g on entry must
/// already equal Ax - b at the (feasible) x, saving one multiplication (warm restarts).
/// `a_norm` is an upper estimate of ||A||_2. `stop` receives ||gP(x)||_2.
/// With a `preconditioner` M (symmetric positive definite), the conjugate gradient steps
/// are preconditioned in face: their directions come from M applied to the free gradient,
/// restricted to the free set (an SPD preconditioner of the face's reduced problem); the
/// expansion and proportioning steps, and so the convergence guarantees, are unchanged.
MprgpResult mprgp(const LinearOperator& A, const Vec& b, const Vec& lower, double a_norm,
                  Vec& x, Vec& g, bool gradient_is_current, const MprgpSettings& settings,
                  const StopTest& stop, const Monitor& monitor = {}, const LinearOperator& preconditioner = {});

/// The same for box bounds (Dostal's MPRGP for bound constraints on both sides: the free
/// set excludes both bounds, the chopped gradient points into the box, the reduced free
/// gradient and the feasible step respect both). With `bounds.upper` null it is the call
/// above, iterate for iterate.
MprgpResult mprgp(const LinearOperator& A, const Vec& b, const Bounds& bounds, double a_norm,
                  Vec& x, Vec& g, bool gradient_is_current, const MprgpSettings& settings,
                  const StopTest& stop, const Monitor& monitor = {}, const LinearOperator& preconditioner = {});

}  // namespace ffeti
