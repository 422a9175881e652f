// A contact row's linear condition in closed form (node to segment, rigid obstacle): the
// set-up builds its rows from it and the sensitivity analysis differentiates it.
#pragma once

#include "constraints/contact/point3.h"

#include <array>

namespace ffeti {

using Point = std::array<double, 2>;

/// Node to segment: slave s projected on segment a-b (the body of the segment on its left),
/// p = (1 - xi) a + xi b, n the outward normal; n.(u_p - u_s) <= n.(s - p).
/// `clamp_xi` keeps p on the segment (the set-up); the derivative of a row keeps its pairing
/// and differentiates the unclamped formula.
struct LinearizedRow {
  std::array<double, 6> coefficients;  ///< of (s_x, s_y, a_x, a_y, b_x, b_y); obstacle: (s_x, s_y)
  double gap;
};
LinearizedRow node_to_segment_row(const Point& s, const Point& a, const Point& b, bool clamp_xi = true);
/// Rigid obstacle through `point` with outward unit normal n: -n.u_s <= n.(s - point).
LinearizedRow obstacle_row(const Point& s, const Point& point, const Point& normal);

/// The slip of a contact row's slave along the master, t.(u_s - u_p), with t the unit
/// tangent (b - a)/|b - a| of the segment, or on an obstacle the line's direction
/// (-n_y, n_x): the same turn from the outward normal in both. Coefficients as above; the
/// gap is 0 (the slip is measured from the state of the last load step).
LinearizedRow node_to_segment_slip(const Point& s, const Point& a, const Point& b);

/// Node to face (three dimensions): slave s against triangle a, b, c with outward normal
/// n = (b - a) x (c - a) / |.|, p its closest point, w its barycentric weights:
/// n.(sum_i w_i u_i - u_s) <= n.(s - p). Coefficients of (s_x, s_y, s_z, a_x, ..., c_z).
struct LinearizedFaceRow {
  std::array<double, 12> coefficients;
  double gap;
  std::array<double, 3> weights;  ///< w of p
};
/// `clamp` keeps p on the triangle (the set-up); the derivative of a row keeps its pairing
/// and differentiates the unclamped formula (p the projection on the triangle's plane).
/// `direction` (a unit vector, not parallel to the plane; contactNormal slave or average):
/// the row's n instead of the face's, p the point of the plane s projects on along it
/// (clamped: the triangle's point nearest to that one).
LinearizedFaceRow node_to_face_row(const Point3& s, const Point3& a, const Point3& b, const Point3& c,
                                   bool clamp = true, const Point3* direction = nullptr);
/// The barycentric weights (w_a, w_b, w_c) of s's projection on the plane of triangle a, b, c:
/// negative outside the triangle (a row's derivative keeps them unclamped).
std::array<double, 3> plane_weights(const Point3& s, const Point3& a, const Point3& b, const Point3& c);
/// The closest point of triangle a, b, c to s as barycentric weights (w_a, w_b, w_c).
std::array<double, 3> closest_point_weights(const Point3& s, const Point3& a, const Point3& b, const Point3& c);

}  // namespace ffeti
