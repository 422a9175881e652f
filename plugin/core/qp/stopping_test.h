// The stopping test of the dual solves, stated in primal terms so that one tolerance means
// one thing on every scene.
#pragma once

#include "qp/qp_types.h"

#include <functional>
#include <limits>

namespace ffeti {

enum class StoppingTest {
  /// The primal solution u(lambda) violates no constraint (gluing jump, Dirichlet misfit,
  /// penetration) by more than tol ||u||_inf, and its equilibrium residual is at most tol
  /// max(||f||, ||B'lambda||): the relative KKT residuals fetiInfo reports are then at most
  /// tol, whatever the number of rows, the units and the load scale.
  relative_kkt,
  /// The seed's: ||gP||_2 <= tol ||b||_2. Its meaning changes with the scene: ||b||_2 sums
  /// over all rows, so the same tol leaves larger violations per row where there are more.
  seed,
};

/// The primal field of a dual iterate, as the stopping test sees it.
struct PrimalCheck {
  double displacement = 0;  ///< ||u||_inf
  double violation = 0;     ///< max(|B_E u - c_E|, (B_I u - c_I)_+, |lambda_i (B_I u - c_I)_i| / ||lambda||_inf) / ||u||_inf
  double equilibrium = 0;   ///< ||K u - f + B'lambda|| / max(||f||, ||B'lambda||)
};

/// The relative_kkt test for one solve. Checking it recovers u (one K^+ application), so
/// two predictions decide when to check. The dual gradient is minus the constraint
/// violation of a primal field (g = F lambda - d = c - B u for u = K^+(f - B'lambda) +
/// R alpha, alpha the kernel part the dual iterate implies), so ||gP||_inf / ||u||_inf
/// predicts the violation; the recovered u fits alpha on the rows that hold with equality
/// and can differ. ||G lambda - e|| relative to its reference predicts the equilibrium
/// residual. A check happens at the first call, when both predictions meet their targets,
/// and when ||gP||_inf has fallen a hundredfold since the last check (||u|| of a distant
/// iterate can be far off: zero at the start of an unloaded scene); a check that fails
/// lowers the target of each prediction that was off by the ratio it was off, and the next
/// check then waits for the gradient to halve (a tolerance below round-off costs a check per
/// halving, not one per iteration). A call with the iterate that last passed passes again
/// without a check (CG confirms its stop with the true gradient). One to five checks per
/// solve on the scenes of the repository.
/// Stagnation at round-off is a verdict kept for residuals this small (relative KKT): above,
/// a residual that stands still is a solve that has not found its active set yet (or a
/// recovery that misreads it), which more iterations may mend, and maxit ends it.
constexpr double kRoundOffCeiling = 1e-6;

class RelativeKktStop {
 public:
  /// The shifted multipliers mu of the solver's iterate, formed only for a check (the free
  /// rows' mu = T x costs a solve with the coarse problem's Gram matrix).
  using Multipliers = std::function<const Vec&()>;

  /// `check(mu)`: the primal check of the shifted multipliers mu (collective; the test is
  /// called with the same iterate on every rank).
  RelativeKktStop(double tolerance, std::function<PrimalCheck(const Vec& mu)> check);

  /// True if the primal field of the solver's iterate x (its multipliers `mu()`) meets the
  /// test. `gradient` is ||gP(x)||_inf, `equality` ||G lambda - e|| relative to its
  /// reference (0 without a coarse space).
  bool operator()(const Vec& x, const Multipliers& mu, double gradient, double equality = 0);

  /// The equality prediction's target: check when ||G lambda - e|| / reference is below it.
  double equality_target() const { return equality_target_; }

  int evaluations() const { return evaluations_; }
  /// True if the test stopped a solve at round-off: three checks in a row, each after the
  /// dual gradient had halved (or after a long wait), failed without halving the best primal
  /// residual, itself at most 1e-6. `measure()` is then the residual reached, above tol.
  bool stagnated() const { return stagnated_; }
  /// The larger of the last check's violation and equilibrium residual (both relative); -1
  /// before any check.
  double measure() const { return measure_; }

 private:
  double tolerance_;
  std::function<PrimalCheck(const Vec&)> check_;
  double target_;               // of the prediction ||gP||_inf / ||u||_inf
  double equality_target_;      // of the prediction ||G lambda - e|| / reference
  double scale_;                // ||u||_inf at the last check
  double checked_gradient_;     // ||gP||_inf at the last check
  bool last_check_failed_ = false;
  Vec passed_;                  // the solver's iterate that passed
  int evaluations_ = 0;
  double measure_ = -1;
  long calls_ = 0;              // of the test, by the solver
  long checked_call_ = 0;       // the call of the last check
  double best_measure_ = std::numeric_limits<double>::infinity();
  int checks_without_progress_ = 0;
  bool stagnated_ = false;
};

/// The stopping test of one dual solve at a solver iterate x and its shifted multipliers mu, given its
/// projected gradient gP (inf- and 2-norm) and, where the formulation leaves the balance of
/// floating bodies to the solver, ||G mu|| and its reference: relative_kkt asks `kkt`,
/// the seed's test compares ||gP||_2 with tol ||b||_2 (and ||G mu|| with tol times its
/// reference). One object for every path, so each path stops by the same rule.
class DualStop {
 public:
  DualStop(StoppingTest kind, double tolerance, double gradient_reference, RelativeKktStop& kkt)
      : kind_(kind), tolerance_(tolerance), gradient_tolerance_(tolerance * gradient_reference), kkt_(kkt) {}

  /// At the solver's iterate x, its multipliers mu() formed only if a primal check needs them.
  bool operator()(const Vec& x, const RelativeKktStop::Multipliers& mu, double gradient_inf,
                  double gradient_norm) const {
    return kind_ == StoppingTest::seed ? gradient_norm <= gradient_tolerance_ : kkt_(x, mu, gradient_inf);
  }
  bool operator()(const Vec& x, const RelativeKktStop::Multipliers& mu, double gradient_inf, double gradient_norm,
                  double equality_norm, double equality_reference) const {
    if (kind_ == StoppingTest::relative_kkt) return kkt_(x, mu, gradient_inf, equality_norm / equality_reference);
    return equality_norm <= tolerance_ * equality_reference && gradient_norm <= gradient_tolerance_;
  }

 private:
  StoppingTest kind_;
  double tolerance_, gradient_tolerance_;
  RelativeKktStop& kkt_;
};

}  // namespace ffeti
