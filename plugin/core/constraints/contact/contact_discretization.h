// One contact discretization (node to node, node to segment, obstacle, ball, node to face,
// mortar) behind one interface: which input selects it and its rows, each with its
// geometry (contact_row_geometry.h). build_constraints runs the registry in order; adding a
// kind is a unit here, an entry in contact_discretizations() and one in capability_table().
#pragma once

#include "constraints/capabilities.h"
#include "constraints/constraint_records.h"

#include <memory>
#include <vector>

namespace ffeti {

struct Row;

/// What the contact rows are built from: the records of all ranks (`records` sorted by
/// (subdomain, dof)), the scalar parameters of `contact` (its per-subdomain lists are not
/// read) and the snapping length.
struct ContactRecords {
  const std::vector<DofRecord>& records;
  const std::vector<SegmentRecord>& segments;
  const std::vector<FaceRecord>& faces;
  const ContactInput& contact;
  double snap;
};

class ContactDiscretization {
 public:
  virtual ~ContactDiscretization() = default;
  virtual ContactKind kind() const = 0;
  /// Whether the input asks for this kind (on all ranks' records alike).
  virtual bool selected(const ContactRecords& in) const = 0;
  /// Appends one contact row per slave node (or none where no master is within reach).
  virtual void add_rows(const ContactRecords& in, std::vector<Row>& rows) const = 0;
  /// A kind that searches masters for its slaves: the argument naming them and what a
  /// master is ("segment", "face"), for the error when no slave found one. nullptr: rows
  /// come without a search.
  virtual const char* searched_argument() const { return nullptr; }
  virtual const char* master_word() const { return nullptr; }
};

/// Every kind, in the order its rows follow one another in B.
const std::vector<std::unique_ptr<const ContactDiscretization>>& contact_discretizations();

}  // namespace ffeti
