// Node to segment (plane problems): each slave node against the nearest master segment of
// another body within the search distance (contactSegments, NodeToSegmentInput).
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_linearization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

/// Node to segment's own input (ContactInput::input_of): contactSegments, per subdomain
/// (a_x, a_y, b_x, b_y) of each master segment. Each slave node (both its dofs in
/// contactSlave) is projected on the nearest master segment of another body within
/// contactRadius; with p = (1 - xi) a + xi b and n the segment's outward normal,
/// n.(u_p - u_slave) <= n.(x_slave - p). Segments run with their body on the left (FreeFEM's
/// orientation of a counter-clockwise border), so n = (b - a) rotated clockwise.
struct NodeToSegmentInput {
  std::vector<std::vector<std::array<int, 4>>> segments;
};

/// n.(u_p - u_s) <= n.(s - p), p the slave's projection on segment a-b (node_to_segment_row).
class NodeToSegmentGeometry final : public ContactRowGeometry {
 public:
  NodeToSegmentGeometry(std::array<DofRef, 2> slave, std::array<DofRef, 4> master, const Point& s, const Point& a,
                        const Point& b)
      : ContactRowGeometry(ContactKind::node_to_segment, slave[0], {s[0], s[1], 0.0}, false),
        slave(slave), master(master), s(s), a(a), b(b) {}

  std::vector<DofRef> moving_nodes() const override { return {slave[0], master[0], master[2]}; }
  RowAt row_at(const NodeMotion& v, double t) const override;
  double length() const override;
  /// (b - a) turned clockwise, normalized: outward, the segment's body on its left.
  Point3 normal() const override;
  std::vector<RowAt> slip_rows() const override;

  const std::array<DofRef, 2> slave;   ///< the slave's x and y dofs
  const std::array<DofRef, 4> master;  ///< the segment's a_x, a_y, b_x, b_y
  const Point s, a, b;                 ///< slave position, segment ends

  /// The dofs of the row's coefficients (node_to_segment_row's order).
  std::vector<DofRef> dofs() const { return {slave[0], slave[1], master[0], master[1], master[2], master[3]}; }
};

class NodeToSegment final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::node_to_segment; }
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "node-to-segment", "contactSlave, contactSegments", kPlaneOnly, kPlaneOnly, kPlaneOnly, kNowhere,
            kPlaneOnly, kPlaneOnly, kPlaneOnly};
  }
  const ListInput* list_input() const override;
  /// contactSegments: plane problems only, its dofs within each subdomain.
  void check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                     const ContactInput& contact, int dimension) const override;
  bool list_given(const ContactInput& contact) const override {
    return any_entry(contact.input_of<NodeToSegmentInput>().segments);
  }
  void read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                 ContactInput& contact) const override;
  void add_segments(const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                    const ContactInput& local_contact, std::vector<SegmentRecord>& segments) const override {
    add_segment_records(local_contact.input_of<NodeToSegmentInput>().segments, local, global_ids, segments);
  }
  bool selected(const ContactRecords& in) const override { return !in.segments.empty(); }
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
  const char* searched_argument() const override { return "contactSegments"; }
  const char* master_word() const override { return "segment"; }
};

}  // namespace ffeti
