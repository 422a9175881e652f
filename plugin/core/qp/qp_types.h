// Shared vocabulary of the QP solvers: operators, status codes, counters, monitors.
#pragma once

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <string>

namespace ffeti {

using Vec = Eigen::VectorXd;

/// Symmetric positive (semi)definite operator applied implicitly: y = A x.
/// The solvers count each call as one Hessian multiplication.
using LinearOperator = std::function<void(const Vec& x, Vec& y)>;

/// Lower bound meaning "this component is not bounded" (equality multipliers).
inline constexpr double kUnbounded = -std::numeric_limits<double>::infinity();

enum class SolveStatus {
  converged,
  max_iterations,      ///< iteration limit reached before the stopping test held
  stagnated,           ///< no progress possible (e.g. a vanishing curvature p'Ap)
  not_positive_definite,
  infeasible,          ///< equality and bound constraints cannot hold together
  invalid_input,
  weakly_active,       ///< sensitivity: weakly active contact rows, beta -> u' is not linear (no adjoint)
  overflow,            ///< the answer has non-finite values: finite data whose products overflow (e.g. 1e308)
  inaccurate,          ///< the dual test held but the primal equilibrium residual is far above tol (a wrong K^+)
};

std::string to_string(SolveStatus status);

/// Component x of an iterate is off its lower bound l (always so where l = kUnbounded).
inline bool above_bound(double x, double l) { return l == kUnbounded || x > l; }

/// Machine-independent cost of one solve. Every application of the Hessian inside the
/// solve is counted in `hessian`; the norm estimate's multiplications are kept apart.
struct IterationCounts {
  int outer = 0;        ///< SMALBE outer iterations (multiplier updates)
  int hessian = 0;      ///< Hessian multiplications inside the solve
  int hessian_norm_estimate = 0;
  int cg = 0;           ///< conjugate gradient steps (MPRGP CG steps or plain CG)
  int expansion = 0;    ///< MPRGP expansion steps
  int proportioning = 0;///< MPRGP proportioning steps
  int settle = 0;       ///< conjugate gradient steps settling a given start (qp/start_settling.h)
  int expansion_fallback = 0;  ///< MPRGP projected-CG expansions rejected for the fixed step
  int penalty_increases = 0;  ///< SMALBE: times the penalty rho grew
  int preconditioner = 0;     ///< applications of a preconditioner (about the cost of one of F)

  IterationCounts& operator+=(const IterationCounts& other);
};

/// The outcome of one QP solve (CG, MPRGP; SMALBE adds its own).
struct QpResult {
  SolveStatus status = SolveStatus::max_iterations;
  IterationCounts counts;
  double gradient_norm = 0;  ///< at exit: ||gP(x)||_2 (CG: ||Ax - b||_2; SMALBE: of the Lagrangian without penalty)
};

/// One progress line: iteration number (SMALBE: the outer one), projected gradient norm,
/// equality residual norm (0 where there is none), Hessian multiplications of the solve so
/// far, and the number of bounded components above their bound (for the FETI dual: contact
/// rows with a positive multiplier, the contact set; 0 for CG). A monitor receives it; the
/// solvers never print.
struct ProgressLine {
  const char* solver;
  int iteration;
  double gradient_norm;
  double equality_norm;
  int hessian;
  int active;
};
using Monitor = std::function<void(const ProgressLine&)>;

/// Stopping test of an iterative solver, called once per iteration with the iterate x, a
/// gradient and the 2-norm of the projected gradient; true stops with `converged`. The
/// gradient is g = Ax - b for CG and MPRGP; for SMALBE the projected gradient of the
/// Lagrangian without penalty, gP(x, nu, 0), the one its global test weighs.
using StopTest = std::function<bool(const Vec& x, const Vec& g, double gradient_norm)>;

}  // namespace ffeti
