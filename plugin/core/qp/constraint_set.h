// The constraint set of one QP: consecutive blocks covering all components, each of one
// kind (qp/set_kind.h: free, half-line, box, disc), and the operations MPRGP, MPGP, SMALBE
// and the start settling take from it, applied block by block. The solvers call these and
// nothing kind-specific: on flat kinds the curved operations do nothing, so a set without
// discs runs MPRGP's own steps.
#pragma once

#include "qp/set_kind.h"

#include <memory>
#include <vector>

namespace ffeti::qp {

/// The free gradient's reduced part phit (SetKind::reduced_free_gradient) as MPRGP reads
/// it: phi'phit and ||phit||^2.
struct ReducedFreeGradient {
  double dot_phi = 0, squared_norm = 0;
};

class ConstraintSet {
 public:
  /// Appends a block: a free block needs only its size, a half-line its lower bounds, a box
  /// both (same size, else std::invalid_argument).
  void add_free(Eigen::Index size);
  void add_half_line(const Vec& lower);
  void add_box(const Vec& lower, const Vec& upper);
  /// Appends k discs (qp::DiscSet): pair j (components first + 2j, first + 2j + 1) lies in
  /// ||x_pair - centre.segment(2j, 2)||_2 <= radius[j]. Throws std::invalid_argument unless
  /// centre has 2k entries and every radius is >= 0 (0 pins the pair at its centre).
  void add_disc(const Vec& centre, const Vec& radius);
  /// Blocks from componentwise bounds: runs of free, lower-bounded and boxed components
  /// (`upper` empty or +infinity: no upper bound).
  static ConstraintSet from_bounds(const Vec& lower, const Vec& upper = Vec());

  /// The set of y = x - offset (x in this set): the same blocks, bounds and disc centres
  /// moved by -offset (the FETI dual's mu = lambda - lambda~: |lambda_t| <= g becomes a disc
  /// centred at -lambda~_t).
  ConstraintSet shifted(const Vec& offset) const;

  const std::vector<Block>& blocks() const { return blocks_; }
  Eigen::Index size() const { return size_; }
  bool bounded() const;  ///< some block is not free
  /// Componentwise bounds of the half-line and box blocks: kUnbounded and +infinity
  /// elsewhere (free components and disc pairs).
  Vec lower() const;
  Vec upper() const;

  /// The Euclidean projection onto the set; returns how many components (disc: pairs) moved.
  int project(Vec& x) const;
  /// The projection on the curved blocks only (SetKind::project_curved).
  int project_curved(Vec& x) const;
  bool contains(const Vec& x) const;

  /// phi: g restricted to the face of x (SetKind::restrict_to_face).
  void free_gradient(const Vec& x, const Vec& g, double a_norm, Vec& phi) const;
  void restrict_to_face(const Vec& x, const Vec& g, double a_norm, Vec& v) const;
  /// 1 where x_i is free to move in a face solve, 0 where held.
  std::vector<char> free_components(const Vec& x) const;
  /// Projected gradient gP = phi + beta of ALGORITHMS.md section 4 (box bounds as in
  /// section 9): gP_i = g_i where x_i is free, min(g_i, 0) where x_i = l_i, max(g_i, 0) where
  /// x_i = u_i, 0 where both; on a disc pair, g inside, g - min(n'g, 0) n on the circle (n the
  /// outward unit normal), 0 at radius 0.
  Vec projected_gradient(const Vec& x, const Vec& g) const;
  /// The same into gp (sized like x): MPRGP's iterations reuse one vector.
  void projected_gradient(const Vec& x, const Vec& g, Vec& gp) const;
  /// ||gP||_inf.
  double projected_gradient_max(const Vec& x, const Vec& g) const;
  /// phi'phit and ||phit||^2, summed component by component.
  /// `phit` (sized like x) is the caller's workspace: one per solve, not one per iteration.
  ReducedFreeGradient reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const;
  /// Some block has a curved face (a disc's circle): a step inside the set's faces may need
  /// project_curved after it; on flat faces it never does.
  bool curved() const;
  /// Largest a >= 0 with x - a p in the set (SetKind::feasible_step).
  double feasible_step(const Vec& x, const Vec& p, bool slide_on_circles) const;

  void add_curvature(const Vec& x, const Vec& g, const Vec& p, Vec& Ap) const;
  void precondition_curvature(const Vec& x, const Vec& g, double a_norm, Vec& v) const;
  bool holds_tangents(const Vec& x, const Vec& g, double a_norm) const;
  /// Over the bounded blocks (box, disc) only, SetKind::linear_minimum: the point of each
  /// minimizing y'x written into x there (x's other components untouched), the sum returned.
  double linear_minimum(const Vec& y, Vec& x) const;
  /// Over the bounded blocks, SetKind::add_linear_minimizer_change.
  void add_linear_minimizer_change(const Vec& y, const Vec& dy, Vec& dx) const;
  /// Components above a finite lower bound: for the FETI dual, the contact set.
  int off_bound_count(const Vec& x) const;

 private:
  void append(std::shared_ptr<const SetKind> kind);
  void componentwise_bounds(Vec& lower, Vec& upper) const;
  std::vector<Block> blocks_;
  /// Immutable, so a copy of the set (SMALBE's inner problem) shares them.
  std::vector<std::shared_ptr<const SetKind>> kinds_;
  Eigen::Index size_ = 0;
};

}  // namespace ffeti::qp
