// What the constraint builder needs to know of each subdomain: records of the dofs that may
// take part in a constraint and of the master segments, gathered from all ranks through a
// flat encoding; the boxes of the subdomains and the snapping length that make positions
// comparable.
#pragma once

#include "constraints/problem_input.h"

#include <array>
#include <vector>

namespace ffeti {

/// A dof that may take part in a constraint: an interface candidate, a Dirichlet dof or a
/// contact dof. Records of all ranks together are all the builder needs, so no rank ever
/// holds the whole primal problem.
struct DofRecord {
  int subdomain, dof, body, component;  // subdomain: global index
  double x, y, z;                       // z = 0 in a plane problem
  bool fixed, slave, master;
  double value;  // Dirichlet value where fixed
  double gap;    // ContactInput::gap_field's entry (0 without one)
  double law_value;  // the friction law's value at this dof: Coulomb's mu (friction_field's entry, else friction) or Tresca's g (slip_bound_field, slip_bound)
};

/// A master segment of the node-to-segment contact: its dofs (a_x, a_y, b_x, b_y) and ends.
struct SegmentRecord {
  int subdomain, body;
  std::array<int, 4> dofs;
  double ax, ay, bx, by;
};

/// A contact triangle (three dimensions): its dofs (a_x, a_y, a_z, b_x, ..., c_z) and corners;
/// a master face (node to face, mortar) or a slave face (mortar).
struct FaceRecord {
  int subdomain, body;
  std::array<int, 9> dofs;
  std::array<std::array<double, 3>, 3> corners;
  bool slave = false;
};

/// The master and slave faces of the local subdomains (global subdomain indices): each list
/// kind's (ContactDiscretization::add_faces), the master faces first.
std::vector<FaceRecord> face_records(const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                                     const ContactInput& local_contact);
/// Appends the records of `lists` (per local subdomain, its triangles' 9 dofs), master or slave faces.
void add_face_records(const std::vector<std::vector<std::array<int, 9>>>& lists, bool slave,
                      const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                      std::vector<FaceRecord>& faces);
std::vector<double> pack(const std::vector<FaceRecord>& faces);
std::vector<FaceRecord> unpack_faces(const std::vector<double>& packed);

/// The master segments of the local subdomains (global subdomain indices): each list kind's
/// (ContactDiscretization::add_segments).
std::vector<SegmentRecord> segment_records(const std::vector<SubdomainInput>& local,
                                           const std::vector<int>& global_ids, const ContactInput& local_contact);
/// Appends the records of `lists` (per local subdomain, its segments' 4 dofs).
void add_segment_records(const std::vector<std::vector<std::array<int, 4>>>& lists,
                         const std::vector<SubdomainInput>& local, const std::vector<int>& global_ids,
                         std::vector<SegmentRecord>& segments);
std::vector<double> pack(const std::vector<SegmentRecord>& segments);
std::vector<SegmentRecord> unpack_segments(const std::vector<double>& packed);

struct BoundingBox {
  double x0, y0, x1, y1;
  double z0 = 0, z1 = 0;  ///< 0 in a plane problem
};

BoundingBox bounding_box(const SubdomainInput& subdomain);

/// Coordinates closer than this are the same node: 1e-9 of the diagonal of all boxes.
double snapping_length(const std::vector<BoundingBox>& boxes);

/// The records of the local subdomains: every Dirichlet and contact dof, and every dof
/// inside the (slightly inflated) box of another subdomain of the same body, the only dofs
/// that can be copies of another subdomain's. `boxes` and `bodies` cover all subdomains
/// (global numbering); `global_ids[k]` is the global index of local subdomain k.
std::vector<DofRecord> constraint_candidates(const std::vector<SubdomainInput>& local,
                                             const std::vector<int>& global_ids,
                                             const ContactInput& local_contact,
                                             const std::vector<BoundingBox>& boxes,
                                             const std::vector<int>& bodies, double snap);

/// Flat encodings of records for collective exchange (exact for indices below 2^53).
std::vector<double> pack(const std::vector<DofRecord>& records);
std::vector<DofRecord> unpack(const std::vector<double>& packed);

/// Records in (subdomain, dof) order; one pass where they already are (one rank's records
/// come so from constraint_candidates).
void sort_by_subdomain_and_dof(std::vector<DofRecord>& records);

}  // namespace ffeti
