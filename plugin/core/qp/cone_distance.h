// The distance from a target to the image of a product of convex cones: min ||C x - t|| over
// x in the cones, by accelerated projected gradients (FISTA with function-value restarts).
// Coulomb's statics check asks it of the friction cones (feti/dual_system.cpp).
#pragma once

#include "qp/qp_types.h"

#include <Eigen/Dense>

#include <functional>

namespace ffeti::qp {

/// Euclidean projection of (n, t) onto the cone {||t|| <= mu n} of half-angle atan(mu) about
/// the axis n: itself inside, 0 in the polar cone {mu ||t|| <= -n}, else the nearest ray.
/// `t` holds `tangents` entries.
void project_onto_cone(double& n, double* t, int tangents, double mu);

struct ConeDistance {
  double distance = 0;  ///< min ||C x - t|| / scale found; -1: undecided (still falling after the step limit)
  Vec x;                ///< the iterate that reached it
};

/// From x = 0 (which `project` must leave in the cones). Stops at the first iterate within
/// `enough` (relative to `scale`), or once the best distance fell by less than 0.1 % over the
/// last half of the steps (from 256 steps on: a distance that has settled above `enough`).
ConeDistance cone_distance(const Eigen::MatrixXd& C, const Vec& target, const std::function<void(Vec&)>& project,
                           double scale, double enough);

}  // namespace ffeti::qp
