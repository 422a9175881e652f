// Derivatives of the contact rows (B'_I, c'_I) when the contact geometry moves with the
// design: node-to-segment normals, projection weights and gaps, obstacle gaps.
#pragma once

#include "feti/constraints.h"
#include "parallel/communicator.h"

#include <vector>

namespace ffeti {

/// The derivative of one contact row: entries of B'_i over (subdomain, dof) and c'_i.
struct RowDerivative {
  std::vector<ConstraintEntry> entries;
  double rhs = 0;
};

/// For every inequality row of `constraints` (index i - equality_rows), the derivative of
/// the row under node velocities `velocity_x/_y` (this rank's subdomains, `global_ids`;
/// empty: nothing moves). Each row keeps its pairing (segment and slave): the derivative
/// of the linearized condition with the projection parameter xi unclamped. Computed by
/// central differences of the row's closed form (node_to_segment_row, obstacle_row) with a
/// step of 1e-6 of the segment length (truncation ~1e-12, round-off ~1e-10 relative): no
/// assembly. Node-to-node rows do not depend on positions. Collective: the velocities of
/// the contact nodes are gathered, so every rank gets every row.
std::vector<RowDerivative> contact_row_derivatives(const Constraints& constraints,
                                                   const std::vector<int>& global_ids,
                                                   const std::vector<std::vector<double>>& velocity_x,
                                                   const std::vector<std::vector<double>>& velocity_y,
                                                   const Communicator& comm);

}  // namespace ffeti
