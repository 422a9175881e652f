// The stopping test of the dual solves, stated in primal terms so that one tolerance means
// one thing on every scene.
#pragma once

#include "qp/qp_types.h"

#include <functional>

namespace ffeti {

enum class StoppingTest {
  /// ||gP||_inf <= tol ||u(lambda)||_inf. The dual gradient is minus the constraint violation
  /// B u - c of the primal field u(lambda) = K^+(f - B'lambda) + R alpha (gluing jumps,
  /// penetrations; on the SMALBE path alpha comes with the multiplier of G lambda = e), so
  /// the test bounds the relative KKT residuals fetiInfo reports (equality, inequality,
  /// complementarity) by about tol, in the units of u, whatever the number of rows.
  relative_kkt,
  /// The seed's: ||gP||_2 <= tol ||b||_2. Its meaning changes with the scene: ||b||_2 sums
  /// over all rows, so the same tol leaves larger violations per row where there are more.
  seed,
};

/// The relative_kkt test for one solve. ||u(lambda)||_inf costs a K^+ application, so it is
/// recomputed only at the first call, when the test holds with the last value known, and
/// when the violation has fallen a hundredfold since the last evaluation: a solve pays two
/// to five of them.
class RelativeKktStop {
 public:
  /// `displacement_scale(x)`: ||u||_inf of the primal field of the dual iterate x
  /// (collective; the test is called with the same x on every rank).
  RelativeKktStop(double tolerance, std::function<double(const Vec& x)> displacement_scale);

  /// True if ||projected_gradient||_inf <= tol ||u(x)||_inf.
  bool operator()(const Vec& x, const Vec& projected_gradient);

  int evaluations() const { return evaluations_; }
  /// ||gP||_inf / ||u||_inf at the last call (with the last ||u||_inf known).
  double measure() const { return measure_; }

 private:
  double tolerance_;
  std::function<double(const Vec&)> displacement_scale_;
  double scale_;
  double evaluated_violation_;  // the violation when scale_ was computed
  int evaluations_ = 0;
  double measure_ = 0;
};

}  // namespace ffeti
