// Node to node (matching meshes): each slave dof against the master dof of another body at
// its position and component, u_slave - u_master <= gap. The contact of a problem that asks
// for no other kind (with no slave dof it adds nothing).
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

/// Node to node's own input (ContactInput::input_of): contactMaster, per subdomain the master
/// dofs; each slave dof pairs with the master dof of another body at the same position and
/// component: u_slave - u_master <= gap. (For the seed's membranes, u1(1,y) <= u2(1,y):
/// slaves on body 1, masters on body 2.)
struct NodeToNodeInput {
  std::vector<std::vector<int>> masters;
  double gap = 0;  ///< gap=, a problem file's "gap"
};

/// The row does not depend on positions: its derivative under motion is zero.
class NodeToNodeGeometry final : public ContactRowGeometry {
 public:
  /// `component`: the row's; `slave_node`, `master_node`: the dofs of the two nodes by
  /// component, looked up for friction only ({-1, -1} otherwise, and for z in a plane problem).
  NodeToNodeGeometry(DofRef slave, DofRef master, const Point3& s, double gap, bool three_d, int component,
                     const std::array<DofRef, 3>& slave_node, const std::array<DofRef, 3>& master_node)
      : ContactRowGeometry(ContactKind::node_to_node, slave, s, three_d),
        master(master), gap(gap), component(component), slave_node(slave_node), master_node(master_node) {}

  std::vector<DofRef> moving_nodes() const override { return {}; }
  RowAt row_at(const NodeMotion&, double) const override { return {{slave_dof(), master}, {1.0, -1.0}, gap}; }
  double length() const override { return 1.0; }
  /// -e_c: u_slave - u_master <= gap is n.(u_master - u_slave) <= gap (a scalar field: c = 0).
  Point3 normal() const override {
    Point3 n{0, 0, 0};
    n[static_cast<size_t>(component)] = -1;
    return n;
  }
  /// t.(u_s - u_m) along slip_directions(n) of the row's normal n = -e_c, c its component
  /// (the row is -n.(u_s - u_m) <= gap, as a plane's -n.u_s): in a plane problem the other
  /// component, in three dimensions the other two.
  std::vector<RowAt> slip_rows() const override;

  const DofRef master;
  const double gap;
  const int component;
  const std::array<DofRef, 3> slave_node, master_node;
};

class NodeToNode final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::node_to_node; }
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "node-to-node", "contactSlave, contactMaster", kBothDimensions, kBothDimensions, kBothDimensions, kNowhere,
            kBothDimensions, kPlaneOnly, kBothDimensions};
  }
  /// contactMaster pairs the slave dofs: refuses contactSegments, contactFaces or an obstacle beside it.
  void check_combination(const ContactInput& contact) const override;
  const ListInput* list_input() const override;
  /// contactMaster's dofs within each subdomain, gap finite.
  void check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                     const ContactInput& contact, int dimension) const override;
  bool list_given(const ContactInput& contact) const override { return any_entry(contact.input_of<NodeToNodeInput>().masters); }
  void read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                 ContactInput& contact) const override;
  /// gap=.
  void read_option(size_t option, double value, ContactInput& contact) const override;
  void flag_dofs(const ContactInput& local_contact, size_t k, std::vector<char>& /*slave*/,
                 std::vector<char>& master) const override {
    const auto& masters = local_contact.input_of<NodeToNodeInput>().masters;
    if (k < masters.size())
      for (int dof : masters[k]) master[static_cast<size_t>(dof)] = 1;
  }
  /// The slaves' default pairing: where no other kind of the registry is selected (so a new
  /// kind needs no word here).
  bool selected(const ContactRecords& in) const override;
  /// With friction, also each pair's nodes by component (InputError where a tangential
  /// component is missing, a scalar field, or where two slave dofs share a node).
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
};

}  // namespace ffeti
