// Inside build_constraints and the contact units (not for other users): the rows of B in the
// making and the functions that match dofs by their snapped position (gluing, Dirichlet,
// node to node, the slave nodes), substitute Dirichlet values and add friction rows.
#pragma once

#include "constraints/constraints.h"

#include <memory>
#include <tuple>
#include <utility>
#include <vector>

namespace ffeti {

/// A row of B in the making; `geometry` only for a contact row.
struct Row {
  std::vector<ConstraintEntry> entries;
  double rhs = 0;
  RowKind kind = RowKind::gluing;
  bool equality = true;
  std::shared_ptr<const ContactRowGeometry> geometry{};
  int normal_row = -1;  ///< a friction row's contact row
  double law_value = 0;  ///< a contact or friction row's friction law value (its slave node's): Coulomb's mu or Tresca's g, the problem's one law
  /// A slave node left without a row by contactRadius, over a master of another body: its
  /// row against that master, kept out of B and checked for penetration after the solve.
  bool beyond_reach = false;
};

/// A slave node of the contact kinds that take every component: its dofs.
struct SlaveNode {
  const DofRecord* x_dof;
  const DofRecord* y_dof;
  const DofRecord* z_dof = nullptr;  ///< three dimensions (node to face) only
};

// In all of these `records` are sorted by (subdomain, dof).
/// `components` = 3: each slave node also needs its z dof (node to face).
std::vector<SlaveNode> slave_nodes(const std::vector<DofRecord>& records, double snap, int components = 2);
void add_gluing_rows(const std::vector<DofRecord>& records, double snap, std::vector<Row>& rows);
void add_dirichlet_rows(const std::vector<DofRecord>& records, std::vector<Row>& rows);
/// Node to node: each slave dof (one copy per physical dof) and the master dof of another
/// body at its position and component; InputError for a slave without one.
struct SlaveMaster {
  const DofRecord* slave;
  const DofRecord* master;
};
std::vector<SlaveMaster> node_to_node_pairs(const std::vector<DofRecord>& records, double snap);
/// The records of each node by component, in one subdomain: the other dofs of a contact
/// dof's node (node-to-node friction slips along them).
class NodeComponents {
 public:
  NodeComponents(const std::vector<DofRecord>& records, double snap);
  /// The record of component `component` at the node of `at`, in its subdomain; nullptr if
  /// none was recorded.
  const DofRecord* find(const DofRecord& at, int component) const;

 private:
  using Key = std::tuple<int, long long, long long, long long, int>;  // subdomain, position, component
  Key key(const DofRecord& r, int component) const;
  double snap_;
  std::vector<std::pair<Key, const DofRecord*>> sorted_;
};
/// The record of a fixed dof, nullptr if the dof is not fixed.
const DofRecord* fixed_record(const std::vector<DofRecord>& records, int subdomain, int dof);
/// FETI-1: known Dirichlet values move to the right-hand side.
void substitute_dirichlet(const std::vector<DofRecord>& records, std::vector<Row>& rows);
/// Appends the friction rows of each contact row of `rows` (its index there as
/// normal_row), the slip rows of its geometry (one, or two adjacent in 3D); fixed dofs leave
/// a row (their values to its right-hand side), rows left empty (a slave that cannot slip)
/// are dropped, and a 3D pair with one empty row is an InputError.
void add_friction_rows(const std::vector<DofRecord>& records, std::vector<Row>& rows);

}  // namespace ffeti
