#include "feti/dirichlet.h"

namespace ffeti {
namespace {

std::vector<char> dof_mask(Eigen::Index n, const std::vector<int>& dofs) {
  std::vector<char> mask(static_cast<size_t>(n), 0);
  for (int dof : dofs) mask[static_cast<size_t>(dof)] = 1;
  return mask;
}

}  // namespace

SparseMatrix eliminate_dirichlet(const SparseMatrix& K, const std::vector<int>& dofs) {
  SparseMatrix result = K;
  const std::vector<char> fixed = dof_mask(K.rows(), dofs);
  for (int j = 0; j < result.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(result, j); it; ++it)
      if ((fixed[static_cast<size_t>(j)] || fixed[static_cast<size_t>(it.row())]) && it.row() != j)
        it.valueRef() = 0.0;
  result.prune(0.0);
  result.makeCompressed();
  return result;
}

Vec eliminated_load(const SparseMatrix& K, const Vec& f, const std::vector<int>& dofs,
                    const std::vector<double>& values) {
  Vec g = Vec::Zero(K.rows());
  for (size_t k = 0; k < dofs.size(); ++k) g[dofs[k]] = values.empty() ? 0.0 : values[k];
  Vec result = f - K.selfadjointView<Eigen::Lower>() * g;  // move the known values to the right-hand side
  for (int dof : dofs) result[dof] = K.coeff(dof, dof) * g[dof];
  return result;
}

}  // namespace ffeti
