// Friction in the dual (docs/algorithms.md, "Friction"): Tresca is one dual solve with the
// friction rows' multipliers in [-g, g] (in 3D each pair in the disc of radius g); Coulomb is the fixed point of the seed's reference
// [DHK00] over Tresca solves, g = mu lambda_n of the previous one.
#pragma once

#include "feti/dual_system.h"

#include <vector>

namespace ffeti {

/// Coulomb's law (its coefficients: Constraints::coulomb_coefficient), or Tresca's with its
/// bound per friction row (slipBound=, slipBoundField=; Constraints::slip_bound).
struct FrictionLaw {
  bool tresca = false;
  Vec slip_bound;  ///< Tresca: g per friction row (>= 0)
  bool coulomb() const { return !tresca; }
};

/// The Coulomb fixed point stops when a Tresca solve to the user's tol gives
/// ||g_new - g||_inf <= tol ||g_new||_inf: its answer meets the stopping test and the law to
/// tol. Earlier solves stop looser (the first at max(tol, 1e-2), or 0.3 from the bounds of a
/// start, the last load step's multipliers, settled in at most one face solve; each later one
/// at max(tol, 0.01 times the last relative change of the bounds)), and start from the last
/// one's multipliers without settling them (in a plane problem a slipping row's force moved
/// onto its new bound). Beyond DualSolveSettings::friction_iterations Tresca solves, or once
/// their Hessian multiplications together reach DualSolveSettings::max_hessian (maxit holds
/// over the whole solve), it reports max_iterations; a Tresca solve stopped at round-off
/// raises the target to the residual it reached, and the fixed point ends stagnated there.

/// A solve with friction: the last Tresca solve (its lambda, u and status; counts and times
/// summed over all of them) and what the fixed point adds.
struct FrictionSolution {
  DualSolution dual;
  Vec slip_bound;                  ///< g of the last Tresca solve, per friction row
  int iterations = 0;              ///< Tresca solves (1 for Tresca)
  std::vector<int> hessian;        ///< Hessian multiplications of each
  double bound_change = 0;         ///< Coulomb: the last ||g_new - g||_inf / ||g_new||_inf
  int sliding_body = -1;           ///< Coulomb, infeasible: the body that would slide away (-1: none named)
  int newton_steps = 0;            ///< Coulomb by Newton (DualSolveSettings::coulomb): its steps
  int newton_hessian = 0;          ///< ... and their multiplications (in dual.counts too)
};

/// Solves with friction from `start` (multipliers of the last load step; empty: none, and
/// the first Coulomb solve has no bound: it sticks everywhere). `data` are the state
/// problem's (its slip_bound is set here); `bodies[s]` the body of global subdomain s.
/// Coulomb's law is first asked whether forces within the friction cones can balance the
/// loads on the floating bodies (DualSystem::coulomb_feasibility): if not, the status is infeasible at
/// once, naming the body. A Tresca solve of the fixed point whose bounds admit no equilibrium
/// (an iterate's normal forces, not the law's) is then not final: the bounds are widened to
/// those of the last converged solve where these are smaller (infinite before any). With
/// Newton (DualSolveSettings::coulomb), its steps follow the first solve with finite bounds;
/// the answer they converge to starts the next Tresca solve, at tol, which must give back its
/// bounds within tol as in the fixed point (else the fixed point goes on). Collective.
FrictionSolution solve_with_friction(const DualSystem& dual, DualData data, const FrictionLaw& law,
                                     DualSolveSettings settings, const Vec& start, const std::vector<int>& bodies);

/// The tolerance of the fixed point's next Tresca solve after one that stopped at `last`
/// and moved the bounds by `bound_change` (relative): kBoundFollowing (0.01) times that
/// change, no looser than `last`, at most ten times tighter (kLargestTightening), never below
/// `reachable` (the user's tol, or the residual a stagnated solve reached); within rounding
/// of `reachable`, exactly `reachable`, which ends the fixed point once the bounds hold.
double next_tresca_tolerance(double last, double bound_change, double reachable);

/// The contact state of each contact row (fetiContact; docs/algorithms.md, "Friction"):
/// open: no force at all (lambda_n = 0 and no friction force); stick: a force, its friction
/// force inside its bound (||lambda_t|| < g, or no friction row); slip: at its bound
/// (at_slip_bound). A Tresca row acts whether closed or not (its bound does not depend on
/// lambda_n), so a row that carries a friction force is never open, even with lambda_n = 0.
enum class ContactState { open = 0, stick = 1, slip = 2 };
struct ContactRowForces {
  std::vector<double> tangential;         ///< lambda_t per contact row (0 without friction rows); 3D: along t1
  std::vector<double> second_tangential;  ///< 3D: lambda_t along t2 (tangent_pair); 0 in a plane problem
  std::vector<double> slip;               ///< the slip of the step along t1, (B u - c) on the friction row; 0 without
  std::vector<double> second_slip;        ///< 3D: along t2; 0 in a plane problem
  std::vector<ContactState> state;
};
/// `slip`: B u - c on the friction rows (FetiResult::slip), empty before a solve.
ContactRowForces contact_row_forces(const Constraints& constraints, const Vec& lambda, const Vec& slip_bound,
                                    const Vec& slip = Vec());

}  // namespace ffeti
