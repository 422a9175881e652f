// The constraint matrix B = [B_E; B_I] and right-hand side c: gluing of duplicated
// interface dofs, Dirichlet rows (Total FETI) and node-to-node contact rows.
#pragma once

#include "feti/problem_input.h"

#include <array>
#include <cstdint>
#include <vector>

namespace ffeti {

enum class RowKind : std::uint8_t { gluing, dirichlet, contact };

struct ConstraintEntry {
  int subdomain;
  int dof;
  double coefficient;
};

using Point = std::array<double, 2>;

/// One contact row's linearized condition as a function of the positions it was built
/// from; the sensitivity analysis differentiates it when the geometry moves.
struct ContactRowGeometry {
  enum class Kind : std::uint8_t { node_to_node, node_to_segment, obstacle };
  Kind kind = Kind::node_to_node;
  /// Node to segment and obstacle: the slave node's x and y dofs (subdomain, dof); node to
  /// node: the slave dof in slave[0]. Node to segment: the segment's a_x, a_y, b_x, b_y.
  /// Unused entries are {-1, -1}. slave[0] is the dof that carries the row's gap_field.
  std::array<std::array<int, 2>, 2> slave{{{-1, -1}, {-1, -1}}};
  std::array<std::array<int, 2>, 4> master{{{-1, -1}, {-1, -1}, {-1, -1}, {-1, -1}}};
  Point s{}, a{}, b{};  ///< slave position, segment ends (obstacle: a = point, b = normal)
};

/// Node to segment: slave s projected on segment a-b (the body of the segment on its left),
/// p = (1 - xi) a + xi b, n the outward normal; n.(u_p - u_s) <= n.(s - p).
/// `clamp_xi` keeps p on the segment (the set-up); the derivative of a row keeps its pairing
/// and differentiates the unclamped formula.
struct LinearizedRow {
  std::array<double, 6> coefficients;  ///< of (s_x, s_y, a_x, a_y, b_x, b_y); obstacle: (s_x, s_y)
  double gap;
};
LinearizedRow node_to_segment_row(const Point& s, const Point& a, const Point& b, bool clamp_xi = true);
/// Rigid obstacle through `point` with outward unit normal n: -n.u_s <= n.(s - point).
LinearizedRow obstacle_row(const Point& s, const Point& point, const Point& normal);

/// Rows in CSR form over (subdomain, dof) entries; equalities first, then inequalities
/// B_I u <= c_I. Full row rank by construction: a node shared by k subdomains gets k-1
/// gluing rows, and none where every copy carries a Dirichlet row.
struct Constraints {
  std::vector<int> row_start{0};
  std::vector<ConstraintEntry> entries;
  std::vector<double> rhs;
  std::vector<RowKind> kind;
  int equality_rows = 0;
  std::vector<ContactRowGeometry> geometry;  ///< one per inequality row, in row order

  int rows() const { return static_cast<int>(rhs.size()); }
  int inequality_rows() const { return rows() - equality_rows; }
  int count(RowKind k) const;
};

/// A dof that may take part in a constraint: an interface candidate, a Dirichlet dof or a
/// contact dof. Records of all ranks together are all the builder needs, so no rank ever
/// holds the whole primal problem.
struct DofRecord {
  int subdomain, dof, body, component;  // subdomain: global index
  double x, y;
  bool fixed, slave, master;
  double value;  // Dirichlet value where fixed
  double gap;    // ContactInput::gap_field's entry (0 without one)
};

/// A master segment of the node-to-segment contact: its dofs (a_x, a_y, b_x, b_y) and ends.
struct SegmentRecord {
  int subdomain, body;
  std::array<int, 4> dofs;
  double ax, ay, bx, by;
};

/// The master segments of the local subdomains (global subdomain indices).
std::vector<SegmentRecord> segment_records(const std::vector<SubdomainInput>& local,
                                           const std::vector<int>& global_ids, const ContactInput& local_contact);
std::vector<double> pack(const std::vector<SegmentRecord>& segments);
std::vector<SegmentRecord> unpack_segments(const std::vector<double>& packed);

struct BoundingBox {
  double x0, y0, x1, y1;
};

/// Coordinates closer than this are the same node: 1e-9 of the diagonal of all boxes.
double snapping_length(const std::vector<BoundingBox>& boxes);

/// The records of the local subdomains: every Dirichlet and contact dof, and every dof
/// inside the (slightly inflated) box of another subdomain of the same body, the only dofs
/// that can be copies of another subdomain's. `boxes` and `bodies` cover all subdomains
/// (global numbering); `global_ids[k]` is the global index of local subdomain k.
std::vector<DofRecord> constraint_candidates(const std::vector<SubdomainInput>& local,
                                             const std::vector<int>& global_ids,
                                             const ContactInput& local_contact,
                                             const std::vector<BoundingBox>& boxes,
                                             const std::vector<int>& bodies, double snap);

/// Flat encodings of records for collective exchange (exact for indices below 2^53).
std::vector<double> pack(const std::vector<DofRecord>& records);
std::vector<DofRecord> unpack(const std::vector<double>& packed);

/// Builds B and c from the records of all subdomains (any order: they are sorted first, so
/// B does not depend on how subdomains are spread over ranks). For FETI-1 the Dirichlet
/// values are substituted into the rows instead of adding rows (rows left empty are
/// dropped; a violated one is an InputError). Throws InputError for a contact slave
/// without a master at its position.
/// `contact` supplies the scalar parameters (gap, search distance, obstacle), the same on
/// every rank; its per-subdomain lists are not read.
Constraints build_constraints(std::vector<DofRecord> records, const std::vector<SegmentRecord>& segments,
                              const ContactInput& contact, FetiVariant variant, double snap);

/// The same for subdomains all held here (global index = position): one process.
Constraints build_constraints(const std::vector<SubdomainInput>& subdomains,
                              const ContactInput& contact, FetiVariant variant);

BoundingBox bounding_box(const SubdomainInput& subdomain);

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
