#include "constraints/surface_checks.h"

#include "constraints/contact/obstacle.h"
#include "base/errors.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace ffeti {
namespace {

double coordinate(const SubdomainInput& sub, size_t dof, int axis) {
  return axis == 0 ? sub.x[dof] : axis == 1 ? sub.y[dof] : sub.z[dof];
}

/// At one dof: (K u)_i for the dilation u_j = (coordinate of dof j's node along its
/// component), taken relative to dof i's node so that a large diagonal (a Dirichlet
/// penalty, a lumped mass) or a rigid translation adds nothing; and the sum of the terms'
/// magnitudes, the scale against which a vanishing force is judged. Only a row whose
/// couplings to other dofs of its component sum negative reads a side: a stiffness's do
/// (they balance its diagonal under a translation), a consistent mass's sum positive, and
/// its dilation force points into the body (M itself as the matrix of a mass-norm
/// projection, or K + c M where the inertia dominates a short time step): no verdict there.
struct DilationForce {
  double force = 0, magnitude = 0;
};
DilationForce dilation_force(const SubdomainInput& sub, int dof) {
  DilationForce out;
  double couplings = 0;
  const int own_axis = sub.component[static_cast<size_t>(dof)];
  for (SparseMatrix::InnerIterator it(sub.K, dof); it; ++it) {  // K symmetric: column = row
    const int axis = sub.component[static_cast<size_t>(it.row())];
    if (it.row() != dof && axis == own_axis) couplings += it.value();
    const double term = it.value() * (coordinate(sub, static_cast<size_t>(it.row()), axis) -
                                      coordinate(sub, static_cast<size_t>(dof), axis));
    out.force += term, out.magnitude += std::abs(term);
  }
  if (!(couplings < 0)) return {};
  return out;
}

std::string point_text(const SubdomainInput& sub, size_t dof) {
  return "(" + std::to_string(sub.x[dof]) + ", " + std::to_string(sub.y[dof]) + ", " + std::to_string(sub.z[dof]) + ")";
}

}  // namespace

void check_face_orientation(const std::vector<std::vector<std::array<int, 9>>>& faces, const std::vector<size_t>& ids,
                            const std::vector<SubdomainInput>& subdomains, const char* name) {
  for (size_t k = 0; k < faces.size(); ++k) {
    const SubdomainInput& sub = subdomains[k];
    if (sub.z.empty() || sub.component.empty()) continue;  // faces need both (checked elsewhere)
    for (size_t f = 0; f < faces[k].size(); ++f) {
      const auto& dofs = faces[k][f];
      const auto at = [&](size_t corner, size_t i) { return static_cast<size_t>(dofs[3 * corner + i]); };
      double u[3], v[3];
      for (int i = 0; i < 3; ++i)
        u[i] = coordinate(sub, at(1, 0), i) - coordinate(sub, at(0, 0), i),
        v[i] = coordinate(sub, at(2, 0), i) - coordinate(sub, at(0, 0), i);
      const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      const double area = std::hypot(n[0], n[1], n[2]);
      double along = 0, size = 0, magnitude = 0;
      for (size_t corner = 0; corner < 3; ++corner) {
        double force[3];
        for (size_t i = 0; i < 3; ++i) {
          const DilationForce d = dilation_force(sub, dofs[3 * corner + i]);
          force[i] = d.force, magnitude += d.magnitude;
          along += d.force * n[i] / area;
        }
        size += std::hypot(force[0], force[1], force[2]);
      }
      // A reversed face's corners are pushed against its normal by about their whole force;
      // a correct one at a concave edge may lean a little the other way.
      if (size > 1e-6 * magnitude && along < -0.25 * size)
        throw InputError(std::string(name) + "[" + std::to_string(ids[k]) + "]: face " + std::to_string(f) +
                         " (corners " + point_text(sub, at(0, 0)) + ", " + point_text(sub, at(1, 0)) + ", " +
                         point_text(sub, at(2, 0)) + ") has its normal (b - a) x (c - a) pointing into its body (K[" +
                         std::to_string(ids[k]) + "] says the body's outside is the other side): list its corners "
                         "as a, c, b; every face must point out of its body (ffetiBoundaryFaces orients them so)");
    }
  }
}

void refuse_higher_order_faces(const std::vector<std::vector<std::array<int, 9>>>& faces, const std::vector<size_t>& ids,
                               const std::vector<SubdomainInput>& subdomains, const char* name) {
  for (size_t k = 0; k < faces.size(); ++k) {
    if (k >= subdomains.size()) break;  // a list for more subdomains: refused by its list's own check
    const SubdomainInput& sub = subdomains[k];
    if (faces[k].empty() || sub.z.empty()) continue;
    // A face with a dof outside its subdomain is refused by its list's own check.
    const auto outside = [&](int dof) { return dof < 0 || static_cast<size_t>(dof) >= sub.x.size(); };
    if (std::any_of(faces[k].begin(), faces[k].end(),
                    [&](const auto& face) { return std::any_of(face.begin(), face.end(), outside); }))
      continue;
    // The x dofs of the faces' corners by position, rounded to a length far below any edge.
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& face : faces[k])
      for (size_t corner = 0; corner < 3; ++corner)
        for (int i = 0; i < 3; ++i) {
          const double c = coordinate(sub, static_cast<size_t>(face[3 * corner]), i);
          lo = std::min(lo, c), hi = std::max(hi, c);
        }
    const double unit = std::max(hi - lo, 1e-300) * 1e-9;
    using Key = std::array<long long, 3>;
    const auto key_of = [&](const double p[3]) {
      return Key{std::llround(p[0] / unit), std::llround(p[1] / unit), std::llround(p[2] / unit)};
    };
    std::map<Key, int> corner_at;
    for (const auto& face : faces[k])
      for (size_t corner = 0; corner < 3; ++corner) {
        const auto dof = static_cast<size_t>(face[3 * corner]);
        const double p[3] = {sub.x[dof], sub.y[dof], sub.z[dof]};
        corner_at.emplace(key_of(p), face[3 * corner]);
      }
    const auto found_near = [&](const double p[3]) {
      const Key centre = key_of(p);
      for (long long dx = -1; dx <= 1; ++dx)
        for (long long dy = -1; dy <= 1; ++dy)
          for (long long dz = -1; dz <= 1; ++dz)
            if (corner_at.count({centre[0] + dx, centre[1] + dy, centre[2] + dz})) return true;
      return false;
    };
    for (const auto& [position, a] : corner_at)
      for (SparseMatrix::InnerIterator it(sub.K, a); it; ++it) {
        const auto b = static_cast<size_t>(it.row());
        if (static_cast<int>(b) <= a || (!sub.component.empty() && sub.component[b] != 0)) continue;
        const double q[3] = {sub.x[b], sub.y[b], sub.z[b]};
        if (!corner_at.count(key_of(q))) continue;  // b: not a face corner (or another component's dof)
        const auto i = static_cast<size_t>(a);
        const double middle[3] = {(sub.x[i] + q[0]) / 2, (sub.y[i] + q[1]) / 2, (sub.z[i] + q[2]) / 2};
        if (std::hypot(q[0] - sub.x[i], q[1] - sub.y[i], q[2] - sub.z[i]) > 10 * unit && found_near(middle))
          throw InputError(std::string(name) + "[" + std::to_string(ids[k]) + "]: the face corner at " +
                           point_text(sub, static_cast<size_t>(corner_at.at(key_of(middle)))) +
                           " is the midpoint of two nodes of one element, " + point_text(sub, i) + " and " +
                           point_text(sub, b) + ": these are a higher-order (P2) mesh's faces, and mortar contact "
                           "takes P1 faces only (use P1 for the contact bodies, or node-to-face contact: "
                           "contactSlave with contactFaces)");
      }
  }
}

ObstacleFacing obstacle_facing(const std::vector<SubdomainInput>& subdomains, const ContactInput& contact) {
  ObstacleFacing out;
  const ObstacleInput& plane = contact.input_of<ObstacleInput>();
  if (!plane.given) return out;
  const auto& normal = plane.normal;
  const double norm = std::hypot(normal[0], normal[1], normal[2]);
  if (!(norm > 0)) return out;  // refused with the rows
  double magnitude = 0;
  for (size_t k = 0; k < subdomains.size() && k < contact.slave_dofs.size(); ++k) {
    const SubdomainInput& sub = subdomains[k];
    if (sub.component.empty()) continue;  // a scalar field: no outward direction to read
    for (int dof : contact.slave_dofs[k]) {
      const DilationForce d = dilation_force(sub, dof);
      const double along = d.force * normal[static_cast<size_t>(sub.component[static_cast<size_t>(dof)])] / norm;
      out.toward += along, out.total += std::abs(along), magnitude += d.magnitude;
    }
  }
  if (out.total <= 1e-6 * magnitude) out = {};  // forces lost in rounding (P2 vertices): no judgement
  return out;
}

bool obstacle_points_into_bodies(const ObstacleFacing& summed) {
  // The slaves of a body resting on a correct plane are pushed against its normal by all of
  // their force (toward = -total); a closed surface of slaves sums to about zero.
  return summed.total > 0 && summed.toward > 0.5 * summed.total;
}

}  // namespace ffeti
