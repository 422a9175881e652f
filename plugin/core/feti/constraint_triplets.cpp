#include "feti/constraint_triplets.h"

#include "base/errors.h"

namespace ffeti {

ConstraintTriplets constraint_triplets(const FetiProblem& problem) {
  if (problem.communicator().size() > 1) throw InputError("P: fetiConstraints runs in one process only");
  if (problem.variant() == FetiVariant::feti1)
    throw InputError("P: fetiConstraints needs variant=\"tfeti\" (FETI-1 eliminates the Dirichlet dofs, "
                     "so their conditions are no rows)");
  std::vector<long> offset(1, 0);
  for (const SubdomainInput& in : problem.inputs()) offset.push_back(offset.back() + in.K.rows());
  const Constraints& c = problem.constraints();
  ConstraintTriplets t;
  t.rhs = c.rhs;
  for (int row = 0; row < c.rows(); ++row) {
    t.kind.push_back(static_cast<long>(c.kind[static_cast<size_t>(row)]));
    for (int e = c.row_start[static_cast<size_t>(row)]; e < c.row_start[static_cast<size_t>(row) + 1]; ++e) {
      const ConstraintEntry& entry = c.entries[static_cast<size_t>(e)];
      t.rows.push_back(row);
      t.columns.push_back(offset[static_cast<size_t>(entry.subdomain)] + entry.dof);
      t.values.push_back(entry.coefficient);
    }
  }
  return t;
}

}  // namespace ffeti
