// Inside build_constraints (not for other users): the rows of B in the making and the
// functions that add each kind. constraint_rows.cpp defines those that match dofs by their
// snapped position (gluing, Dirichlet, node to node, the slave nodes); contact_rows.cpp
// those of the slave nodes (node to segment, obstacle).
#pragma once

#include "feti/constraints.h"

#include <vector>

namespace ffeti {

/// A row of B in the making; `geometry` only for a contact row.
struct Row {
  std::vector<ConstraintEntry> entries;
  double rhs = 0;
  RowKind kind = RowKind::gluing;
  bool equality = true;
  ContactRowGeometry geometry{};
  int normal_row = -1;  ///< a friction row's contact row
  double friction = 0;  ///< a contact or friction row's Coulomb coefficient (its slave node's)
};

/// A slave node of the node-to-segment or obstacle contact: its two dofs and position.
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
void add_node_to_node_rows(const std::vector<DofRecord>& records, double gap, double snap, std::vector<Row>& rows);
void add_node_to_segment_rows(const std::vector<DofRecord>& records, const std::vector<SegmentRecord>& segments,
                              const ContactInput& contact, double snap, std::vector<Row>& rows);
void add_node_to_face_rows(const std::vector<DofRecord>& records, const std::vector<FaceRecord>& faces,
                           const ContactInput& contact, double snap, std::vector<Row>& rows);
/// Mortar (three dimensions): `faces` holds the slave faces and the master faces.
void add_mortar_rows(const std::vector<DofRecord>& records, const std::vector<FaceRecord>& faces,
                     const ContactInput& contact, double snap, std::vector<Row>& rows);
void add_obstacle_rows(const std::vector<DofRecord>& records, const ContactInput& contact, double snap,
                       std::vector<Row>& rows);
/// The record of a fixed dof, nullptr if the dof is not fixed.
const DofRecord* fixed_record(const std::vector<DofRecord>& records, int subdomain, int dof);
/// FETI-1: known Dirichlet values move to the right-hand side.
void substitute_dirichlet(const std::vector<DofRecord>& records, std::vector<Row>& rows);
/// Appends a friction row for each contact row of `rows` (its index there as normal_row);
/// fixed dofs leave the row (their values to its right-hand side), and a row left empty (a
/// slave that cannot slip) is dropped.
void add_friction_rows(const std::vector<DofRecord>& records, std::vector<Row>& rows);

}  // namespace ffeti
