#include "feti/stopping_test.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace ffeti {

RelativeKktStop::RelativeKktStop(double tolerance, std::function<PrimalCheck(const Vec& mu)> check)
    : tolerance_(tolerance), check_(std::move(check)), target_(tolerance), equality_target_(tolerance),
      scale_(std::numeric_limits<double>::infinity()),
      checked_gradient_(std::numeric_limits<double>::infinity()) {}

bool RelativeKktStop::operator()(const Vec& x, const Multipliers& mu, double gradient, double equality) {
  if (passed_.size() == x.size() && passed_ == x) return true;
  const bool predicted_done = gradient <= target_ * scale_ && equality <= equality_target_ &&
                              (!last_check_failed_ || gradient <= 0.5 * checked_gradient_);
  if (!predicted_done && gradient > 0.01 * checked_gradient_) return false;
  const PrimalCheck check = check_(mu());
  ++evaluations_;
  scale_ = check.displacement;
  checked_gradient_ = gradient;
  measure_ = std::max(check.violation, check.equilibrium);
  last_check_failed_ = measure_ > tolerance_;
  if (!last_check_failed_) {
    passed_ = x;
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
