// The disc kind of qp/set_kind.h (isotropic friction's constraint set, ALGORITHMS.md
// section 11): each pair x_i, x_i+1 of the block lies in ||x_pair - c|| <= g. Its faces
// are curved: a pair on its circle is free along the tangent (MPGP slides it round the
// circle and projects it back), and the circle adds curvature to f along that tangent.
#pragma once

#include "qp/set_kind.h"

namespace ffeti::qp {

class DiscSet final : public SetKind {
 public:
  /// k discs from component `first` on: pair j lies in ||x_pair - centre.segment(2j, 2)||
  /// <= radius[j]. Throws std::invalid_argument unless centre has 2k entries, every radius
  /// is finite and >= 0 (0 pins the pair at its centre) and every centre finite.
  DiscSet(Eigen::Index first, const Vec& centre, const Vec& radius);
  std::shared_ptr<const SetKind> shifted(const Vec& offset) const override;

  /// Moves every pair outside its disc radially onto the circle.
  int project(Vec& x) const override;
  /// The same: every pair is on a curved face.
  int project_curved(Vec& x) const override { return project(x); }
  bool curved() const override { return true; }
  bool contains(const Vec& x) const override;

  /// On a pair on its circle, v's part along the tangent at x (the tangent counts as free:
  /// held, a pair slipping on its circle moves only by projected gradient steps, steepest
  /// descent, docs/algorithms.md); 0 on a pinned pair, and 0 on a pair whose circle's
  /// curvature there exceeds kStiffCircle ||A|| (a row slipping fast under a small bound:
  /// the projected step P(x - abar g) turns it best, close to Newton's step round the
  /// circle; CG round it, the curvature changing with every g, took 231 multiplications of
  /// the 3D forced slide against 83).
  void restrict_to_face(const Vec& x, const Vec& g, double a_norm, Vec& v) const override;
  void mark_free(const Vec& x, std::vector<char>& face) const override;
  /// g inside the disc; on the circle, with n the outward unit normal, g - min(n'g, 0) n
  /// (the normal part goes only where it points inward); 0 on a pinned pair.
  void projected_gradient(const Vec& x, const Vec& g, Vec& gp) const override;
  /// (x - P(x - abar phi)) / abar on every pair (on its circle phi is tangential, and phit
  /// the chord the step abar takes round it).
  void reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const override;
  /// The larger root of ||d - a p||^2 = g^2, d = x_pair - c (0 for a pair on or outside its
  /// circle moving out).
  double feasible_step(const Vec& x, const Vec& p, bool slide_on_circles) const override;

  /// On a pair on its circle whose -g points out (the disc holds it), (max(-n'g, 0) /
  /// radius) p_pair: a move s along the tangent followed by the projection back changes f by
  /// g't s + s^2 (t'At - n'g / radius) / 2 + O(s^3), so A plus this term is the Hessian of
  /// f round the circle (of the Lagrangian), the one a CG step that slides must use.
  void add_curvature(const Vec& x, const Vec& g, const Vec& p, Vec& Ap) const override;
  /// Divides v on each pair on its circle by 1 + c / a_norm, c that curvature: a diagonal
  /// preconditioner for it, which on a pair with a small radius and a large -n'g exceeds
  /// ||A|| by orders and would set every CG step.
  void precondition_curvature(const Vec& x, const Vec& g, double a_norm, Vec& v) const override;
  /// Whether a pair on its circle is stiff (restrict_to_face holds its tangent).
  bool holds_tangents(const Vec& x, const Vec& g, double a_norm) const override;
  double linear_minimum(const Vec& y, Vec& x) const override;
  void add_linear_minimizer_change(const Vec& y, const Vec& dy, Vec& dx) const override;

 private:
  /// The first component of every pair not strictly inside its disc: on the circle (to a
  /// relative 1e-12, so that a pair projected onto it counts as there despite round-off) or
  /// pinned by a radius 0.
  std::vector<Eigen::Index> held_pairs(const Vec& x) const;
  /// The curvature -n'g / ||d|| where -g points out (0 elsewhere) of the held pair at i, or
  /// -1 for a pinned pair (nothing moves it).
  double curvature(const Vec& x, const Vec& g, Eigen::Index i) const;
  Eigen::Vector2d offset_from_centre(const Vec& x, Eigen::Index i) const;
  double radius(Eigen::Index i) const { return radius_[(i - block().first) / 2]; }
  Vec centre_;  ///< 2 entries per pair
  Vec radius_;  ///< 1 per pair
};

}  // namespace ffeti::qp
