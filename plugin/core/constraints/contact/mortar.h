// Mortar contact (three dimensions): one row per slave node, its normal gap weighted by its
// shape function over the slave faces (contactSlaveFaces, MortarInput) that master faces
// (node to face's contactFaces) cover (mortar_integration.h).
#pragma once

#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/contact_row_geometry.h"

#include "constraints/constraint_records.h"

#include <memory>
#include <utility>

namespace ffeti {

/// Mortar's own input (ContactInput::input_of): contactSlaveFaces, per subdomain the slave
/// triangles, ordered like the master faces (outward normal). Their corners are the slave
/// nodes (contactSlave then stays empty), each with one row: the normal gap weighted by its
/// shape function phi_j and integrated over the overlap of its slave faces with the master
/// faces of another body facing them (each slave face projected on a master face's plane
/// along that face's normal n, within contactRadius and the nearest master's distance plus
/// two edges): sum over the pairs of int phi_j n.(u_m - u_s) <= int phi_j n.(x_s - x_m),
/// divided by int phi_j so that the multiplier is a force as in the other rows. A uniform
/// pressure passes exactly (docs/algorithms.md, "Mortar").
struct MortarInput {
  std::vector<std::vector<std::array<int, 9>>> slave_faces;
};

/// A dof's share of a mortar row's weighted jump: coefficient times its component of u.
struct JumpEntry {
  DofRef dof;
  int component;
  double coefficient;
};

/// The faces of a mortar problem, sorted by (subdomain, dofs): its rows name their faces by
/// index into these lists (shared by all rows).
struct MortarSurface {
  std::vector<FaceRecord> slaves, masters;
};

/// One (slave face, master face) pair of a row: the faces' indices in the MortarSurface, and
/// the row's node as a corner of the slave face.
struct MortarPair {
  int slave, master, corner;
};

/// A mortar row sums over the pairs of faces its slave's faces overlap (or touch: a motion
/// may make them overlap). Its motion derivative re-integrates those pairs with their
/// corners moved (docs/algorithms.md, "Mortar", sensitivities).
class MortarGeometry final : public ContactRowGeometry {
 public:
  /// With friction: `jump`, the row's weighted jump (1/w_j) int phi_j (u_s - u_m) as entries
  /// per dof and component; `weighted_normal`, its pairs' normals weighted by int phi_j.
  /// `snap`: the distance within which corners of different subdomains are one node.
  MortarGeometry(DofRef slave, const Point3& s, std::shared_ptr<const MortarSurface> surface,
                 std::vector<MortarPair> pairs, double snap, std::vector<JumpEntry> jump,
                 const Point3& weighted_normal);

  /// The corners of the row's faces, each subdomain's copy of a node apart: per pair, its
  /// slave face's corners then its master face's, each node where it first appears.
  std::vector<DofRef> moving_nodes() const override { return nodes_; }
  /// Every pair re-integrated with its corners moved, the pairing kept.
  RowAt row_at(const NodeMotion& v, double t) const override;
  /// The shortest edge of the row's faces.
  double length() const override { return length_; }
  /// weighted_normal normalized (a flat contact: the master's normal).
  Point3 normal() const override;
  /// t.(the weighted jump) along tangent_pair(normal) (docs/algorithms.md, "Mortar", friction).
  std::vector<RowAt> slip_rows() const override;
  /// Refuses a motion along which the row has a kink: its one-sided differences, summed per
  /// node over the subdomains' copies, disagree (a slave edge on a master edge where the
  /// master kinks or ends, moving across it).
  std::string unverified_motion(const NodeMotion& velocities) const override;

  const std::vector<JumpEntry> jump;
  const Point3 weighted_normal;

 private:
  std::shared_ptr<const MortarSurface> surface_;
  std::vector<MortarPair> pairs_;
  std::vector<DofRef> nodes_;                        // moving_nodes()
  std::vector<std::array<size_t, 6>> pair_nodes_;    // per pair, its slave's then its master's corners in nodes_
  std::vector<int> physical_;                        // per node of nodes_, one index per physical node
  double length_ = 0;
};

class Mortar final : public ContactDiscretization {
 public:
  ContactKind kind() const override { return ContactKind::mortar; }
  /// name, selected by: rows, friction, sensitivity, sensitivity with friction, MPI, ffeti-solve,
  /// fetiContactStart
  KindCapabilities capabilities() const override {
    return {kind(), "mortar", "contactSlaveFaces, contactFaces", kSolidOnly, kSolidOnly, kSolidOnly, kNowhere, kSolidOnly,
            kNowhere, kSolidOnly};
  }
  /// The corners of contactSlaveFaces are its slaves: refuses contactSlave or an obstacle beside them.
  void check_combination(const ContactInput& contact) const override;
  const ListInput* list_input() const override;
  /// contactSlaveFaces: three dimensions, each face checked (check_face_list); the slave
  /// faces and their masters (contactFaces) P1 faces only.
  void check_against(const std::vector<SubdomainInput>& subdomains, const std::vector<size_t>& ids,
                     const ContactInput& contact, int dimension) const override;
  bool list_given(const ContactInput& contact) const override { return any_entry(contact.input_of<MortarInput>().slave_faces); }
  void read_list(const std::vector<std::vector<int>>& lists, const std::vector<int>& ids,
                 ContactInput& contact) const override;
  /// The slave faces' corners are the slave nodes.
  void flag_dofs(const ContactInput& local_contact, size_t k, std::vector<char>& slave,
                 std::vector<char>& /*master*/) const override {
    const auto& faces = local_contact.input_of<MortarInput>().slave_faces;
    if (k < faces.size())
      for (const auto& face : faces[k])
        for (int dof : face) slave[static_cast<size_t>(dof)] = 1;
  }
  void add_faces(const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                 const ContactInput& local_contact, std::vector<FaceRecord>& faces) const override {
    add_face_records(local_contact.input_of<MortarInput>().slave_faces, true, local, global_ids, faces);
  }
  /// Any slave face on any rank.
  bool selected(const ContactRecords& in) const override;
  void add_rows(const ContactRecords& in, std::vector<Row>& rows) const override;
  const char* searched_argument() const override { return "contactSlaveFaces"; }
  const char* master_word() const override { return "face"; }
};

}  // namespace ffeti
