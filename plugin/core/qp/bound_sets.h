// The flat kinds of qp/set_kind.h: free components, half-lines x_i >= l_i and boxes
// l_i <= x_i <= u_i. Their faces are flat, so they have no curvature and no sliding: the
// projection, free set, chopped gradient and feasible step are per component (Dostal's
// MPRGP with bounds on one side or on both).
#pragma once

#include "qp/set_kind.h"

namespace ffeti::qp {

/// No constraint: every component is free, the projected gradient is g.
class FreeSet final : public SetKind {
 public:
  FreeSet(Eigen::Index first, Eigen::Index size) : SetKind({first, size, BlockKind::free}) {}
  std::shared_ptr<const SetKind> shifted(const Vec& offset) const override;
  int project(Vec&) const override { return 0; }
  bool contains(const Vec&) const override { return true; }
  void restrict_to_face(const Vec&, const Vec&, double, Vec&) const override {}
  void mark_free(const Vec&, std::vector<char>&) const override {}
  void projected_gradient(const Vec& x, const Vec& g, Vec& gp) const override;
  void reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const override;
  double feasible_step(const Vec&, const Vec&, bool) const override;
};

/// Componentwise bounds: lower only (kTwoSided false, the half-line of a contact row) or
/// lower and upper (a box, Tresca's |lambda_t| <= g in 2D). A component with l_i = u_i is
/// pinned: it cannot move whatever the sign of its gradient.
template <bool kTwoSided>
class BoundSet final : public SetKind {
 public:
  /// `upper` is ignored (and may be empty) for a half-line.
  BoundSet(Eigen::Index first, const Vec& lower, const Vec& upper);
  std::shared_ptr<const SetKind> shifted(const Vec& offset) const override;
  int project(Vec& x) const override;
  bool contains(const Vec& x) const override;
  void restrict_to_face(const Vec& x, const Vec& g, double a_norm, Vec& v) const override;
  void mark_free(const Vec& x, std::vector<char>& face) const override;
  void projected_gradient(const Vec& x, const Vec& g, Vec& gp) const override;
  void reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const override;
  double feasible_step(const Vec& x, const Vec& p, bool slide_on_circles) const override;
  int off_bound_count(const Vec& x) const override;
  double linear_minimum(const Vec& y, Vec& x) const override;
  void write_bounds(Vec& lower, Vec& upper) const override;

 private:
  double lower(Eigen::Index i) const { return lower_[i - block().first]; }
  double upper(Eigen::Index i) const { return upper_[i - block().first]; }
  bool has_upper(Eigen::Index i) const;
  /// x_i strictly inside its bounds: free to move either way.
  bool free(Eigen::Index i, double x) const;
  Vec lower_, upper_;  ///< the block's bounds (upper_ empty for a half-line)
};

using HalfLineSet = BoundSet<false>;
using BoxSet = BoundSet<true>;

}  // namespace ffeti::qp
