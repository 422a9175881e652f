// Node to face (three dimensions): each slave node against the nearest master triangle of
// another body within the search distance (ContactInput::master_faces), found through the
// faces' grid.
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

namespace ffeti {

/// n.(sum_i w_i u_i - u_s) <= n.(s - p), p the slave's projection on the triangle
/// (node_to_face_row).
class FaceGeometry final : public ContactRowGeometry {
 public:
  FaceGeometry(std::array<DofRef, 3> slave, const Point3& s, std::array<DofRef, 9> face,
               const std::array<Point3, 3>& corners, bool on_bent_edge = false)
      : ContactRowGeometry(ContactKind::node_to_face, slave[0], s, true), slave(slave), face(face), corners(corners),
        on_bent_edge(on_bent_edge) {}

  std::vector<DofRef> moving_nodes() const override { return {slave[0], face[0], face[3], face[6]}; }
  RowAt row_at(const NodeMotion& v, double t) const override;
  /// The face's first edge.
  double length() const override;
  /// (b - a) x (c - a), normalized: out of the master's body.
  Point3 normal() const override;
  /// t.(u_s - sum_i w_i u_i) along tangent_pair(n) of the face's normal, w the weights of
  /// the slave's closest point on the face.
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
};

class NodeToFace final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::node_to_face; }
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "node-to-face", "contactSlave, contactFaces", kSolidOnly, kSolidOnly, kSolidOnly, kNowhere,
            kSolidOnly, kSolidOnly, kNowhere};
  }
  /// Master faces without slave faces (those make mortar).
  const ListInput* list_input() const override;
  /// contactFaces: three dimensions, each face checked (check_face_list).
  void check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                     const ContactInput& contact, int dimension) const override;
  bool list_given(const ContactInput& contact) const override { return any_entry(contact.master_faces); }
  void read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                 ContactInput& contact) const override;
  bool selected(const ContactRecords& in) const override;
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
  const char* searched_argument() const override { return "contactFaces"; }
  const char* master_word() const override { return "face"; }
};

}  // namespace ffeti
