// One quadratic program as every solver of qp/ reads it (CONVENTIONS.md 13, PermonQP's QP
// object): minimize 1/2 x'Hx - b'x subject to a convex constraint set per block of
// components and, optionally, C x = 0 given by Q, the orthogonal projector onto Im C'.
// CG, MPRGP and SMALBE take it under one signature:
//   Result solver(const qp::Problem&, const Settings&, Vec& x /* start in, iterate out */,
//                 const qp::Budget&, const StopTest&, const Monitor& = {})
// A formulation (feti/dual_formulations.cpp) builds one; the solver that fits is chosen
// by the caller's path, not by which members are set.
#pragma once

#include "qp/qp_types.h"

#include <limits>
#include <vector>

namespace ffeti::qp {

/// The set a block of components must lie in. A new kind is one more value here and its
/// projection and chopped gradient in the solvers (qp/disc.h for discs); the solvers'
/// signatures stay.
enum class BlockKind {
  free,       ///< no constraint (equality multipliers)
  half_line,  ///< x_i >= l_i (contact multipliers)
  box,        ///< l_i <= x_i <= u_i (Tresca friction multipliers, l = -g, u = g)
  disc,       ///< pairs (x_i, x_i+1), i = first + 2j: ||x_pair - c_pair||_2 <= g_j (isotropic
              ///< friction in 3D, ALGORITHMS.md section 11)
};

/// Components [first, first + size) and the set they lie in.
struct Block {
  Eigen::Index first = 0;
  Eigen::Index size = 0;
  BlockKind kind = BlockKind::free;
};

/// The constraint set of a QP: consecutive blocks covering all components. The bounds are
/// stored per component (`lower` is kUnbounded on free components; `upper` is empty when no
/// block is a box, else +infinity outside boxes), since the solvers test them per component;
/// the blocks say which law holds where. A disc's components have no bounds (kUnbounded,
/// +infinity): the per-component tests below see them as free, and the solvers correct that
/// pair by pair from `disc_centre` and `disc_radius` (qp/disc.h) when `has_discs()`, so a
/// set without discs runs the per-component code alone.
class ConstraintSet {
 public:
  /// Appends a block: `lower` (and for a box `upper`) give its bounds; a free block needs only its size.
  void add_free(Eigen::Index size);
  void add_half_line(const Vec& lower);
  void add_box(const Vec& lower, const Vec& upper);
  /// Appends k discs: pair j (components first + 2j, first + 2j + 1) lies in
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
  Eigen::Index size() const { return lower.size(); }
  bool bounded() const;  ///< some block is not free
  bool has_discs() const { return disc_radius.size() > 0; }

  /// x_i strictly inside its bounds: free to move either way.
  bool free(Eigen::Index i, double x) const { return above_bound(x, lower[i]) && (upper.size() == 0 || x < upper[i]); }
  bool has_upper(Eigen::Index i) const {
    return upper.size() && upper[i] < std::numeric_limits<double>::infinity();
  }
  /// x_i at both bounds (l_i = u_i, e.g. a friction row whose bound is 0): it cannot move,
  /// whatever the sign of its gradient.
  bool pinned(Eigen::Index i, double x) const { return !above_bound(x, lower[i]) && upper.size() && x >= upper[i]; }

  Vec lower;  ///< per component, kUnbounded where free
  Vec upper;  ///< per component, +infinity where unbounded above; empty: no box block
  /// Per component, empty when no block is a disc: on a disc's components the centre of
  /// its pair's disc (0 elsewhere) and the pair's radius, on both of its components
  /// (+infinity elsewhere).
  Vec disc_centre, disc_radius;

 private:
  void append(BlockKind kind, const Vec& lower_part, const Vec& upper_part);
  void append_disc_data(Eigen::Index first, const Vec& centre_part, const Vec& radius_part);
  std::vector<Block> blocks_;
};

/// The QP. Owns b and the bounds; the operators are handles whose captured objects must
/// outlive the Problem (a formulation's dual operator, coarse space, projectors).
struct Problem {
  LinearOperator hessian;          ///< H, symmetric positive semidefinite
  Vec b;                           ///< linear term
  double hessian_norm = 0;         ///< upper estimate of ||H||_2 (MPRGP's step, SMALBE's penalty; 0 for CG)
  LinearOperator preconditioner;   ///< approximates H^+ (empty: none)
  LinearOperator range_projector;  ///< Q onto Im C' of the equality part C x = 0 (empty: none)
  /// SMALBE's multiplier term nu = C'mu to start from (empty: 0): a sequence of solves of
  /// one problem with other bounds (friction's fixed point) starts each from the last one's
  /// x and nu (SmalbeResult::multiplier); with x alone the Lagrangian's gradient at the
  /// start is off by the whole of nu, and every solve costs as much as a cold one.
  Vec equality_multiplier;
  ConstraintSet constraints;       ///< one block per group of components

  Eigen::Index size() const { return b.size(); }
};

/// What a solve may spend: Hessian multiplications, counted over everything it calls (a
/// nested solve gets what remains, never a fresh copy). Checked once, here.
class Budget {
 public:
  explicit Budget(int max_hessian);  ///< throws std::invalid_argument unless max_hessian >= 1
  int max_hessian() const { return max_hessian_; }
  /// What remains after `spent` multiplications (at least 0).
  int remaining(int spent) const { return spent >= max_hessian_ ? 0 : max_hessian_ - spent; }

 private:
  int max_hessian_;
};

}  // namespace ffeti::qp
