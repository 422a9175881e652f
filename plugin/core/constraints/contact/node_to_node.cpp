#include "constraints/contact/node_to_node.h"

#include "constraints/contact/obstacle.h"
#include "constraints/constraint_rows.h"
#include "constraints/input_checks.h"

#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace ffeti {
namespace {

std::string where(const DofRecord& r) {
  return "dof " + std::to_string(r.dof) + " of subdomain " + std::to_string(r.subdomain) + " at (" +
         std::to_string(r.x) + ", " + std::to_string(r.y) + ", " + std::to_string(r.z) + ")";
}

/// The dofs of `at`'s node by component, for friction: every component but the row's must
/// be there, and none of the slave's may be a slave too (its rows would repeat each other's
/// slips).
std::array<DofRef, 3> node_dofs(const NodeComponents& nodes, const DofRecord& at, int components) {
  std::array<DofRef, 3> dofs{{{-1, -1}, {-1, -1}, {-1, -1}}};
  for (int c = 0; c < components; ++c) {
    const DofRecord* r = c == at.component ? &at : nodes.find(at, c);
    if (!r)
      throw InputError("friction: node-to-node contact slips along the other components of each slave and master "
                       "node (a vector field with component=): " + where(at) + " has no dof of component " +
                       std::to_string(c) + " at its node");
    if (c != at.component && at.slave && r->slave)
      throw InputError("friction: contactSlave lists " + where(at) + " and dof " + std::to_string(r->dof) +
                       " of the same node: node-to-node friction takes one slave dof per node, along the normal");
    dofs[static_cast<size_t>(c)] = {r->subdomain, r->dof};
  }
  return dofs;
}

}  // namespace

const ListInput* NodeToNode::list_input() const {
  static const ListInput spec{"contactMaster", 1, "1 dof per entry", "master", 1, MeshEntries::node_dofs,
                              {{"gap", "gap", {}, "node-to-node contact (1 component)"}}};
  return &spec;
}

void NodeToNode::read_option(size_t /*option*/, double value, ContactInput& contact) const {
  contact.input_of<NodeToNodeInput>().gap = value;
}

void NodeToNode::read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& /*ids*/,
                           ContactInput& contact) const {
  contact.input_of<NodeToNodeInput>().masters = lists;  // one dof per entry: every list is whole
}

void NodeToNode::check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                               const ContactInput& contact, int /*dimension*/) const {
  check_list_dofs(contact.input_of<NodeToNodeInput>().masters, ids, subdomains, list_input()->argument);
  if (!std::isfinite(contact.input_of<NodeToNodeInput>().gap)) throw InputError("gap: must be finite");
}

std::vector<RowAt> NodeToNodeGeometry::slip_rows() const {
  Point3 n{0, 0, 0};
  n[static_cast<size_t>(component)] = -1;
  std::vector<RowAt> rows;
  for (const Point3& t : slip_directions(n, three_d())) {
    RowAt row{{}, {}, 0.0};
    for (size_t i = 0; i < 3; ++i)
      if (t[i] != 0) {
        row.dofs.insert(row.dofs.end(), {slave_node[i], master_node[i]});
        row.coefficients.insert(row.coefficients.end(), {t[i], -t[i]});
      }
    rows.push_back(std::move(row));
  }
  return rows;
}

void NodeToNode::check_combination(const ContactInput& contact) const {
  if (list_given(contact) &&
      (ffeti::list_given(ContactKind::node_to_segment, contact) || ffeti::list_given(ContactKind::node_to_face, contact) ||
       contact.input_of<ObstacleInput>().given || contact.kind_parameters.count(ContactKind::ball)))
    throw InputError("contactMaster: node-to-node contact cannot be combined with contactSegments, contactFaces or "
                     "obstacle in one problem (the slave dofs would belong to both)");
}

bool NodeToNode::selected(const ContactRecords& in) const {
  const auto& units = contact_discretizations();
  return std::none_of(units.begin(), units.end(),
                      [&](const auto& unit) { return unit.get() != this && unit->selected(in); });
}

void NodeToNode::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  const int components = in.contact.three_d ? 3 : 2;
  std::optional<NodeComponents> nodes;
  if (in.contact.has_friction()) nodes.emplace(in.records, in.snap);
  for (const auto& [slave, master] : node_to_node_pairs(in.records, in.snap)) {
    const double gap = in.contact.input_of<NodeToNodeInput>().gap + slave->gap;
    std::array<DofRef, 3> slave_node{{{-1, -1}, {-1, -1}, {-1, -1}}}, master_node = slave_node;
    if (nodes) slave_node = node_dofs(*nodes, *slave, components), master_node = node_dofs(*nodes, *master, components);
    rows.push_back({{{slave->subdomain, slave->dof, 1.0}, {master->subdomain, master->dof, -1.0}},
                    gap,
                    RowKind::contact,
                    false,
                    std::make_shared<const NodeToNodeGeometry>(
                        DofRef{slave->subdomain, slave->dof}, DofRef{master->subdomain, master->dof},
                        Point3{slave->x, slave->y, slave->z}, gap, in.contact.three_d, slave->component, slave_node,
                        master_node),
                    -1,
                    slave->law_value});
  }
}

}  // namespace ffeti
