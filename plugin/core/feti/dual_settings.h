// What a caller asks of a dual solve: tolerance, stopping test, budget, start and the
// solvers' own settings.
#pragma once

#include "feti/dual_path.h"
#include "qp/stopping_test.h"
#include "qp/norm_estimate.h"
#include "qp/smalbe.h"

namespace ffeti {

/// How the SMALBE path meets the coarse constraints G lambda = e (docs/algorithms.md).
enum class CoarseConstraints {
  penalty,    ///< all rows of G by SMALBE's augmented Lagrangian, on P F P
  free_rows,  ///< the rows the free multipliers can meet by the oblique projector T; the rest by SMALBE
};

/// Stopping test of every path (docs/algorithms.md): by default (relative_kkt) the recovered
/// u(lambda) violates no constraint by more than tolerance ||u||_inf,
/// or the seed's  ||gP||_2 <= tolerance ||b||_2,  b = P(d - F lambda~) (T'b with coarse
/// free_rows: the gradient at the start);  and on both, where there is a coarse space,
/// ||G lambda - e||_2 <= tolerance ||e||_2.

/// The relative distance min ||G lambda - e|| / ||e|| over lambda_I >= 0 below which a scene
/// counts as feasible whatever tol: MPRGP on G'G resolves it only to about 1e-11 (a feasible
/// spanner gave 1.3e-11, depending on the expansion steps), so a smaller tol must not turn
/// that round-off into "infeasible"; infeasible scenes are off by far more (docs/algorithms.md).
constexpr double kFeasibilityResolution = 1e-8;

/// How Coulomb's law is solved (feti/friction.h): by the fixed point over Tresca solves, or by
/// semismooth Newton steps after its first solve (feti/coulomb_newton.h) and the fixed point's
/// check of their answer; `automatic`: Newton in a plane problem, the fixed point in three
/// dimensions (where Newton's closed set churns near full slip: docs/log.md, 2026-12-08).
enum class CoulombMethod { automatic, fixed_point, newton };

struct DualSolveSettings {
  double tolerance = 1e-4;
  /// The relative distance from equilibrium below which the loads count as balanced by
  /// multipliers within their bounds (the Farkas check before SMALBE); 0: `tolerance`. A
  /// solve with a tolerance looser than the user's (Coulomb's early Tresca solves) keeps
  /// the user's here: at its own it let a pull of 1.01 mu W through to maxit.
  double feasibility_tolerance = 0;
  CoarseConstraints coarse_constraints = CoarseConstraints::free_rows;
  StoppingTest stopping = StoppingTest::relative_kkt;
  int max_hessian = 10000;          ///< over the whole solve (friction: over all its Tresca solves)
  SmalbeSettings smalbe{};          ///< used on the SMALBE path
  MprgpSettings mprgp{};            ///< used on the MPRGP path and inside SMALBE
  NormEstimateSettings norm_estimate{};
  Monitor monitor{};
  /// Seed test: measure ||gP|| against max(||b||, ||B K^+ f||) instead of ||b||: for right-hand sides
  /// whose b is small after cancellation (a sensitivity load f' - K'u in near equilibrium),
  /// ||b|| lies below the round-off of the data it came from, and a tolerance relative to it
  /// cannot be reached.
  bool reference_includes_data = false;
  /// Multipliers to start from (rows as constraints()), e.g. a previous solve's lambda or
  /// one interpolated from a coarser mesh; empty: lambda = 0 (lambda~ where bodies float).
  /// Moved onto the constraints' feasible set first, so any values of the right size do.
  Vec start;
  /// Face solves that settle a given start before MPRGP (qp/start_settling.h); 0: MPRGP
  /// from the start as given. Ignored without a start. 2: measured, docs/results/large-contact.md.
  int settle = 2;
  /// Coulomb friction: Tresca solves of the fixed point at most (feti/friction.h).
  int friction_iterations = 50;
  CoulombMethod coulomb = CoulombMethod::automatic;
  /// Throws InputError naming the setting; returns the budget of `max_hessian` for the
  /// user call (qp/budget.h), made here once and passed down to every solve of the call.
  qp::Budget validate() const;
};

}  // namespace ffeti
