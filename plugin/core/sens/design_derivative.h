// What a front end hands to the sensitivity analysis for one design direction beta: the
// directional derivatives of the assembled data (seed eq. 12), for this rank's subdomains.
#pragma once

#include "feti/problem_input.h"

#include <vector>

namespace ffeti {

/// Per local subdomain (same order as the problem's local subdomains). An empty entry
/// means zero: a subdomain the design does not move has an empty K' and f'.
/// - dK: K'_s, symmetric, full storage, the same size as K_s;
/// - df: f'_s;
/// - velocity_x, velocity_y: the derivative of each dof's node position, which moves the
///   contact geometry (normals, weights and gaps of node-to-segment and obstacle rows).
///   Empty on every subdomain: the contact geometry does not move.
/// Prescribed Dirichlet values, gluing and node-to-node gaps are design independent.
struct DesignDerivative {
  std::vector<SparseMatrix> dK;
  std::vector<Vec> df;
  std::vector<std::vector<double>> velocity_x, velocity_y;
};

}  // namespace ffeti
