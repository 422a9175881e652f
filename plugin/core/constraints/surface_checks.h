// Checks of contact surfaces against the bodies they bound, from what the core sees of a
// body: its stiffness matrix and its dofs' coordinates (no elements). A surface listed
// against its body (a face with two corners swapped, a plane whose normal points into the
// body, P2 sub-triangles given to a P1-only discretization) would otherwise give an answer
// or an "infeasible" with no word about the cause.
#pragma once

#include "constraints/problem_input.h"

#include <vector>

namespace ffeti {

/// Contact faces (`contactFaces`, `contactSlaveFaces`) whose normal (b - a) x (c - a) points
/// into their body: InputError naming the face and its corners. The body's outward side is
/// read from K: K applied to the displacement u = x (a uniform dilation) gives at each
/// boundary node c * the integral of phi_j n over the boundary around it (c > 0 for an
/// elastic material), zero inside (docs/algorithms.md, "Which side of a surface is its
/// body's"). Faces whose corners get no such force (P2 vertex functions integrate to zero
/// on a flat face) are not judged.
void check_face_orientation(const std::vector<std::vector<std::array<int, 9>>>& faces, const std::vector<size_t>& ids,
                            const std::vector<SubdomainInput>& subdomains, const char* name);

/// Mortar contact takes P1 faces only: InputError when a face corner lies at the midpoint of
/// two coupled face corners of its subdomain (two nodes of one element), which only a
/// higher-order mesh has (`ffetiBoundaryFaces` gives a P2 face as its 4 sub-triangles).
void refuse_higher_order_faces(const std::vector<std::vector<std::array<int, 9>>>& faces, const std::vector<size_t>& ids,
                               const std::vector<SubdomainInput>& subdomains, const char* name);

/// The slave nodes' dilation forces along a flat obstacle's normal: `toward` their sum
/// (positive when the bodies' outward normals at the slaves point along the obstacle's
/// normal, i.e. the normal points into the bodies), `total` the sum of their magnitudes.
/// Summed over ranks by the caller; `obstacle_points_into_bodies` decides.
struct ObstacleFacing {
  double toward = 0, total = 0;
};
ObstacleFacing obstacle_facing(const std::vector<SubdomainInput>& subdomains, const ContactInput& contact);
bool obstacle_points_into_bodies(const ObstacleFacing& summed);

}  // namespace ffeti
