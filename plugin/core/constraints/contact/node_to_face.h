// Node to face (three dimensions): each slave node against the nearest master triangle of
// another body within the search distance (contactFaces, NodeToFaceInput), found through the
// faces' grid.
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_linearization.h"
#include "constraints/contact/contact_row_geometry.h"

#include <vector>

namespace ffeti {

/// Whose normal a node-to-face row takes (contactNormal=): the master face's, the slave
/// surface's at the slave node (the area-weighted normals of the slave body's faces in
/// contactFaces around it), the two averaged, or (flatter, the default) the flatter
/// surface's, chosen per couple of bodies by flatter_side (docs/reference.md, "contactNormal").
enum class ContactNormal { master, slave, average, flatter };

/// Node to face's own input (ContactInput::input_of): contactFaces, per subdomain the master
/// triangles (mortar's master faces too), each the x, y, z dofs of its corners a, b, c,
/// ordered so that (b - a) x (c - a) points out of its body. Each slave node (its three dofs
/// in contactSlave) is projected on the nearest face of another body within contactRadius, p
/// its closest point, n the face's unit normal: n.(u_p - u_slave) <= n.(x_slave - p), u_p
/// interpolated linearly on the face.
struct NodeToFaceInput {
  std::vector<std::vector<std::array<int, 9>>> faces;
  ContactNormal normal = ContactNormal::flatter;  ///< the rows' normal (contactNormal=)
};

/// The slave surface around a slave node, whose normal a row takes with contactNormal
/// slave or average: the slave body's faces in contactFaces that have the node as a corner.
struct SlaveFan {
  ContactNormal normal = ContactNormal::master;  ///< master: no fan, the face's normal
  std::vector<DofRef> neighbours;                ///< the other corners' x dofs (moving nodes 4, 5, ...)
  std::vector<Point3> positions;                 ///< their positions
  /// Each face's corners in its order (outward of the slave's body): -1 the slave node,
  /// k >= 0 neighbours[k].
  std::vector<std::array<int, 3>> faces;
};

/// The unit outward normal of the slave surface at its node s: the fan's faces' (b - a) x
/// (c - a) summed (area-weighted), `neighbours` the fan's corners' positions.
Point3 fan_normal(const SlaveFan& fan, const Point3& s, const std::vector<Point3>& neighbours);

/// contactNormal="flatter": the normal of the flatter surface, judged by how much each side's
/// unit normals over the rows spread (1 - |their mean|): a curved surface tilts by up to a/R
/// at the rim of a contact of radius a, and a tilted row spends friction under the normal
/// load alone (docs/results/friction.md, "Which body is the slave"). master where the master
/// faces spread at most half as much as the slave surface, or both are flat (spread <= 1e-12)
/// or a side has none; slave where the slave surface spreads at most half as much; average
/// between (curved alike: two equal spheres, their common plane).
ContactNormal flatter_side(const std::vector<Point3>& master_normals, const std::vector<Point3>& slave_normals);

/// The row's normal n (out of the master, towards the slave) for master face normal m:
/// m, minus the slave's own normal o, or (m - o)/|m - o|.
Point3 row_direction(ContactNormal normal, const Point3& m, const Point3& o);

/// n.(sum_i w_i u_i - u_s) <= n.(s - p), p the slave's projection on the triangle
/// (node_to_face_row); with a fan, n from the slave surface (row_direction) and p the point
/// of the face's plane the slave reaches along it.
class FaceGeometry final : public ContactRowGeometry {
 public:
  FaceGeometry(std::array<DofRef, 3> slave, const Point3& s, std::array<DofRef, 9> face,
               const std::array<Point3, 3>& corners, bool on_bent_edge = false, SlaveFan fan = {});

  /// The slave, the face's corners a, b, c, then the fan's neighbours (their motion turns
  /// the slave's normal).
  std::vector<DofRef> moving_nodes() const override;
  RowAt row_at(const NodeMotion& v, double t) const override;
  /// The row at the nodes moved by t v: clamped (the set-up) or not (its derivative).
  LinearizedFaceRow linearized(const NodeMotion& v, double t, bool clamp) const;
  /// The face's first edge.
  double length() const override;
  /// The row's normal: the face's (b - a) x (c - a), normalized, out of the master's body;
  /// with a fan, row_direction's.
  Point3 normal() const override;
  /// t.(u_s - sum_i w_i u_i) along tangent_pair(n) of the row's normal, w the weights of
  /// the row's point p on the face.
  std::vector<RowAt> slip_rows() const override;
  /// Refuses a motion whose derivative is one-sided: the slave on an edge or a corner of its
  /// face moving across it relative to the face (it changes face on one side), or a slave
  /// beyond the face's edges (its clamped projection is not what row_at differentiates).
  std::string unverified_motion(const NodeMotion& velocities) const override;
  /// A slave on an edge (or corner) its face shares with a face of another slope: any motion.
  /// The row takes this face's normal; moved off the surface, the slave is nearer the other
  /// face on one side of the design, whose gap changes at another rate (measured: a
  /// near-cancelling direction 7 % off central differences). Mortar rows have no such kink.
  bool one_sided_under(const NodeMotion& velocities) const override;

  const std::array<DofRef, 3> slave;  ///< the slave's x, y, z dofs
  const std::array<DofRef, 9> face;   ///< the triangle's x, y, z dofs of corners a, b, c
  const std::array<Point3, 3> corners;
  const bool on_bent_edge;            ///< the slave on an edge or corner shared with a face of another normal
  const SlaveFan fan;
};

class NodeToFace final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::node_to_face; }
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "node-to-face", "contactSlave, contactFaces", kSolidOnly, kSolidOnly, kSolidOnly, kNowhere,
            kSolidOnly, kSolidOnly, kSolidOnly};
  }
  /// Master faces without slave faces (those make mortar).
  const ListInput* list_input() const override;
  /// contactFaces: three dimensions, each face checked (check_face_list).
  void check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                     const ContactInput& contact, int dimension) const override;
  bool list_given(const ContactInput& contact) const override { return any_entry(contact.input_of<NodeToFaceInput>().faces); }
  void read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                 ContactInput& contact) const override;
  /// contactNormal= (its word's position in ContactNormal's order).
  void read_option(size_t option, double value, ContactInput& contact) const override;
  /// With contactNormal other than master (the slave surface's faces give its normal; flatter
  /// compares it with the master's).
  bool lists_slave_group(const ContactInput& contact) const override {
    return contact.input_of<NodeToFaceInput>().normal != ContactNormal::master;
  }
  void add_faces(const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                 const ContactInput& local_contact, std::vector<FaceRecord>& faces) const override {
    add_face_records(local_contact.input_of<NodeToFaceInput>().faces, false, local, global_ids, faces);
  }
  /// contactNormal other than master: only with contactFaces and not mortar's contactSlaveFaces.
  void check_combination(const ContactInput& contact) const override;
  bool selected(const ContactRecords& in) const override;
  /// With contactNormal slave or average, each slave's fan from the faces of its own body;
  /// InputError naming contactNormal for a slave without any, or one whose row's normal lies
  /// within 15 degrees of its face's plane.
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
  const char* searched_argument() const override { return "contactFaces"; }
  const char* master_word() const override { return "face"; }
};

}  // namespace ffeti
