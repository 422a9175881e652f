// Restarted GMRES for a nonsymmetric linear operator (Coulomb's law linearized on its
// stick and slip sets: feti/coulomb_newton.h), counting its applications.
#pragma once

#include "qp/qp_types.h"

namespace ffeti::qp {

struct GmresResult {
  bool converged = false;
  int applications = 0;          ///< of A
  double relative_residual = 0;  ///< ||b - A x|| / ||b|| at the end
};

/// Solves A x = b from x by GMRES(restart): stops when ||b - A x|| <= tol ||b|| or after
/// `max_applications` applications of A. Modified Gram-Schmidt and Givens rotations; the
/// residual norm is the least-squares one, the true one recomputed at each restart.
GmresResult gmres(const LinearOperator& A, const Vec& b, Vec& x, double tol, int max_applications, int restart = 40);

}  // namespace ffeti::qp
