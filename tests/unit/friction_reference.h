// The undivided problem's dual with friction, dense, for the friction tests: H = B K_ff^-1 B'
// with K_ff the free block of a dense K, solved by accelerated projected gradient onto
// half-lines (normal multipliers) and intervals or discs (each contact row's friction
// multipliers). It shares no code with qp/ or the constraint builder: the rows are written
// by the tests from the nodes' positions.
#pragma once

#include "constraints/problem_input.h"

#include <Eigen/Dense>

#include <vector>

namespace ffeti {

/// A contact row over all dofs of the undivided problem: normal.u <= gap, and its slip rows
/// tangents[k].u (one in the plane, two in 3D) whose multipliers keep ||lambda_t|| <= bound.
struct ReferenceRow {
  Vec normal;
  double gap = 0;
  std::vector<Vec> tangents;
  double bound = 0;
};

/// Per row: lambda_n and lambda_t (the tangents' multipliers, in their order).
struct ReferenceForces {
  double normal = 0;
  std::vector<double> tangential;
};

/// min 1/2 u'Ku - f'u subject to the rows and the fixed dofs' values, through its dual:
/// min 1/2 l'Hl - d'l over lambda_n >= 0, ||lambda_t|| <= g, by projected gradient with
/// Nesterov's momentum (restarted when a step turns back, O'Donoghue and Candes) until the
/// iterate stops moving. Rows' entries on fixed dofs move to their right-hand sides.
std::vector<ReferenceForces> friction_dual(const Eigen::MatrixXd& K, const Vec& f, const std::vector<int>& fixed,
                                           const std::vector<double>& fixed_values, const std::vector<ReferenceRow>& rows);

/// `body` reflected through the plane of its last coordinate = 0 (y in the plane, z in 3D):
/// its positions, the stiffness D K D and the Dirichlet values D v with D = -1 on the last
/// component's dofs. A mirror image of a mesh is a mesh, and isotropic elasticity is
/// invariant under reflections.
SubdomainInput mirrored(SubdomainInput body);

}  // namespace ffeti
