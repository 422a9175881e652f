// The stopping test of the dual solves, stated in primal terms so that one tolerance means
// one thing on every scene.
#pragma once

#include "qp/qp_types.h"

#include <functional>

namespace ffeti {

enum class StoppingTest {
  /// The largest constraint violation of the primal solution u(lambda) (gluing jump,
  /// Dirichlet misfit, penetration) at most tol ||u||_inf: the relative KKT residuals
  /// fetiInfo reports (equality, inequality) are then at most tol, whatever the number of
  /// rows, the units and the load scale.
  relative_kkt,
  /// The seed's: ||gP||_2 <= tol ||b||_2. Its meaning changes with the scene: ||b||_2 sums
  /// over all rows, so the same tol leaves larger violations per row where there are more.
  seed,
};

/// The primal field of a dual iterate, as the stopping test sees it: ||u||_inf and the
/// largest constraint violation of u relative to it.
struct PrimalCheck {
  double displacement = 0;  ///< ||u||_inf
  double violation = 0;     ///< max(|B_E u - c_E|, (B_I u - c_I)_+) / ||u||_inf
};

/// The relative_kkt test for one solve. The dual gradient is minus the constraint violation
/// of a primal field (g = F lambda - d = c - B u for u = K^+(f - B'lambda) + R alpha, alpha
/// the kernel part the dual iterate implies), so ||gP||_inf / ||u||_inf predicts the
/// violation. The recovered u (alpha fitted on the rows that hold with equality) can differ,
/// so the prediction only decides when to check: the check recovers u (one K^+ application)
/// and the test holds when its true violation is at most tol. A check that fails lowers the
/// prediction's target by the ratio it was off. Checks happen at the first call, when the
/// prediction meets its target, and when ||gP||_inf has fallen a hundredfold since the last
/// check (||u|| of a distant iterate can be far off: zero at the start of an unloaded scene):
/// two to five per solve.
class RelativeKktStop {
 public:
  /// `check(x)`: the primal check of the dual iterate x (collective; the test is called
  /// with the same x on every rank).
  RelativeKktStop(double tolerance, std::function<PrimalCheck(const Vec& x)> check);

  /// True if the primal field of x violates no constraint by more than tol ||u||_inf.
  bool operator()(const Vec& x, const Vec& projected_gradient);

  int evaluations() const { return evaluations_; }
  /// The violation of the last check (relative to ||u||_inf).
  double measure() const { return measure_; }

 private:
  double tolerance_;
  std::function<PrimalCheck(const Vec&)> check_;
  double target_;               // of the prediction ||gP||_inf / ||u||_inf
  double scale_;                // ||u||_inf at the last check
  double checked_gradient_;     // ||gP||_inf at the last check
  int evaluations_ = 0;
  double measure_ = 0;
};

}  // namespace ffeti
