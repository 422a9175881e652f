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

/// Restricts v to the face of x on the held disc pairs: on a pair on its circle, v's part
/// along the circle's tangent at x (a move along it slides round the circle, projected back
/// onto it); 0 on a pinned pair. The tangent counts as free: treated as held, a pair slipping
/// on its circle moves only by projected gradient steps, steepest descent (docs/algorithms.md).
void restrict_to_disc_faces(const Vec& x, const ConstraintSet& set, Vec& v);

/// The curvature the circles add to f along their tangents, applied to p: on a pair on its
/// circle whose -g points out (the disc holds it), (max(-n'g, 0) / radius) p_pair, 0
/// elsewhere. A move s along the tangent followed by the projection back changes f by
/// g't s + s^2 (t'At - n'g / radius) / 2 + O(s^3): A plus this term is the Hessian of f round
/// the circle (of the Lagrangian), the one a CG step that slides must use.
Vec circle_curvature(const Vec& x, const Vec& g, const ConstraintSet& set, const Vec& p);

/// Divides v on each pair on its circle by 1 + c / a_norm, c the circle's curvature there
/// (circle_curvature's factor): a diagonal preconditioner for the curvature, which on a pair
/// with a small radius and a large -n'g exceeds ||A|| by orders and would set every CG step.
void precondition_circle_curvature(const Vec& x, const Vec& g, const ConstraintSet& set, double a_norm, Vec& v);

/// Sets v to 0 on the pairs on their circle whose curvature there (circle_curvature's
/// factor) exceeds kStiffCircle = 0.3 times a_norm: their tangent is held
/// rather than free. Such a pair, a row slipping fast under a small bound, turns best by the
/// projected step P(x - abar g), which round its circle is close to Newton's step
/// abar g_t / (||d|| + abar |n'g|); CG round it, the curvature changing with every g, took
/// 231 multiplications of the 3D forced slide against 83.
void hold_stiff_circle_pairs(const Vec& x, const Vec& g, const ConstraintSet& set, double a_norm, Vec& v);
/// Whether any pair is held so (MPGP's proportioning then takes the projected step).
bool has_stiff_circle_pairs(const Vec& x, const Vec& g, const ConstraintSet& set, double a_norm);

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
/// With `slide_on_circles`, the pairs on their circle are left out: p moves them along
/// their tangent (restrict_to_disc_faces), and the step is projected back onto the circle.
double disc_feasible_step(const Vec& x, const Vec& p, const ConstraintSet& set, bool slide_on_circles);

/// Overwrites phit on the disc pairs with the reduced free gradient there,
/// (x - P(x - abar phi)) / abar: the part of the free gradient phi a step abar can take
/// without leaving the disc (on a pair on its circle phi is tangential, and phit the chord
/// the step abar takes round the circle).
void overwrite_disc_reduced_free_gradient(const Vec& x, const Vec& phi, const ConstraintSet& set, double abar,
                                          Vec& phit);

}  // namespace ffeti::qp
