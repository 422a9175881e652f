// One quadratic program as every solver of qp/ reads it (CONVENTIONS.md 13, PermonQP's QP
// object): minimize 1/2 x'Hx - b'x subject to a convex constraint set per block of
// components and, optionally, C x = 0 given by Q, the orthogonal projector onto Im C'.
// CG, MPRGP and SMALBE take it under one signature:
//   Result solver(const qp::Problem&, const Settings&, Vec& x /* start in, iterate out */,
//                 qp::Budget& /* charged with its multiplications */, const StopTest&,
//                 const Monitor& = {})
// A formulation (feti/dual_formulations.cpp) builds one; the solver that fits is chosen
// by the caller's path, not by which members are set.
#pragma once

#include "qp/budget.h"
#include "qp/constraint_set.h"
#include "qp/qp_types.h"

#include <Eigen/Dense>

namespace ffeti::qp {

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
  /// C itself (k x n, full row rank) where the formulation holds it, optional: SMALBE then
  /// balances the modes that only bounded blocks hold by their rigid-plastic model
  /// (qp/held_modes.h). Not owned: it must outlive the Problem.
  const Eigen::MatrixXd* equality_rows = nullptr;
  ConstraintSet constraints;       ///< one block per group of components (qp/constraint_set.h)

  Eigen::Index size() const { return b.size(); }
};

}  // namespace ffeti::qp
