#include "constraints/constraint_triplets.h"

#include "base/errors.h"

namespace ffeti {

ConstraintTriplets constraint_triplets(const Constraints& c, const std::vector<SubdomainInput>& inputs,
                                       FetiVariant variant, int processes) {
  if (processes > 1) throw InputError("P: fetiConstraints runs in one process only");
  if (variant == FetiVariant::feti1)
    throw InputError("P: fetiConstraints needs variant=\"tfeti\" (FETI-1 eliminates the Dirichlet dofs, "
                     "so their conditions are no rows)");
  std::vector<long> offset(1, 0);
  for (const SubdomainInput& in : inputs) offset.push_back(offset.back() + in.K.rows());
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
