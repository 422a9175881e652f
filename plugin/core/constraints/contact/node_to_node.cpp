#include "constraints/contact/node_to_node.h"

#include "constraints/constraint_rows.h"

namespace ffeti {

void NodeToNode::add_rows(const ContactRecords& in, std::vector<Row>& rows) const {
  for (const auto& [slave, master] : node_to_node_pairs(in.records, in.snap)) {
    const double gap = in.contact.gap + slave->gap;
    rows.push_back({{{slave->subdomain, slave->dof, 1.0}, {master->subdomain, master->dof, -1.0}},
                    gap,
                    RowKind::contact,
                    false,
                    std::make_shared<const NodeToNodeGeometry>(DofRef{slave->subdomain, slave->dof},
                                                               DofRef{master->subdomain, master->dof},
                                                               Point3{slave->x, slave->y, slave->z}, gap,
                                                               in.contact.three_d, slave->component)});
  }
}

}  // namespace ffeti
