// The solver path of a dual problem, chosen once from its constraints.
#pragma once

namespace ffeti {

/// The solver path the constraints call for (ALGORITHMS.md section 6).
enum class DualPath {
  cholesky,      ///< no constraint rows: one subdomain solve each
  cg,            ///< equality rows only, nothing floats: CG on F
  projected_cg,  ///< equality rows only, something floats: CG on P F P
  mprgp,         ///< contact rows, nothing floats: MPRGP on F
  smalbe,        ///< contact rows, something floats: SMALBE-M (MPRGP where the free-rows form leaves no equality part)
};

/// The path's name in reports and statistics ("projected_cg"); paths are compared as enums.
const char* path_name(DualPath path);

}  // namespace ffeti
