// One dual quadratic program as the qp/ solvers take it (docs/algorithms.md, "The dual
// problem"): minimize 1/2 x'Hx - b'x over the solver's variable x, with the bounds of the
// contact rows and, on the SMALBE path, an equality part C x = 0 given by the projector Q
// onto Im C'. Each formulation builds one (DualSystem::plain_qp, projected_qp, penalty_qp,
// free_rows_qp, beside the coarse space they use); the dispatcher (dual_solve.cpp) hands it
// to CG, MPRGP or SMALBE.
#pragma once

#include "qp/qp_types.h"

#include <functional>

namespace ffeti {

/// The solver path the constraints call for (ALGORITHMS.md section 6).
enum class DualPath {
  cholesky,      ///< no constraint rows: one subdomain solve each
  cg,            ///< equality rows only, nothing floats: CG on F
  projected_cg,  ///< equality rows only, something floats: CG on P F P
  mprgp,         ///< contact rows, nothing floats: MPRGP on F
  smalbe,        ///< contact rows, something floats: SMALBE-M (or MPRGP where no body floats as a whole)
};

/// The path's name in reports and statistics ("projected_cg").
const char* path_name(DualPath path);

struct DualQp {
  LinearOperator hessian;          ///< H, symmetric positive semidefinite
  Vec b;
  double hessian_norm = 0;         ///< upper estimate of ||H||_2 (0: not needed, CG)
  LinearOperator preconditioner;   ///< approximates H^+ (empty: none)
  LinearOperator range_projector;  ///< Q (empty: no equality part left to SMALBE)
  /// The shifted multipliers mu = lambda - lambda~ of a solver iterate x (empty: mu = x).
  std::function<void(const Vec& x, Vec& mu)> to_multipliers;
  /// ||G mu||, which the stopping test weighs (empty: the iterates meet G mu = 0 by
  /// construction, or nothing floats).
  std::function<double(const Vec& mu)> equality_norm;
  Vec start;                       ///< the solver's first iterate
};

}  // namespace ffeti
