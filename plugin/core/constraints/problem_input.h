// What a front end (the FreeFEM binding, a test) hands to the core for one problem.
#pragma once

#include "base/linear_algebra.h"
#include "constraints/capabilities.h"

#include <any>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <typeindex>
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
  /// Stiffness, symmetric, full (not half) storage: the input checks walk whole columns.
  /// FetiProblem keeps only its lower triangle once they are done.
  SharedMatrix K;
  Vec f;                          ///< load
  std::vector<double> x, y;       ///< coordinates of each dof's node
  std::vector<double> z;          ///< third coordinate (empty: a plane problem; every subdomain alike)
  std::vector<int> component;     ///< field component of each dof (empty: scalar field; 0..2 in 3D)
  int body = 0;                   ///< body the subdomain belongs to
  std::vector<int> dirichlet_dofs;      ///< local dofs with a prescribed value
  std::vector<double> dirichlet_values; ///< their values (empty: all zero)
};

/// Contact conditions, linearized for small displacements; one row per physical slave node
/// (its copies in other subdomains are glued to it). Each contact kind is a unit of
/// constraints/contact/ that reads, checks and uses its own input: the fields below are
/// grouped by the kind that owns them (docs/architecture.md, "A contact kind").
struct ContactInput {
  /// Shared: the slave dofs of every kind but mortar, per subdomain (may be empty).
  std::vector<std::vector<int>> slave_dofs;

  // ---- each list kind's own input, and the plane's: its unit's struct (NodeToNodeInput,
  // NodeToSegmentInput, NodeToFaceInput, MortarInput, ObstacleInput, ...: its per-subdomain
  // list, e.g. node to face's master triangles, and its scalar arguments), stored by its
  // read_list, read_option or read_input, checked by its check_against; a new kind declares
  // its own and adds nothing here ----
  /// `Input` to fill in: made at first use with its unit's defaults.
  template <class Input>
  Input& input_of() {
    std::any& held = list_inputs[std::type_index(typeid(Input))];
    if (!held.has_value()) held = Input{};
    return std::any_cast<Input&>(held);
  }
  /// `Input` as given: its unit's defaults where it was not.
  template <class Input>
  const Input& input_of() const {
    static const Input defaults{};
    const auto held = list_inputs.find(std::type_index(typeid(Input)));
    return held == list_inputs.end() ? defaults : std::any_cast<const Input&>(held->second);
  }
  std::map<std::type_index, std::any> list_inputs;  ///< by the input's type (read through input_of)

  /// The kinds that search masters (node to segment, node to face, mortar): farther slaves get no row.
  double search_distance = 1e300;

  // ---- the kinds that own an array of parameters (KindInput) ----
  /// The kinds that own their input (the ball, the cylinder, ...; the plane keeps its own
  /// ObstacleInput in list_inputs): per kind the entries
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
