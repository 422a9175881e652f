// The right-hand side of one dual problem and what a solve of a sequence carries over.
#pragma once

#include "qp/qp_types.h"

#include <vector>

namespace ffeti {

/// The right-hand side of one dual problem, for loads f (as the operators see them) and
/// constraint right-hand side c: d = B K^+ f - c, e = R'f, lambda~ = G'(GG')^{-1} e and
/// b = P(d - F lambda~).
struct DualData {
  std::vector<Vec> loads;
  Vec c, e, lambda_tilde, b;
  double data_norm = 0;  ///< max(||B K^+ f||, ||c||): the size of what b was computed from
  Vec slip_bound;        ///< per friction row: g >= 0 of |lambda_t| <= g (empty without friction)
};

/// What a solve of a sequence (friction's fixed point: one system, other bounds) carries
/// over from the last, besides its multipliers (DualSolveSettings::start).
struct DualWarmStart {
  Vec equality_multiplier;  ///< DualSolution::equality_multiplier of the last solve (empty: 0)
};

}  // namespace ffeti
