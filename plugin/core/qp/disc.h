// The geometry of disc blocks (isotropic friction's constraint set, ALGORITHMS.md section 11)
// as MPGP needs it: each pair x_i, x_i+1 of a disc block lies in ||x_pair - c|| <= g. The
// solvers run their per-component code first, which sees disc components as free, and then
// these functions correct the disc pairs; a set without discs never calls them.
#pragma once

#include "qp/problem.h"

#include <vector>

namespace ffeti::qp {

/// First component of every disc pair of x not strictly inside its disc: on the circle (to
/// a relative 1e-12, so that a pair projected onto it counts as there despite round-off) or
/// pinned by a radius 0. Together with the half-line and box bounds they form the active set.
std::vector<Eigen::Index> held_disc_pairs(const Vec& x, const ConstraintSet& set);

/// Sets v to 0 on the held disc pairs of x (restricts v to the free set there).
void zero_held_disc_pairs(const Vec& x, const ConstraintSet& set, Vec& v);

/// Moves every disc pair outside its disc radially onto the circle (the Euclidean
/// projection); returns how many pairs moved.
int project_onto_discs(Vec& x, const ConstraintSet& set);

/// Overwrites gp on the disc pairs with the projected gradient there: g inside the disc;
/// on the circle, with n the outward unit normal, g - min(n'g, 0) n (minus the projection of
/// -g onto the tangent cone {d : n'd <= 0}: the normal part goes only where it points inward);
/// 0 on a pinned pair.
void overwrite_disc_projected_gradient(const Vec& x, const Vec& g, const ConstraintSet& set, Vec& gp);

/// Largest a >= 0 with every disc pair of x - a p in its disc: the larger root of
/// ||d - a p||^2 = g^2, d = x_pair - c (0 for a pair on or outside its circle moving out).
double disc_feasible_step(const Vec& x, const Vec& p, const ConstraintSet& set);

/// Overwrites phit on the disc pairs with the reduced free gradient there,
/// (x - P(x - abar phi)) / abar: the part of the free gradient phi a step abar can take
/// without leaving the disc (phi is 0 on held pairs, and so is phit).
void overwrite_disc_reduced_free_gradient(const Vec& x, const Vec& phi, const ConstraintSet& set, double abar,
                                          Vec& phit);

}  // namespace ffeti::qp
