// Derivatives of the contact rows (B'_I, c'_I) when the contact geometry moves with the
// design: node-to-segment and node-to-face normals, projection weights and gaps, obstacle gaps.
#pragma once

#include "constraints/constraints.h"
#include "parallel/communicator.h"

#include <vector>

namespace ffeti {

/// The derivative of one contact row: entries of B'_i over (subdomain, dof) and c'_i.
struct RowDerivative {
  std::vector<ConstraintEntry> entries;
  double rhs = 0;
  bool one_sided = false;  ///< a row in use whose derivative is one-sided (ContactRowGeometry::one_sided_under)
};

/// Node velocities x, y, z: per local subdomain one value per dof, read at each node's x
/// dof (empty lists or entries: zero; z: three dimensions only).
using NodeVelocities = std::array<const std::vector<std::vector<double>>*, 3>;

/// For every inequality row of `constraints` (index i - equality_rows), the derivative of
/// the row under the node velocities (this rank's subdomains, `global_ids`; empty: nothing
/// moves). Each row keeps its pairing (segment or face, and slave): the derivative of the
/// linearized condition with the projection unclamped. Computed by central differences of
/// the row's closed form (ContactRowGeometry::row_at of its kind) with a step of 1e-6 of
/// its length() (truncation ~1e-12, round-off ~1e-10 relative): no assembly. Rows without
/// moving nodes (node to node) do not depend on positions; kinds without a derivative are
/// refused before (capability_table()). A row in use (`in_use`, per inequality row: the
/// sensitivity keeps it or it carries a force) whose motion gives no two-sided derivative
/// (ContactRowGeometry::unverified_motion) is refused, one whose derivative is one-sided
/// though its pairing holds is marked (RowDerivative::one_sided); the others' derivatives go
/// unused.
/// Collective: the velocities of the contact nodes are gathered, so every rank gets every row.
std::vector<RowDerivative> contact_row_derivatives(const Constraints& constraints,
                                                   const std::vector<int>& global_ids,
                                                   const NodeVelocities& velocities, const std::vector<bool>& in_use,
                                                   const Communicator& comm);

}  // namespace ffeti
