// SMALBE: semimonotonic augmented Lagrangians for bound and equality constraints,
//   min 1/2 x'Hx - b'x  subject to  l_i <= x_i <= u_i  and  C x = 0,
// with MPRGP on the bound-constrained subproblems. The equality constraint enters only
// through Q, the orthogonal projector onto Im C' (C x = 0 <=> Q x = 0); with orthonormal
// rows of C the penalty term rho/2 ||C x||^2 equals rho/2 x'Qx.
#pragma once

#include "qp/mprgp.h"
#include "qp/qp_types.h"

namespace ffeti {

enum class SmalbeVariant {
  seed_alg31,  ///< seed paper Algorithm 3.1: M fixed, rho grows by beta when ||Qx|| > eta
  smalbe_m,    ///< rho fixed ~ ||H||, M shrinks by beta when L increases too little
};

struct SmalbeSettings {
  SmalbeVariant variant = SmalbeVariant::smalbe_m;
  double rho_factor = 1.1;    ///< rho_0 = rho_factor * ||H||
  double M_factor = 1.0;      ///< M_0 = M_factor * ||A||, A = H + rho Q (M has the units of A)
  double eta_factor = 0.1;    ///< eta_0 = eta_factor * ||b||
  double alpha = 0.1;         ///< seed_alg31: eta <- alpha eta when ||Qx|| <= eta
  double beta = 2.0;          ///< smalbe_m: M <- M / beta; seed_alg31: rho <- beta rho
  int max_outer = 200;
  int stall_rounds = 10;      ///< smalbe_m: rho <- beta rho after this many rounds without ||Qx|| < 0.9 its best
  int max_hessian = 20000;    ///< over all inner MPRGP calls
  MprgpSettings inner{};      ///< its max_hessian is overridden by what remains of the above

  void validate() const;
};

struct SmalbeResult : QpResult {
  double equality_norm = 0;            ///< ||Q x||_2 at exit
  double rho = 0;                      ///< final penalty
};

struct SmalbeProblem {
  LinearOperator hessian;                  ///< H, symmetric positive semidefinite
  std::function<void(const Vec&, Vec&)> range_projector;  ///< y = Q x
  const Vec* b = nullptr;
  const Vec* lower = nullptr;              ///< kUnbounded where a component is free
  double hessian_norm = 0;                 ///< upper estimate of ||H||_2
  /// Optional: an SPD approximation of H^{-1} on Ker C. The inner MPRGP then
  /// preconditions in face with P M P + Q / rho (P = I - Q), the inverse's approximation
  /// of H + rho Q.
  LinearOperator preconditioner;
  const Vec* upper = nullptr;              ///< upper bounds (+infinity where none); null: none
  /// In: the multiplier term nu = C'mu to start from (empty: 0); out: the final one. A
  /// sequence of solves of one problem with other bounds (friction's fixed point) starts
  /// each from the last one's x and nu: with x alone the gradient of the Lagrangian at the
  /// start is off by the whole of nu, and every solve costs as much as a cold one. Null: 0.
  Vec* multiplier = nullptr;
};

/// Global stopping test: x, gP(x, nu, 0) (projected gradient of the Lagrangian without
/// penalty) and Q x. Returning true ends the solve with `converged`.
using SmalbeStopTest = std::function<bool(const Vec& x, const Vec& projected_gradient, const Vec& Qx)>;

/// Runs SMALBE from the start x (projected onto the bounds; updated in place).
SmalbeResult smalbe(const SmalbeProblem& problem, Vec& x, const SmalbeSettings& settings,
                    const SmalbeStopTest& stop, const Monitor& monitor = {});

}  // namespace ffeti
