#include "feti/stopping_test.h"

#include <algorithm>
#include <limits>
#include <utility>

namespace ffeti {

RelativeKktStop::RelativeKktStop(double tolerance, std::function<PrimalCheck(const Vec& x)> check)
    : tolerance_(tolerance), check_(std::move(check)), target_(tolerance),
      scale_(std::numeric_limits<double>::infinity()),
      checked_gradient_(std::numeric_limits<double>::infinity()) {}

bool RelativeKktStop::operator()(const Vec& x, const Vec& projected_gradient) {
  const double gradient = projected_gradient.size() ? projected_gradient.lpNorm<Eigen::Infinity>() : 0.0;
  if (gradient > target_ * scale_ && gradient > 0.01 * checked_gradient_) return false;
  const PrimalCheck check = check_(x);
  ++evaluations_;
  scale_ = check.displacement;
  checked_gradient_ = gradient;
  measure_ = check.violation;
  if (measure_ <= tolerance_) return true;
  // The prediction said done (or was not yet known) and the recovered field disagrees:
  // aim lower by the ratio between them.
  const double predicted = scale_ > 0 ? gradient / scale_ : std::numeric_limits<double>::infinity();
  if (predicted <= target_) target_ = std::max(std::min(target_, tolerance_ * predicted / measure_), 1e-6 * tolerance_);
  return false;
}

}  // namespace ffeti
