// Aitken's delta-squared acceleration of the Coulomb fixed point g_{k+1} = G(g_k) on the
// bound vector (docs/algorithms.md, "Friction"; friction.cpp uses it): the next bound is
// g_k + omega_k r_k, r_k = G(g_k) - g_k, with Irons and Tuck's relaxation
// omega_k = -omega_{k-1} r_{k-1}.(r_k - r_{k-1}) / ||r_k - r_{k-1}||^2, the vector form of
// Aitken's delta squared: exact in one step for a linear map with one contracting mode.
#pragma once

#include "base/linear_algebra.h"

namespace ffeti {

class BoundAcceleration {
 public:
  /// The bound to solve with next, given the bound `bound` solved with last and its image
  /// G(bound). Safeguards: the plain step G(bound) while there is no finite last residual,
  /// whenever the residual did not decrease (then the history restarts from this residual),
  /// and omega clipped to [kMinRelaxation, kMaxRelaxation]; the result projected on g >= 0.
  Vec next(const Vec& bound, const Vec& image);
  /// Forgets the history: the next call takes the plain step.
  void reset();
  /// Whether the last next() returned an extrapolated bound (not the plain G(bound)).
  bool accelerated() const { return accelerated_; }
  double relaxation() const { return relaxation_; }

  static constexpr double kMinRelaxation = 1.0;
  static constexpr double kMaxRelaxation = 10.0;

 private:
  Vec last_residual_;  ///< r_{k-1}; empty: no history
  double relaxation_ = 1.0;
  bool accelerated_ = false;
};

}  // namespace ffeti
