// Where the time of a set-up and a solve went, phase by phase.
#pragma once

#include <cstddef>

namespace ffeti {

/// Where the time of a set-up and a solve went, phase by phase.
struct PhaseTimes {  ///< wall-clock seconds; in a problem's result over several ranks, the slowest rank's
  double constraints = 0, factorization = 0, coarse_space = 0, dual_data = 0;  ///< set-up
  double norm_estimate = 0;   ///< estimating ||H|| (first solve of a system only)
  double free_rows = 0;       ///< building T of coarse "free-rows" (first solve of a system only)
  double solve = 0, recovery = 0, kkt = 0;
  double dual_operator = 0;   ///< the part of solve spent applying F
  double preconditioner = 0;  ///< the part of solve spent applying the preconditioner
  double primal_checks = 0;   ///< the part of solve spent in the stopping test's primal checks
  double hessian = 0;         ///< the part of solve in the solver's Hessian multiplications (F, projections)
  double factor_solves = 0;   ///< of dual_operator, the subdomain solves (thread-seconds: DualOperator)

  /// Several solves of one problem (friction's fixed point) add up phase by phase.
  PhaseTimes& operator+=(const PhaseTimes& o) {
    double* mine[] = {&constraints, &factorization, &coarse_space, &dual_data, &norm_estimate, &free_rows, &solve,
                      &recovery, &kkt, &dual_operator, &preconditioner, &primal_checks, &hessian, &factor_solves};
    const double* theirs[] = {&o.constraints, &o.factorization, &o.coarse_space, &o.dual_data, &o.norm_estimate,
                              &o.free_rows, &o.solve, &o.recovery, &o.kkt, &o.dual_operator, &o.preconditioner,
                              &o.primal_checks, &o.hessian, &o.factor_solves};
    for (size_t k = 0; k < sizeof(mine) / sizeof(mine[0]); ++k) *mine[k] += *theirs[k];
    return *this;
  }
};

}  // namespace ffeti
