// Coulomb's law on the dual by a primal-dual active set (semismooth Newton) iteration, the
// slip directions taken from the last iterate (docs/algorithms.md, "Friction"): each step
// fixes which contact rows are closed, which of their friction pairs stick and which slip
// (lambda_t = mu lambda_n s), and solves the linear, nonsymmetric system that leaves by
// GMRES, G lambda = e held by an oblique projection. The fixed point over Tresca solves
// (feti/friction.h) starts it and checks its answer.
#pragma once

#include "feti/dual_system.h"
#include "qp/budget.h"

namespace ffeti {

struct CoulombNewtonResult {
  bool converged = false;  ///< the sets and slip directions repeated with the system solved to tol
  Vec lambda;              ///< the last iterate
  int hessian = 0;         ///< applications of F
  int preconditioner = 0;  ///< applications of the dual preconditioner (GMRES's)
  int steps = 0;
};

/// From `lambda` (a Tresca solution: its closed rows, sticking and slipping pairs start the
/// sets) until the sets and the slip directions repeat with the system solved to tol, the
/// sets cycle, or 30 steps; charges `budget` and stops where it runs out. Collective (every
/// rank holds the dual vectors and does the same steps).
CoulombNewtonResult coulomb_newton(const DualSystem& dual, const DualData& data, const Vec& lambda, double tol,
                                   qp::Budget& budget);

}  // namespace ffeti
