// Node to node (matching meshes): each slave dof against the master dof of another body at
// its position and component, u_slave - u_master <= gap. The contact of a problem that asks
// for no other kind (with no slave dof it adds nothing).
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

/// The row does not depend on positions: its derivative under motion is zero.
class NodeToNodeGeometry final : public ContactRowGeometry {
 public:
  /// `component`: the slave dof's field component c.
  NodeToNodeGeometry(DofRef slave, DofRef master, const Point3& s, double gap, bool three_d, int component)
      : ContactRowGeometry(ContactKind::node_to_node, slave, s, three_d), master(master), gap(gap),
        component(component) {}

  std::vector<DofRef> moving_nodes() const override { return {}; }
  RowAt row_at(const NodeMotion&, double) const override { return {{slave_dof(), master}, {1.0, -1.0}, gap}; }
  double length() const override { return 1.0; }
  /// -e_c: u_slave - u_master <= gap is n.(u_master - u_slave) <= gap (a scalar field: c = 0).
  Point3 normal() const override {
    Point3 n{0, 0, 0};
    n[static_cast<size_t>(component)] = -1;
    return n;
  }

  const DofRef master;
  const double gap;
  const int component;
};

class NodeToNode final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::node_to_node; }
  bool selected(const ContactRecords& in) const override {
    return in.segments.empty() && in.faces.empty() && !in.contact.obstacle;
  }
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
};

}  // namespace ffeti
