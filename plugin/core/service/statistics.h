// The statistics of a solve as named numbers, in one fixed order: what fetiInfo returns
// by key and fetiReport prints as "key=value" pairs.
#pragma once

#include "feti/feti_problem.h"
#include "feti/friction.h"

#include <string>
#include <utility>
#include <vector>

namespace ffeti {

using Statistics = std::vector<std::pair<std::string, double>>;

/// Dimensions and setup times of the problem, and (when `result` is given) the solve's
/// status code (0 = converged, see status_code), counts, residuals, energy and times.
Statistics statistics(const FetiProblem& problem, const FetiResult* result);

/// 0 converged, 1 max_iterations, 2 stagnated, 3 not_positive_definite, 4 infeasible,
/// 5 invalid_input, 6 weakly_active: the integer fetiSolve (and the sensitivity calls) return.
int status_code(SolveStatus status);

/// One contact row: the position of its slave dof and its multiplier (the contact force).
struct ContactMultiplier {
  double x, y, lambda;
  double z = 0;                              ///< the slave node's third coordinate (0 in a plane problem)
  double tangential = 0;                     ///< the friction row's multiplier (0 without one); 3D: along t1
  double second_tangential = 0;              ///< 3D: the friction force along t2 (tangent_pair); 0 in the plane
  ContactState state = ContactState::open;   ///< open, stick or slip (friction.h)
  Point3 normal{0, 0, 0};                    ///< the row's unit normal (ContactRowGeometry::normal)
  std::array<Point3, 2> tangents{};          ///< t1, t2 (ContactRowGeometry::tangents; t2 = 0 in the plane)
  double slip = 0, second_slip = 0;          ///< the slip of the last step along t1, t2 (0 without friction rows)
};
/// The contact rows in row order, with the multipliers of `result` (0 without one: the
/// positions alone, known from the set-up) and, with friction, the friction forces and states.
std::vector<ContactMultiplier> contact_multipliers(const FetiProblem& problem, const FetiResult* result);

/// The Hessian multiplications of each Tresca solve of a solve with friction, comma
/// separated ("73,56,14,23"; empty without friction).
std::string friction_counts(const FetiResult& result);

/// One line "RANK rank=r subdomains=... primal=... time_factor=... time_solve=...
/// peak_memory_mb=..." per rank: the load balance (subdomains, unknowns) and per-rank times.
std::string format_rank_report(const FetiProblem& problem);

/// "key=value key=value ..." with the path and status as words.
std::string format_report(const FetiProblem& problem, const FetiResult* result);

}  // namespace ffeti
