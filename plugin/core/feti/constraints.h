// The constraint matrix B = [B_E; B_I] and right-hand side c: gluing of duplicated
// interface dofs, Dirichlet rows (Total FETI) and node-to-node contact rows.
#pragma once

#include "feti/problem_input.h"

#include <cstdint>
#include <vector>

namespace ffeti {

enum class RowKind : std::uint8_t { gluing, dirichlet, contact };

struct ConstraintEntry {
  int subdomain;
  int dof;
  double coefficient;
};

/// Rows in CSR form over (subdomain, dof) entries; equalities first, then inequalities
/// B_I u <= c_I. Full row rank by construction: a node shared by k subdomains gets k-1
/// gluing rows, and none where every copy carries a Dirichlet row.
struct Constraints {
  std::vector<int> row_start{0};
  std::vector<ConstraintEntry> entries;
  std::vector<double> rhs;
  std::vector<RowKind> kind;
  int equality_rows = 0;

  int rows() const { return static_cast<int>(rhs.size()); }
  int inequality_rows() const { return rows() - equality_rows; }
  int count(RowKind k) const;
};

/// Builds B and c. For FETI-1 the Dirichlet values are substituted into the rows instead
/// of adding rows (rows left empty are dropped; a violated one is an InputError).
/// Throws InputError for a contact slave without a master at its position.
Constraints build_constraints(const std::vector<SubdomainInput>& subdomains,
                              const NodeToNodeContact& contact, FetiVariant variant);

/// The rows touching one subdomain: their global indices and B_s restricted to them.
struct LocalConstraints {
  std::vector<int> rows;
  SparseMatrix B;  ///< rows.size() x n_s
};

std::vector<LocalConstraints> split_by_subdomain(const Constraints& constraints,
                                                 const std::vector<Eigen::Index>& sizes);

}  // namespace ffeti
