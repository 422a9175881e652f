#include "feti/stopping_test.h"

#include <limits>
#include <utility>

namespace ffeti {

RelativeKktStop::RelativeKktStop(double tolerance, std::function<double(const Vec& x)> displacement_scale)
    : tolerance_(tolerance), displacement_scale_(std::move(displacement_scale)),
      scale_(std::numeric_limits<double>::infinity()),
      evaluated_violation_(std::numeric_limits<double>::infinity()) {}

bool RelativeKktStop::operator()(const Vec& x, const Vec& projected_gradient) {
  const double violation = projected_gradient.size() ? projected_gradient.lpNorm<Eigen::Infinity>() : 0.0;
  // ||u|| known from a distant iterate can be far off (zero at the start of an unloaded
  // scene with a prescribed gap): it is also recomputed each time the violation has fallen
  // a hundredfold since the last evaluation.
  if (violation > tolerance_ * scale_ && violation > 0.01 * evaluated_violation_) {
    measure_ = violation / scale_;
    return false;
  }
  scale_ = displacement_scale_(x);
  evaluated_violation_ = violation;
  ++evaluations_;
  measure_ = scale_ > 0 ? violation / scale_ : (violation > 0 ? std::numeric_limits<double>::infinity() : 0.0);
  return violation <= tolerance_ * scale_;
}

}  // namespace ffeti
