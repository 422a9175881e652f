// The constraint matrix B = [B_E; B_I] and right-hand side c: gluing of duplicated
// interface dofs, Dirichlet rows (Total FETI), the contact rows of the discretizations in
// contact/ and the friction rows, built from the records of constraint_records.h.
#pragma once

#include "constraints/capabilities.h"
#include "constraints/constraint_records.h"
#include "constraints/contact/contact_row_geometry.h"
#include "constraints/problem_input.h"

#include <cstdint>
#include <memory>
#include <vector>

namespace ffeti {

enum class RowKind : std::uint8_t { gluing, dirichlet, contact, friction };

struct ConstraintEntry {
  int subdomain;
  int dof;
  double coefficient;
};

/// Rows in CSR form over (subdomain, dof) entries; equalities first, then the contact rows
/// B_I u <= c_I, then (with friction) the tangential rows, whose multipliers are bounded,
/// |lambda_t| <= g in a plane problem, ||(lambda_t1, lambda_t2)|| <= g per pair in 3D.
/// Full row rank by construction: a node shared by k subdomains gets k-1 gluing rows, and
/// none where every copy carries a Dirichlet row.
struct Constraints {
  std::vector<int> row_start{0};
  std::vector<ConstraintEntry> entries;
  std::vector<double> rhs;
  std::vector<RowKind> kind;
  int equality_rows = 0;
  int friction_rows = 0;
  /// One per contact row, in row order; shared with the friction rows and the sensitivity
  /// problem's rows (immutable).
  std::vector<std::shared_ptr<const ContactRowGeometry>> geometry;
  std::vector<ContactKind> contact_kinds;    ///< the kinds the input selected (rows or not)
  std::vector<int> normal_row;               ///< per friction row: the row of its contact row
  /// Per friction row, its slave node's value of the law (> 0), in one of the two (the
  /// other empty): Coulomb's coefficient mu, or Tresca's slip bound g (slipBound=).
  std::vector<double> coulomb_coefficient;
  std::vector<double> slip_bound;
  /// Friction rows per contact row that has them: 1 in a plane problem, 2 in three
  /// dimensions (t1 then t2, adjacent: their multipliers lie in one disc ||lambda_t|| <= g).
  int tangent_directions = 1;
  /// Slave nodes that contactRadius left without a row although they lie over a master of
  /// another body, in front of it: their rows against it (B u <= c form, not in B), which
  /// FetiProblem::solve checks for penetration. Node to segment and node to face.
  struct Watched {
    std::vector<int> row_start{0};
    std::vector<ConstraintEntry> entries;
    std::vector<double> rhs;
    int rows() const { return static_cast<int>(rhs.size()); }
  } beyond_reach;

  int rows() const { return static_cast<int>(rhs.size()); }
  /// The rows with bounded multipliers: contact and friction rows.
  int inequality_rows() const { return rows() - equality_rows; }
  int contact_rows() const { return inequality_rows() - friction_rows; }
  int first_friction_row() const { return rows() - friction_rows; }
  int count(RowKind k) const;
};

/// Builds B and c from the records of all subdomains (any order: they are sorted first, so
/// B does not depend on how subdomains are spread over ranks). For FETI-1 the Dirichlet
/// values are substituted into the rows instead of adding rows (rows left empty are
/// dropped; a violated one is an InputError). Throws InputError for a contact slave
/// without a master at its position, and for friction where a selected kind has none
/// (capability_table()).
/// `contact` supplies the scalar parameters (gap, search distance, obstacle), the same on
/// every rank; its per-subdomain lists are not read.
Constraints build_constraints(std::vector<DofRecord> records, const std::vector<SegmentRecord>& segments,
                              const std::vector<FaceRecord>& faces, const ContactInput& contact, FetiVariant variant,
                              double snap);

/// The same for subdomains all held here (global index = position): one process.
Constraints build_constraints(const std::vector<SubdomainInput>& subdomains,
                              const ContactInput& contact, FetiVariant variant);

/// The rows touching one subdomain: their global indices and B_s restricted to them.
struct LocalConstraints {
  std::vector<int> rows;
  SparseMatrix B;  ///< rows.size() x n_s
};

/// Blocks for the local subdomains; `global_ids[k]` is local subdomain k's global index
/// (empty: local = global) and `sizes[k]` its number of dofs.
std::vector<LocalConstraints> split_by_subdomain(const Constraints& constraints,
                                                 const std::vector<Eigen::Index>& sizes,
                                                 const std::vector<int>& global_ids = {});

/// The columns (dofs) where a block B_s has an entry, ascending: the subdomain's interface.
std::vector<int> touched_dofs(const SparseMatrix& B);

/// The rows touching each global subdomain (`count` subdomains), in row order.
std::vector<std::vector<int>> rows_by_subdomain(const Constraints& constraints, int count);

}  // namespace ffeti
