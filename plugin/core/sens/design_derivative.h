// What a front end hands to the sensitivity analysis for one design direction beta: the
// directional derivatives of the assembled data (seed eq. 12), for this rank's subdomains.
#pragma once

#include "constraints/problem_input.h"

#include <vector>

namespace ffeti {

/// Per local subdomain (same order as the problem's local subdomains). An empty entry
/// means zero: a subdomain the design does not move has an empty K' and f'.
/// - dK: K'_s, symmetric, full storage, the same size as K_s;
/// - df: f'_s;
/// - velocity_x, velocity_y, velocity_z (three dimensions): the derivative of each dof's
///   node position, which moves the contact geometry (normals, weights and gaps of
///   node-to-segment, node-to-face and obstacle rows).
///   Empty on every subdomain: the contact geometry does not move.
/// - dgap: the derivative of ContactInput::gap_field (one value per dof, read where the
///   gap is read): a design that changes the gaps themselves, e.g. a contact profile
///   described by its gap. Empty on every subdomain: the gaps do not change.
/// Prescribed Dirichlet values, gluing and the scalar node-to-node gap are design independent.
struct DesignDerivative {
  std::vector<SparseMatrix> dK;
  std::vector<Vec> df;
  std::vector<std::vector<double>> velocity_x, velocity_y, velocity_z;
  std::vector<std::vector<double>> dgap;
};

}  // namespace ffeti
