// The statics question of Coulomb friction, asked before its fixed point: can contact forces
// within their friction cones balance the loads on the floating bodies? If not, no load
// step's solution exists (the body slides away), whatever the normal forces turn out to be.
#pragma once

#include "constraints/constraints.h"
#include "feti/coarse_space.h"
#include "feti/free_row_projector.h"

namespace ffeti {

struct CoulombFeasibility {
  /// min ||G lambda - e|| / ||e|| over lambda with lambda_n >= 0 and ||lambda_t|| <= mu
  /// lambda_n per contact row (gluing and Dirichlet multipliers free); -1: undecided (the
  /// iteration neither reached `enough` nor settled).
  double distance = 0;
  /// The body whose rigid modes carry most of the residual G lambda - e at that minimum (-1
  /// when feasible or undecided): the one that would slide.
  int body = -1;
};

/// The free multipliers (gluing, Dirichlet) balance every part of e but the floating bodies'
/// rigid modes (FreeRowProjector: G_F spans all but Im W), so the distance is
/// min ||C lambda_I - W'e|| over the contact rows' cones, C = W'G (k x m, k the bodies'
/// modes: a small, well-conditioned problem where G's rows, the subdomains' modes, made
/// projected gradients on G itself crawl). Accelerated projected gradients (FISTA with
/// restarts) from 0; stops at `enough`, or where the distance stops falling.
/// Unlike the Tresca check (CoarseSpace::feasibility_residual) its answer does not depend on
/// the bounds' normal forces, which Coulomb's fixed point only estimates: bounds of an early
/// iterate may admit no equilibrium where the law does (the 3D block sheared at 0.96 mu P).
/// `bodies[s]`: the body of global subdomain s.
CoulombFeasibility coulomb_feasibility(const CoarseSpace& coarse, const FreeRowProjector& free_rows,
                                       const Constraints& constraints, const Vec& e, const std::vector<int>& bodies,
                                       double enough);

}  // namespace ffeti
