// FETI-1 treatment of Dirichlet conditions: elimination inside K_s.
#pragma once

#include "constraints/problem_input.h"

namespace ffeti {

/// Zeroes the rows and columns of the Dirichlet dofs except the diagonal, which keeps its
/// value so that the scaling of K is unchanged. The matrix stays symmetric and becomes
/// regular on any connected subdomain with a Dirichlet dof. The storage is kept (a lower
/// triangle stays one).
SparseMatrix eliminate_dirichlet(const SparseMatrix& K, const std::vector<int>& dofs);

/// The load that goes with eliminate_dirichlet: f - K[:,D] g, and K_DD g on the Dirichlet
/// dofs, so that the solution takes the values g there. Reads K's lower triangle only.
Vec eliminated_load(const SparseMatrix& K, const Vec& f, const std::vector<int>& dofs,
                    const std::vector<double>& values);

}  // namespace ffeti
