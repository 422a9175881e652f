#include "binding/convert.h"

#include "base/errors.h"

namespace ffeti::binding {

SparseMatrix to_sparse(Matrice_Creuse<double>& matrix, const std::string& name) {
  HashMatrix<int, double>* hash = matrix.pHM();
  if (!hash) throw InputError(name + ": empty matrix (was it assembled?)");
  if (hash->n != hash->m)
    throw InputError(name + ": not square (" + std::to_string(hash->n) + " x " + std::to_string(hash->m) + ")");
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(hash->nnz * (hash->half ? 2 : 1));
  const int base = hash->fortran;
  for (size_t k = 0; k < hash->nnz; ++k) {
    const int i = hash->i[k] - base, j = hash->j[k] - base;
    entries.emplace_back(i, j, hash->aij[k]);
    if (hash->half && i != j) entries.emplace_back(j, i, hash->aij[k]);  // the other triangle
  }
  SparseMatrix result(hash->n, hash->n);
  result.setFromTriplets(entries.begin(), entries.end());
  result.makeCompressed();
  return result;
}

Vec to_vec(const KN<double>& values) {
  Vec result(values.N());
  for (long k = 0; k < values.N(); ++k) result[k] = values[k];
  return result;
}

std::vector<double> to_std(const KN<double>& values) {
  std::vector<double> result(static_cast<size_t>(values.N()));
  for (long k = 0; k < values.N(); ++k) result[static_cast<size_t>(k)] = values[k];
  return result;
}

std::vector<int> to_indices(const KN<long>& values, long bound, const std::string& name) {
  std::vector<int> result;
  for (long k = 0; k < values.N(); ++k) {
    if (values[k] < 0 || values[k] >= bound)
      throw InputError(name + ": entry " + std::to_string(k) + " is " + std::to_string(values[k]) +
                       ", outside 0.." + std::to_string(bound - 1));
    result.push_back(static_cast<int>(values[k]));
  }
  return result;
}

std::vector<std::vector<int>> per_subdomain(const KN<KN<long>>* lists, long count, const std::vector<int>& ids,
                                            const std::vector<long>& bounds, const std::string& name) {
  if (!lists) return {};
  if (lists->N() != count)
    throw InputError(name + ": has " + std::to_string(lists->N()) + " entries for " + std::to_string(count) +
                     " subdomains");
  std::vector<std::vector<int>> result;
  for (size_t k = 0; k < ids.size(); ++k)
    result.push_back(to_indices((*lists)[ids[k]], bounds[k], name + "[" + std::to_string(ids[k]) + "]"));
  return result;
}

void copy_to(const Vec& from, KN<double>& to) {
  to.resize(from.size());
  for (Eigen::Index k = 0; k < from.size(); ++k) to[k] = from[k];
}

void copy_to(const std::vector<double>& from, KN<double>& to) {
  to.resize(static_cast<long>(from.size()));
  for (size_t k = 0; k < from.size(); ++k) to[static_cast<long>(k)] = from[k];
}

void copy_to(const std::vector<long>& from, KN<long>& to) {
  to.resize(static_cast<long>(from.size()));
  for (size_t k = 0; k < from.size(); ++k) to[static_cast<long>(k)] = from[k];
}

}  // namespace ffeti::binding
