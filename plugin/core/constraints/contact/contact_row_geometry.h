// A contact row's linearized condition as a function of the positions it was built from,
// one type per contact kind: the sensitivity analysis moves its nodes and differentiates
// it, friction asks it for the tangential row.
#pragma once

#include "constraints/capabilities.h"
#include "constraints/contact/point3.h"

#include <array>
#include <initializer_list>
#include <string>
#include <vector>

namespace ffeti {

/// A dof as (global subdomain, local dof); {-1, -1}: none.
using DofRef = std::array<int, 2>;

/// A row's condition over `dofs`: sum coefficients[k] u(dofs[k]) <= gap. Entries whose dof
/// is {-1, -1} are none (a plane problem's z).
struct RowAt {
  std::vector<DofRef> dofs;
  std::vector<double> coefficients;
  double gap = 0;
};

/// The velocities of a row's moving nodes, in moving_nodes() order; a node past the end
/// stands still (so {} is no motion). Any number of nodes: a mortar row moves with every
/// corner of its slave faces and of the master faces they overlap.
class NodeMotion {
 public:
  NodeMotion() = default;
  NodeMotion(std::initializer_list<Point3> velocities) : velocities_(velocities) {}
  explicit NodeMotion(size_t nodes) : velocities_(nodes, Point3{0, 0, 0}) {}
  const Point3& operator[](size_t node) const {
    static const Point3 still{0, 0, 0};
    return node < velocities_.size() ? velocities_[node] : still;
  }
  Point3& operator[](size_t node) { return velocities_.at(node); }
  std::vector<Point3>::const_iterator begin() const { return velocities_.begin(); }
  std::vector<Point3>::const_iterator end() const { return velocities_.end(); }
  /// The fastest node of the whole design (every row's), 0 if not known: a row whose own
  /// nodes move by round-off only (a velocity field that vanishes there) is judged against it.
  double reference_speed = 0;

 private:
  std::vector<Point3> velocities_;
};

class ContactRowGeometry {
 public:
  ContactRowGeometry(ContactKind kind, DofRef slave_dof, const Point3& slave_position, bool three_d)
      : kind_(kind), slave_dof_(slave_dof), slave_position_(slave_position), three_d_(three_d) {}
  virtual ~ContactRowGeometry() = default;

  ContactKind kind() const { return kind_; }
  /// The slave dof that carries the row's gap_field entry (its component 0).
  DofRef slave_dof() const { return slave_dof_; }
  const Point3& slave_position() const { return slave_position_; }  ///< z = 0 in a plane problem
  bool three_d() const { return three_d_; }

  /// The nodes whose motion moves the row, each named by its x dof (empty: the row does
  /// not depend on positions).
  virtual std::vector<DofRef> moving_nodes() const = 0;
  /// The row with its nodes moved by t times `velocities`, keeping its pairing (segment or
  /// face, and slave): the projection is not clamped.
  virtual RowAt row_at(const NodeMotion& velocities, double t) const = 0;
  /// The length the geometry is measured in: the step of the differences scales with it.
  virtual double length() const = 0;
  /// The row's unit normal n (docs/reference.md, "Signs"): the master's outward normal at
  /// the slave's closest point, pointing from the master to the slave; the row is
  /// n.(u_master - u_slave) <= gap and its multiplier pushes the slave along n (z = 0 in a
  /// plane problem).
  virtual Point3 normal() const = 0;
  /// The row's tangents, functions of normal() alone: in the plane t1 = (-n_y, n_x) (the
  /// turn a segment's direction makes from its outward normal) and t2 = 0; in three
  /// dimensions tangent_pair(n). The friction rows are the slips along them.
  std::array<Point3, 2> tangents() const;
  /// The tangential rows of friction, the slips t.(u_slave - u_master) from the last load
  /// step's state (gap 0): one in a plane problem, two in three dimensions along
  /// tangent_pair(n) of the row's normal n, t1 then t2 (their multipliers form one disc).
  virtual std::vector<RowAt> slip_rows() const = 0;
  /// Why the derivative of this row along `velocities` is not the cost's (one-sided: the
  /// pairing would change on one side), or "" when it is: the sensitivities refuse such a
  /// motion of a row they use rather than answer wrongly.
  virtual std::string unverified_motion(const NodeMotion& /*velocities*/) const { return ""; }
  /// True where the row keeps its pairing along `velocities` but its derivative is one-sided
  /// all the same, so the sensitivities answer with a warning and a status instead of
  /// refusing (node to face: a slave on an edge between faces that bend against each other).
  virtual bool one_sided_under(const NodeMotion& /*velocities*/) const { return false; }

 private:
  ContactKind kind_;
  DofRef slave_dof_;
  Point3 slave_position_;
  bool three_d_;
};

/// The slip directions of friction for a row's unit normal n (out of the master, towards the
/// slave): in a plane problem the turn (-n_y, n_x) a segment's tangent makes from its outward
/// normal, in three dimensions tangent_pair(n).
std::vector<Point3> slip_directions(const Point3& n, bool three_d);

/// The slip rows t.u_s of a slave against a rigid surface (a plane, a ball) of unit normal n
/// at the slave: the surface does not move. `slave`: its x, y, z dofs (z {-1, -1} in a plane
/// problem).
std::vector<RowAt> rigid_slip_rows(const std::array<DofRef, 3>& slave, const Point3& n, bool three_d);

/// The step of the central differences of `g`'s row along `velocities`: the fastest node
/// moves by 1e-6 of g.length() (truncation ~1e-12, round-off ~1e-10 relative); 0 when
/// nothing moves.
double difference_step(const ContactRowGeometry& g, const NodeMotion& velocities);

inline Point3 moved(const Point3& p, const Point3& velocity, double t) {
  return {p[0] + t * velocity[0], p[1] + t * velocity[1], p[2] + t * velocity[2]};
}

}  // namespace ffeti
