#include "qp/stopping_test.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace ffeti {

RelativeKktStop::RelativeKktStop(double tolerance, std::function<PrimalCheck(const Vec& mu)> check)
    : tolerance_(tolerance), check_(std::move(check)), target_(tolerance), equality_target_(tolerance),
      scale_(std::numeric_limits<double>::infinity()),
      checked_gradient_(std::numeric_limits<double>::infinity()) {}

namespace {

/// Checks in a row that failed and did not halve the best residual so far: with the gradient
/// halved before each, the dual iterate improved at least 8-fold while its primal field did
/// not: the field's accuracy is set by round-off in its recovery, not by the iterate. A check
/// after which neither the gradient nor the residual halved counts for all of them: the
/// iterate itself stands still (node to face at tol 1e-12: ||gP|| 1.56e-14 and the residual
/// 1.29e-12 for 3,000 multiplications).
constexpr int kChecksWithoutProgress = 3;
/// A failed check is repeated, whatever the gradient, once the solver has been called this
/// many times since (and half as many times as before it): a gradient that stalls at
/// round-off halves no more, and would run to maxit without another check.
constexpr long kOverdueCalls = 50;

}  // namespace

bool RelativeKktStop::operator()(const Vec& x, const Multipliers& mu, double gradient, double equality) {
  if (passed_.size() == x.size() && passed_ == x) return true;
  ++calls_;
  const bool predicted_done = gradient <= target_ * scale_ && equality <= equality_target_ &&
                              (!last_check_failed_ || gradient <= 0.5 * checked_gradient_);
  const bool overdue = last_check_failed_ && calls_ - checked_call_ >= std::max(kOverdueCalls, checked_call_ / 2);
  if (!predicted_done && !overdue && gradient > 0.01 * checked_gradient_) return false;
  const PrimalCheck check = check_(mu());
  ++evaluations_;
  const bool gradient_stalled = evaluations_ > 1 && gradient > 0.5 * checked_gradient_;
  checked_call_ = calls_;
  scale_ = check.displacement;
  checked_gradient_ = gradient;
  measure_ = std::max(check.violation, check.equilibrium);
  last_check_failed_ = measure_ > tolerance_;
  if (!last_check_failed_) {
    passed_ = x;
    return true;
  }
  if (measure_ <= 0.5 * best_measure_) {
    best_measure_ = measure_;
    checks_without_progress_ = 0;
  } else if ((checks_without_progress_ += gradient_stalled ? kChecksWithoutProgress : 1) >= kChecksWithoutProgress &&
             best_measure_ <= kRoundOffCeiling) {
    stagnated_ = true;  // the best accuracy the data allow: stop, and say so (DualSystem::solve)
    return true;
  }
  // A prediction that said done while the recovered field disagrees aims lower by the
  // ratio between them.
  const auto lower = [&](double& target, double predicted, double actual) {
    if (actual > tolerance_ && predicted <= target)
      target = std::max(std::min(target, tolerance_ * predicted / actual), 1e-6 * tolerance_);
  };
  lower(target_, scale_ > 0 ? gradient / scale_ : std::numeric_limits<double>::infinity(), check.violation);
  lower(equality_target_, equality, check.equilibrium);
  return false;
}

}  // namespace ffeti
