#include "binding/convert.h"

#include "base/errors.h"

#include <algorithm>

namespace ffeti::binding {

namespace {

/// Calls visit(i, j, a) for every stored entry, zero-based, and for the mirror of each
/// off-diagonal one where FreeFEM kept one triangle (sym=1 assembly).
template <class Visit>
void for_each_entry(const HashMatrix<int, double>& hash, Visit&& visit) {
  const int base = hash.fortran;
  for (size_t k = 0; k < hash.nnz; ++k) {
    const int i = hash.i[k] - base, j = hash.j[k] - base;
    visit(i, j, hash.aij[k]);
    if (hash.half && i != j) visit(j, i, hash.aij[k]);
  }
}

/// Offsets of a counting sort: start[b] is where bucket b begins, start[n] the total.
std::vector<int> bucket_starts(std::vector<int> counts) {
  std::vector<int> start(counts.size() + 1, 0);
  for (size_t b = 0; b < counts.size(); ++b) start[b + 1] = start[b] + counts[b];
  return start;
}

}  // namespace

SparseMatrix to_sparse(Matrice_Creuse<double>& matrix, const std::string& name) {
  HashMatrix<int, double>* hash = matrix.pHM();
  if (!hash) throw InputError(name + ": empty matrix (was it assembled?)");
  if (hash->n != hash->m)
    throw InputError(name + ": not square (" + std::to_string(hash->n) + " x " + std::to_string(hash->m) + ")");
  // Compressed columns straight from the hash table's coordinates: two stable counting
  // sorts, by row and then by column, leave every column's rows ascending in O(nnz). Triplets
  // and setFromTriplets took most of a 3D set-up's conversion (1.3 s of 1024 subdomains).
  const int n = hash->n;
  std::vector<int> per_row(static_cast<size_t>(n), 0), per_column(static_cast<size_t>(n), 0);
  for_each_entry(*hash, [&](int i, int j, double) { ++per_row[static_cast<size_t>(i)], ++per_column[static_cast<size_t>(j)]; });
  const std::vector<int> row_start = bucket_starts(std::move(per_row));
  const auto total = static_cast<size_t>(row_start.back());
  std::vector<int> next(row_start.begin(), row_start.end() - 1);
  std::vector<int> row_major_column(total);
  std::vector<double> row_major_value(total);
  for_each_entry(*hash, [&](int i, int j, double a) {
    const auto at = static_cast<size_t>(next[static_cast<size_t>(i)]++);
    row_major_column[at] = j, row_major_value[at] = a;
  });
  const std::vector<int> column_start = bucket_starts(std::move(per_column));
  SparseMatrix result(n, n);
  result.resizeNonZeros(static_cast<Eigen::Index>(total));
  std::copy(column_start.begin(), column_start.end(), result.outerIndexPtr());
  next.assign(column_start.begin(), column_start.end() - 1);
  for (int i = 0; i < n; ++i)  // rows in ascending order: each column's entries arrive sorted
    for (auto e = static_cast<size_t>(row_start[static_cast<size_t>(i)]); e < static_cast<size_t>(row_start[static_cast<size_t>(i) + 1]); ++e) {
      const auto at = static_cast<size_t>(next[static_cast<size_t>(row_major_column[e])]++);
      result.innerIndexPtr()[at] = i;
      result.valuePtr()[at] = row_major_value[e];
    }
  // A hash table holds each (i, j) once; a half matrix storing both triangles would not.
  for (int j = 0; j < n; ++j)
    for (int p = column_start[static_cast<size_t>(j)] + 1; p < column_start[static_cast<size_t>(j) + 1]; ++p)
      if (result.innerIndexPtr()[p] == result.innerIndexPtr()[p - 1])
        throw InputError(name + ": entry (" + std::to_string(result.innerIndexPtr()[p]) + "," + std::to_string(j) +
                         ") stored twice (a one-triangle matrix holding both triangles?)");
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
