// What a dual solve returns, and Coulomb's statics check.
#pragma once

#include "feti/dual_path.h"
#include "feti/phase_times.h"
#include "qp/qp_types.h"

#include <vector>

namespace ffeti {

struct DualSolution {
  SolveStatus status = SolveStatus::invalid_input;
  DualPath path = DualPath::cholesky;  ///< the path taken
  IterationCounts counts;
  double gradient_norm = 0;      ///< final ||gP|| (absolute) and its reference ||b||
  double gradient_reference = 0;
  double equality_norm = 0;      ///< final ||G lambda - e|| and its reference ||e||
  double equality_reference = 0;
  double violation = -1;         ///< relative_kkt: the last check's measure (-1: no check ran)
  int scale_evaluations = 0;     ///< relative_kkt: primal checks (a K^+ application each)
  long dual_operator_applications = 0;  ///< columns F was applied to in the solve (times.dual_operator's)
  Vec lambda;                    ///< multipliers, rows ordered as constraints()
  /// SMALBE path: the solver's final multiplier term of the equality part (qp/smalbe.h);
  /// empty on the other paths. The next solve of the same system with other bounds starts
  /// from it (DualWarmStart).
  Vec equality_multiplier;
  std::vector<Vec> u;            ///< primal solution per subdomain of this rank
  PhaseTimes times;              ///< this rank's: norm_estimate, free_rows, solve (and its parts), recovery
};

/// Coulomb's statics check (DualSystem::coulomb_feasibility).
struct CoulombFeasibility {
  /// min ||G lambda - e|| / ||e|| over lambda with lambda_n >= 0 and ||lambda_t|| <= mu
  /// lambda_n per contact row (gluing and Dirichlet multipliers free); -1: undecided.
  double distance = 0;
  /// The body whose rigid modes carry most of the residual at that minimum (-1 when
  /// feasible or undecided): the one that would slide.
  int body = -1;
};

}  // namespace ffeti
