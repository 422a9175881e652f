#include "feti/stopping_test.h"

#include <limits>
#include <utility>

namespace ffeti {

RelativeKktStop::RelativeKktStop(double tolerance, std::function<double(const Vec& x)> displacement_scale)
    : tolerance_(tolerance), displacement_scale_(std::move(displacement_scale)),
      scale_(std::numeric_limits<double>::infinity()) {}

bool RelativeKktStop::operator()(const Vec& x, const Vec& projected_gradient) {
  const double violation = projected_gradient.size() ? projected_gradient.lpNorm<Eigen::Infinity>() : 0.0;
  if (violation > tolerance_ * scale_) {
    measure_ = violation / scale_;
    return false;
  }
  scale_ = displacement_scale_(x);
  ++evaluations_;
  measure_ = scale_ > 0 ? violation / scale_ : (violation > 0 ? std::numeric_limits<double>::infinity() : 0.0);
  return violation <= tolerance_ * scale_;
}

}  // namespace ffeti
