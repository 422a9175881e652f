// What a front end (the FreeFEM binding, a test) hands to the core for one problem.
#pragma once

#include "base/linear_algebra.h"
#include "constraints/capabilities.h"

#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace ffeti {

/// A stiffness matrix held by reference count, read-only: subdomains given the same matrix
/// (the identical boxes of a structured split, fetiSetup's stiffnessOf=) share one copy
/// instead of holding one each (1024 boxes of 3D elasticity: 2.2 GB of copies) and are
/// checked once. Assigning a SparseMatrix makes a new matrix of its own.
class SharedMatrix {
 public:
  SharedMatrix() : held_(std::make_shared<Held>()) {}
  SharedMatrix(SparseMatrix matrix, std::string name = {})  // NOLINT(google-explicit-constructor): reads as a SparseMatrix
      : held_(std::make_shared<Held>(Held{std::move(matrix), std::move(name)})) {}
  operator const SparseMatrix&() const { return held_->matrix; }  // NOLINT(google-explicit-constructor)
  const SparseMatrix& get() const { return held_->matrix; }
  Eigen::Index rows() const { return held_->matrix.rows(); }
  Eigen::Index cols() const { return held_->matrix.cols(); }
  /// What errors call it where it is not subdomain s's own K[s] (e.g. "K[2]" of stiffnessOf=);
  /// empty: the subdomain's K.
  const std::string& name() const { return held_->name; }
  /// The matrix to change in place, first copied where other holders share it (so that
  /// changing one subdomain's stiffness never changes another's).
  SparseMatrix& edit() {
    if (held_.use_count() > 1) held_ = std::make_shared<Held>(*held_);
    return held_->matrix;
  }

 private:
  struct Held {
    SparseMatrix matrix;
    std::string name;
  };
  std::shared_ptr<Held> held_;
};

/// One subdomain's finite element data. Dofs that stand for the same physical node and
/// field component in several subdomains of one body are recognised by equal coordinates
/// and glued; dofs of different bodies are never glued.
struct SubdomainInput {
  SharedMatrix K;                 ///< stiffness, symmetric, full (not half) storage
  Vec f;                          ///< load
  std::vector<double> x, y;       ///< coordinates of each dof's node
  std::vector<double> z;          ///< third coordinate (empty: a plane problem; every subdomain alike)
  std::vector<int> component;     ///< field component of each dof (empty: scalar field; 0..2 in 3D)
  int body = 0;                   ///< body the subdomain belongs to
  std::vector<int> dirichlet_dofs;      ///< local dofs with a prescribed value
  std::vector<double> dirichlet_values; ///< their values (empty: all zero)
};

/// Whose normal a node-to-face row takes (contactNormal=): the master face's (the default),
/// the slave surface's at the slave node (the area-weighted normals of the slave body's
/// faces in contactFaces around it), or the two averaged (docs/reference.md, "contactNormal").
enum class ContactNormal { master, slave, average };

/// Contact conditions, linearized for small displacements; one row per physical slave node
/// (its copies in other subdomains are glued to it). Each contact kind is a unit of
/// constraints/contact/ that reads, checks and uses its own input: the fields below are
/// grouped by the kind that owns them (docs/architecture.md, "A contact kind").
struct ContactInput {
  /// Shared: the slave dofs of every kind but mortar, per subdomain (may be empty).
  std::vector<std::vector<int>> slave_dofs;

  // ---- each list kind's own per-subdomain list (ListInput: read by its read_list, checked
  // by its check_against; fetiSetup's argument and ffeti-solve's key in its unit) ----
  /// Node to node (contactMaster; matching meshes): each slave dof pairs with the master
  /// dof of another body at the same position and component: u_slave - u_master <= gap.
  /// (For the seed's membranes, u1(1,y) <= u2(1,y): slaves on body 1, masters on body 2.)
  std::vector<std::vector<int>> master_dofs;
  double gap = 0;  ///< node to node's gap
  /// Node to segment (contactSegments; 2D vector fields): per subdomain (a_x, a_y, b_x, b_y).
  /// Each slave node (both its dofs in slave_dofs) is projected on the nearest master segment
  /// of another body within search_distance; with p = (1 - xi) a + xi b and n the segment's
  /// outward normal, n.(u_p - u_slave) <= n.(x_slave - p). Segments run with their body on the
  /// left (FreeFEM's orientation of a counter-clockwise border), so n = (b - a) rotated clockwise.
  std::vector<std::vector<std::array<int, 4>>> master_segments;
  /// Node to face (contactFaces; three dimensions; mortar's master faces too): per subdomain
  /// the master triangles, each the x, y, z dofs of its corners a, b, c, ordered so that
  /// (b - a) x (c - a) points out of its body. Each slave node (its three dofs in slave_dofs)
  /// is projected on the nearest face of another body within search_distance, p its closest
  /// point, n the face's unit normal: n.(u_p - u_slave) <= n.(x_slave - p), u_p interpolated
  /// linearly on the face.
  std::vector<std::vector<std::array<int, 9>>> master_faces;
  ContactNormal normal = ContactNormal::master;  ///< node to face's row normal (contactNormal=)
  /// Mortar (contactSlaveFaces; three dimensions): per subdomain the slave triangles, ordered
  /// like the master faces (outward normal). Their corners are the slave nodes (slave_dofs then
  /// stays empty), each with one row: the normal gap weighted by its shape function phi_j and
  /// integrated over the overlap of its slave faces with the master faces of another body
  /// facing them (each slave face projected on a master face's plane along that face's
  /// normal n, within search_distance and the nearest master's distance plus two edges):
  /// sum over the pairs of int phi_j n.(u_m - u_s) <= int phi_j n.(x_s - x_m), divided by
  /// int phi_j so that the multiplier is a force as in the other rows. A uniform pressure
  /// passes exactly (docs/algorithms.md, "Mortar").
  std::vector<std::vector<std::array<int, 9>>> slave_faces;
  /// The kinds that search masters (node to segment, node to face, mortar): farther slaves get no row.
  double search_distance = 1e300;

  // ---- the kinds that own an array of parameters (KindInput) ----
  /// The plane obstacle (obstacle=, read by contact/obstacle.cpp): a line (a plane in 3D)
  /// through obstacle_point with outward normal obstacle_normal (pointing away from the
  /// obstacle): -n.u_slave <= n.(x_slave - point).
  bool obstacle = false;
  std::array<double, 3> obstacle_point{0, 0, 0}, obstacle_normal{0, 1, 0};  ///< z entries: 3D only
  /// The other kinds that own their input (the ball, the cylinder, ...): per kind the entries
  /// of its fetiSetup argument (or of its problem-file key's fields), read and checked by its
  /// unit. A kind given here takes the slave nodes of contactSlave.
  std::map<ContactKind, std::vector<double>> kind_parameters;

  // ---- shared by every kind ----
  /// Per subdomain, one value per dof (empty: none): a clearance added to the right-hand
  /// side of the contact row of each slave node, read at its slave dof (node to node) or
  /// at its component-0 dof (node to segment, obstacle): a gap per contact row, e.g. the
  /// profile of a contact surface described by its gap rather than by its mesh.
  std::vector<std::vector<double>> gap_field;
  /// Set by the set-up (not the caller): the subdomains have a third coordinate.
  bool three_d = false;
  /// Friction (every kind; docs/algorithms.md, "Friction"): each contact row gets a
  /// tangential row, the slip t.(u_slave - u_p) of the slave along the master's tangent t (on
  /// an obstacle the line's direction, node to node the other component) measured from
  /// the state of the last load step, whose multiplier, the friction force, keeps
  /// |lambda_t| <= g; in 3D two, along tangent_pair(n), whose multipliers keep ||lambda_t|| <= g.
  /// Coulomb: g = friction * lambda_n (a fixed point over Tresca solves). Tresca: g =
  /// slip_bound, a force per row. Negative: not given; neither given: frictionless, no rows.
  /// A row whose coefficient or bound is 0 gets no friction row: it could carry no force,
  /// and mu = 0 is then exactly the frictionless problem (refusals of unrestrained bodies too).
  double friction = -1;
  double slip_bound = -1;
  /// Coulomb with a coefficient per contact row: per subdomain one value per dof (empty
  /// entries: `friction` there, which must be given), read at the slave node's component-0
  /// dof like gap_field.
  std::vector<std::vector<double>> friction_field;
  /// Tresca with a bound per contact row (a traction bound uniform on a graded mesh: the
  /// bound times each node's share of the contact surface): like friction_field, empty
  /// entries `slip_bound` there (fetiSetup sets 0 when only slipBoundField is given).
  std::vector<std::vector<double>> slip_bound_field;
  bool has_friction() const { return friction >= 0 || slip_bound >= 0; }
};

enum class FetiVariant {
  feti1,  ///< Dirichlet dofs eliminated inside K_s (the seed); touching subdomains are regular
  tfeti,  ///< Total FETI: Dirichlet conditions are rows of B_E; every subdomain floats
};

}  // namespace ffeti
