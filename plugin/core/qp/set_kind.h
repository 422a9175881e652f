// One kind of convex set a block of consecutive components of a QP lies in, with the
// operations MPRGP and MPGP take from it (PermonQP's QPC objects: projection, gradient
// splitting, feasible step, reduced gradient). One class per kind (qp/bound_sets.h: free,
// half-line, box; qp/disc_set.h: disc); qp::ConstraintSet (qp/constraint_set.h) holds the blocks
// of one problem and applies each operation block by block, so the solvers are written
// once against it and a new kind is one more class here, not a branch in them.
//
// Every operation reads and writes the block's components [first, first + size) of
// full-length vectors: x the iterate (feasible unless said otherwise), g = Ax - b, a_norm an
// upper estimate of ||A||_2.
#pragma once

#include "qp/qp_types.h"

#include <memory>
#include <stdexcept>
#include <vector>

namespace ffeti::qp {

/// The set a block of components must lie in.
enum class BlockKind {
  free,       ///< no constraint (equality multipliers)
  half_line,  ///< x_i >= l_i (contact multipliers)
  box,        ///< l_i <= x_i <= u_i (Tresca friction multipliers in 2D, l = -g, u = g)
  disc,       ///< pairs (x_i, x_i+1), i = first + 2j: ||x_pair - c_pair||_2 <= g_j (isotropic
              ///< friction in 3D, ALGORITHMS.md section 11)
};

/// Components [first, first + size) and the set they lie in.
struct Block {
  Eigen::Index first = 0;
  Eigen::Index size = 0;
  BlockKind kind = BlockKind::free;
  /// A box or a disc: bounded in every direction, so a linear function has a minimum on it
  /// (SetKind::linear_minimum; ConstraintSet::bounded means some block is not free).
  bool compact() const { return kind == BlockKind::box || kind == BlockKind::disc; }
};

class SetKind {
 public:
  explicit SetKind(const Block& block) : block_(block) {}
  virtual ~SetKind() = default;
  const Block& block() const { return block_; }

  /// The set of y = x - offset (offset full-length): bounds and centres moved by -offset.
  virtual std::shared_ptr<const SetKind> shifted(const Vec& offset) const = 0;

  /// The Euclidean projection of x onto the block's set; returns the components (disc:
  /// pairs) it moved.
  virtual int project(Vec& x) const = 0;
  /// The projection where the set is curved only (disc pairs), nothing on flat faces: a
  /// step along the face of a feasible x, within feasible_step(..., slide = true), leaves a
  /// curved face by a second-order amount and stays in a flat one. Returns what moved.
  virtual int project_curved(Vec& x) const { (void)x; return 0; }
  /// True where the set has curved faces (project_curved may move a point): discs.
  virtual bool curved() const { return false; }
  /// Whether x lies in the set (no tolerance).
  virtual bool contains(const Vec& x) const = 0;

  /// Restricts v to the face of x: 0 where x is at a bound (both ways for a pinned
  /// component), the tangent on a disc pair on its circle, 0 on a pair on a circle that
  /// curves too much there for its tangent to count as free (qp/disc_set.h). The free
  /// gradient phi is g so restricted.
  virtual void restrict_to_face(const Vec& x, const Vec& g, double a_norm, Vec& v) const = 0;
  /// face[i] = 0 where x_i is held (at a bound, a disc pair not strictly inside): the
  /// components a face solve keeps fixed (qp/start_settling.h).
  virtual void mark_free(const Vec& x, std::vector<char>& face) const = 0;
  /// gp = the projected gradient, minus the projection of -g onto the tangent cone at x.
  virtual void projected_gradient(const Vec& x, const Vec& g, Vec& gp) const = 0;
  /// phit = (x - P(x - abar phi)) / abar on the free part, phi elsewhere: the part of the
  /// free gradient a step abar can take without leaving the set.
  virtual void reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const = 0;
  /// Largest a >= 0 keeping x - a p in the set; with `slide_on_circles` the pairs on their
  /// circle left out (p moves them along the tangent, project_curved brings them back).
  virtual double feasible_step(const Vec& x, const Vec& p, bool slide_on_circles) const = 0;

  /// Adds to Ap the curvature the set adds to f along its curved faces (0 on flat ones).
  virtual void add_curvature(const Vec& x, const Vec& g, const Vec& p, Vec& Ap) const {
    (void)x, (void)g, (void)p, (void)Ap;
  }
  /// Scales v by the inverse of 1 + that curvature / a_norm (nothing on flat faces).
  virtual void precondition_curvature(const Vec& x, const Vec& g, double a_norm, Vec& v) const {
    (void)x, (void)g, (void)a_norm, (void)v;
  }
  /// Whether restrict_to_face holds a tangent that a projected step should turn (a disc
  /// pair on a stiff circle); flat faces never do.
  virtual bool holds_tangents(const Vec& x, const Vec& g, double a_norm) const {
    (void)x, (void)g, (void)a_norm;
    return false;
  }

  /// Bounded kinds only (box, disc; qp/held_modes.h): writes into x's block the point of the
  /// set minimizing y'x (a box: the bound against y_i's sign, the middle where y_i = 0; a
  /// disc: c - g y/||y||, c where y = 0) and returns y'x there. Free and half-line blocks
  /// are unbounded along some y and throw std::logic_error.
  virtual double linear_minimum(const Vec& y, Vec& x) const {
    (void)y, (void)x;
    throw std::logic_error("linear_minimum: an unbounded block");
  }
  /// Adds to dx that point's change along dy: on a disc pair -g (I - yy'/||y||^2) dy / ||y||
  /// (the point turns round its circle), 0 on flat faces.
  virtual void add_linear_minimizer_change(const Vec& y, const Vec& dy, Vec& dx) const {
    (void)y, (void)dy, (void)dx;
  }

  /// Components above a finite lower bound: for the FETI dual, contact rows in contact.
  virtual int off_bound_count(const Vec& x) const { (void)x; return 0; }
  /// Writes the block's componentwise bounds into lower and upper (pre-filled with
  /// kUnbounded and +infinity: free and disc components have none).
  virtual void write_bounds(Vec& lower, Vec& upper) const { (void)lower, (void)upper; }

 private:
  Block block_;
};

}  // namespace ffeti::qp
