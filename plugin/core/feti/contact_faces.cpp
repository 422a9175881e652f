// Node-to-face contact rows (three dimensions): each slave node against the nearest master
// triangle of another body, found through a uniform grid of the faces' boxes.
#include "feti/constraint_rows.h"
#include "feti/face_grid.h"

namespace ffeti {

void add_node_to_face_rows(const std::vector<DofRecord>& records, const std::vector<FaceRecord>& faces,
                           const ContactInput& contact, double snap, std::vector<Row>& rows) {
  const FaceGrid grid(faces);
  for (const SlaveNode& node : slave_nodes(records, snap, 3)) {
    const Point3 s{node.x_dof->x, node.x_dof->y, node.x_dof->z};
    const FaceRecord* face = grid.nearest(s, node.x_dof->body, contact.search_distance);
    if (!face) continue;  // no master face within reach: no contact possible here
    ContactRowGeometry geometry;
    geometry.kind = ContactRowGeometry::Kind::node_to_face;
    geometry.slave = {{{node.x_dof->subdomain, node.x_dof->dof}, {node.y_dof->subdomain, node.y_dof->dof}}};
    geometry.s = {s[0], s[1]};
    geometry.slave_z = {node.z_dof->subdomain, node.z_dof->dof};
    geometry.s3 = s;
    for (size_t k = 0; k < 9; ++k) geometry.face[k] = {face->subdomain, face->dofs[k]};
    geometry.corners = face->corners;
    const LinearizedFaceRow linear = node_to_face_row(s, face->corners[0], face->corners[1], face->corners[2]);
    Row row{{}, linear.gap + node.x_dof->gap, RowKind::contact, false, geometry, -1, node.x_dof->friction};
    const DofRecord* slave[3] = {node.x_dof, node.y_dof, node.z_dof};
    for (size_t i = 0; i < 3; ++i)
      if (linear.coefficients[i] != 0) row.entries.push_back({slave[i]->subdomain, slave[i]->dof, linear.coefficients[i]});
    for (size_t k = 0; k < 9; ++k)
      if (linear.coefficients[3 + k] != 0) row.entries.push_back({face->subdomain, face->dofs[k], linear.coefficients[3 + k]});
    rows.push_back(std::move(row));
  }
}

}  // namespace ffeti
