// Conversions between FreeFEM's script types and the core's types. No numerics here.
#pragma once

#include "ff++.hpp"

#include "constraints/problem_input.h"

#include <string>
#include <vector>

namespace ffeti::binding {

/// A FreeFEM sparse matrix as a full (both triangles) Eigen matrix; `half` storage
/// (sym=1 assembly) is expanded. `name` is used in error messages, e.g. "K[3]".
SparseMatrix to_sparse(Matrice_Creuse<double>& matrix, const std::string& name);

Vec to_vec(const KN<double>& values);
std::vector<double> to_std(const KN<double>& values);
/// Integer list; throws InputError naming `name` for an entry outside [0, bound).
std::vector<int> to_indices(const KN<long>& values, long bound, const std::string& name);

/// The entries of an optional int[int][int] argument (nullptr: none) for the subdomains
/// `ids` of this rank, each checked against the subdomain's dof count `bounds[k]`.
std::vector<std::vector<int>> per_subdomain(const KN<KN<long>>* lists, long count, const std::vector<int>& ids,
                                            const std::vector<long>& bounds, const std::string& name);

/// `to` resized to `from`'s size and filled with it.
void copy_to(const Vec& from, KN<double>& to);
void copy_to(const std::vector<double>& from, KN<double>& to);
void copy_to(const std::vector<long>& from, KN<long>& to);

}  // namespace ffeti::binding
