// Where the time of a set-up and a solve went, phase by phase.
#pragma once

namespace ffeti {

struct PhaseTimes {  ///< wall-clock seconds; in a problem's result over several ranks, the slowest rank's
  double constraints = 0, factorization = 0, coarse_space = 0, dual_data = 0;  ///< set-up
  double norm_estimate = 0;   ///< estimating ||H|| (first solve of a system only)
  double free_rows = 0;       ///< building T of coarse "free-rows" (first solve of a system only)
  double solve = 0, recovery = 0, kkt = 0;
  double dual_operator = 0;   ///< the part of solve spent applying F
  double preconditioner = 0;  ///< the part of solve spent applying the preconditioner
  double primal_checks = 0;   ///< the part of solve spent in the stopping test's primal checks
};

}  // namespace ffeti
