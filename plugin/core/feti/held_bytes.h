// What the plugin holds besides the factors, in bytes, for the report's memory keys: a user
// who runs out of memory learns which part of a set-up to shrink (smaller subdomains hold
// sparser factors; the copies of K_s and the constraint rows scale with the unknowns).
#pragma once

#include "constraints/constraints.h"
#include "constraints/problem_input.h"
#include "feti/subdomain.h"

#include <vector>

namespace ffeti {

/// Bytes of a vector's elements (its size, not its capacity).
template <class T>
double vector_bytes(const std::vector<T>& v) {
  return static_cast<double>(v.size() * sizeof(T));
}

/// Bytes of a dense vector or matrix's entries.
template <class Dense>
double dense_bytes(const Dense& m) {
  return static_cast<double>(m.size()) * sizeof(typename Dense::Scalar);
}

/// Bytes of a compressed sparse matrix: values, inner indices and outer starts.
template <class Sparse>
double sparse_bytes(const Sparse& K) {
  using Index = typename Sparse::StorageIndex;
  return static_cast<double>(K.nonZeros()) * static_cast<double>(sizeof(typename Sparse::Scalar) + sizeof(Index)) +
         static_cast<double>(K.outerSize() + 1) * static_cast<double>(sizeof(Index));
}

/// The plugin's copies of the subdomains' input: K_s (a matrix shared by identical
/// subdomains counted once), f_s, coordinates, components and Dirichlet lists.
double input_bytes(const std::vector<SubdomainInput>& inputs);

/// The subdomains' kernel bases R_s and index maps (fixing dofs, kept dofs, interface).
double kernel_bytes(const SubdomainList& subdomains);

/// The explicit blocks of K_s^+ on the interfaces the dual operator applies
/// (Subdomain::form_explicit_block), a block shared by identical subdomains counted once.
double explicit_block_bytes(const SubdomainList& subdomains);

/// The constraint rows B, c and their kinds as this rank holds them.
double constraint_bytes(const Constraints& constraints);

}  // namespace ffeti
