// The constraint rows of a set-up problem as one matrix over the undivided dofs, for a
// solver of the undivided problem (the peers of the benchmarks, fetiConstraints).
#pragma once

#include "constraints/constraints.h"

#include <vector>

namespace ffeti {

/// B u = c (equality rows) and B u <= c (contact rows) over the dofs of all subdomains
/// numbered one after the other in subdomain order, as triplets.
struct ConstraintTriplets {
  std::vector<long> rows, columns;
  std::vector<double> values;
  std::vector<double> rhs;    ///< c, per row
  std::vector<long> kind;     ///< per row: 0 gluing, 1 Dirichlet, 2 contact (RowKind)
};

/// The rows of a problem over `inputs` (all its subdomains, in order) set up with `variant`
/// on `processes` ranks. InputError unless it runs in one process with Total FETI (FETI-1
/// eliminates the Dirichlet dofs, so their conditions are no rows).
ConstraintTriplets constraint_triplets(const Constraints& c, const std::vector<SubdomainInput>& inputs,
                                       FetiVariant variant, int processes);

}  // namespace ffeti
