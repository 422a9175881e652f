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
  int stall_rounds = 10;      ///< smalbe_m: rho <- beta rho after this many rounds without ||Qx|| < 0.9 its best
  /// smalbe_m: where the plain updates crawl, balance the modes that only bounded blocks hold
  /// by their rigid-plastic model (Problem::equality_rows; qp/held_modes.h), safeguarded.
  bool balance_held_modes = true;
  MprgpSettings inner{};      ///< of every inner MPRGP call (each gets what remains of the budget)

  void validate() const;
};

struct SmalbeResult : QpResult {
  double equality_norm = 0;            ///< ||Q x||_2 at exit
  double rho = 0;                      ///< final penalty
  Vec multiplier;                      ///< final multiplier term nu = C'mu (the next solve's
                                       ///< Problem::equality_multiplier)
};

/// Runs SMALBE on the problem (its bounds and its equality part `range_projector`, which it
/// needs) from the start x (projected onto the bounds; the last iterate on return) and the
/// multiplier term `problem.equality_multiplier` (empty: 0). `problem.hessian_norm` is an
/// upper estimate of ||H||_2. With `problem.preconditioner` M, an SPD approximation of H^{-1}
/// on Ker C, the inner MPRGP preconditions in face with P M P + Q / rho (P = I - Q), the
/// inverse's approximation of H + rho Q. The inner MPRGP calls charge the budget.
/// `stop` receives x, gP(x, nu, 0) (the projected gradient of the Lagrangian without
/// penalty) and its 2-norm; true ends the solve with `converged`.
SmalbeResult smalbe(const qp::Problem& problem, const SmalbeSettings& settings, Vec& x, qp::Budget& budget,
                    const StopTest& stop, const Monitor& monitor = {});

}  // namespace ffeti
