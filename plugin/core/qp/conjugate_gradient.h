// Conjugate gradients for A x = b with A symmetric positive definite on the iteration's
// subspace. With A = P F P and b in Ker G this is the projected CG of FETI-1 (Farhat-Roux).
#pragma once

#include "qp/qp_types.h"

namespace ffeti {

struct CgSettings {
  int max_hessian = 20000;  ///< limit on Hessian multiplications
  void validate() const;
};

struct CgResult {
  SolveStatus status = SolveStatus::max_iterations;
  IterationCounts counts;
  double gradient_norm = 0;  ///< ||A x - b||_2 at exit
};

/// Minimizes 1/2 x'Ax - b'x from the start x (updated in place); g = Ax - b on return.
/// `stop` receives ||g||_2. Convergence is declared only on the true gradient A x - b
/// (recomputed once the updated one passes the test: one more multiplication); if it fails
/// the test, CG restarts from it, and after two such restarts returns `stagnated`: the
/// tolerance asked for lies below what round-off lets the data reach.
CgResult conjugate_gradient(const LinearOperator& A, const Vec& b, Vec& x, Vec& g,
                            const CgSettings& settings, const StopTest& stop,
                            const Monitor& monitor = {});

}  // namespace ffeti
