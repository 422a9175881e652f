// The constraint matrix B = [B_E; B_I] and right-hand side c: gluing of duplicated
// interface dofs, Dirichlet rows (Total FETI) and contact rows (node to node, node to
// segment, obstacle), built from the records of constraint_records.h.
#pragma once

#include "feti/constraint_records.h"
#include "feti/contact_linearization.h"
#include "feti/problem_input.h"

#include <array>
#include <cstdint>
#include <vector>

namespace ffeti {

enum class RowKind : std::uint8_t { gluing, dirichlet, contact, friction };

struct ConstraintEntry {
  int subdomain;
  int dof;
  double coefficient;
};

/// One contact row's linearized condition as a function of the positions it was built
/// from; the sensitivity analysis differentiates it when the geometry moves.
struct ContactRowGeometry {
  enum class Kind : std::uint8_t { node_to_node, node_to_segment, obstacle, node_to_face, mortar, ball };
  Kind kind = Kind::node_to_node;
  /// Node to segment and obstacle: the slave node's x and y dofs (subdomain, dof); node to
  /// node: the slave dof in slave[0]. Node to segment: the segment's a_x, a_y, b_x, b_y.
  /// Node to face, 3D obstacle and mortar: the slave's x and y dofs, s its x and y, and
  /// the three-dimensional data below. Unused entries are {-1, -1}. slave[0] is the dof
  /// that carries the row's gap_field.
  std::array<std::array<int, 2>, 2> slave{{{-1, -1}, {-1, -1}}};
  std::array<std::array<int, 2>, 4> master{{{-1, -1}, {-1, -1}, {-1, -1}, {-1, -1}}};
  Point s{}, a{}, b{};  ///< slave position, segment ends (obstacle: a = point, b = normal)
  /// Three dimensions (node to face, obstacle; not mortar): the slave's z dof and position;
  /// node to face: the master triangle's x, y, z dofs and corners; obstacle: the plane's
  /// point and unit normal in corners[0], corners[1]. A ball (in the plane too, z = 0): its
  /// centre in corners[0], its radius in corners[1][0], the slave's position in s3.
  std::array<int, 2> slave_z{-1, -1};
  Point3 s3{};
  std::array<std::array<int, 2>, 9> face{};
  std::array<Point3, 3> corners{};
};

/// Rows in CSR form over (subdomain, dof) entries; equalities first, then the contact rows
/// B_I u <= c_I, then (with friction) the tangential rows, whose multipliers are bounded on
/// both sides, |lambda_t| <= g. Full row rank by construction: a node shared by k
/// subdomains gets k-1 gluing rows, and none where every copy carries a Dirichlet row.
struct Constraints {
  std::vector<int> row_start{0};
  std::vector<ConstraintEntry> entries;
  std::vector<double> rhs;
  std::vector<RowKind> kind;
  int equality_rows = 0;
  int friction_rows = 0;
  std::vector<ContactRowGeometry> geometry;  ///< one per contact row, in row order
  std::vector<int> normal_row;               ///< per friction row: the row of its contact row
  std::vector<double> friction_coefficient;  ///< per friction row: Coulomb's mu (its slave node's)

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
/// without a master at its position.
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

/// The rows touching each global subdomain (`count` subdomains), in row order.
std::vector<std::vector<int>> rows_by_subdomain(const Constraints& constraints, int count);

}  // namespace ffeti
