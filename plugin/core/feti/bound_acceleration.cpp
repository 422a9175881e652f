#include "feti/bound_acceleration.h"

#include <algorithm>

namespace ffeti {

Vec BoundAcceleration::next(const Vec& bound, const Vec& image) {
  accelerated_ = false;
  // g = infinity (the first solve of a step without multipliers) has no residual to learn from.
  if (!bound.allFinite() || !image.allFinite()) {
    reset();
    return image;
  }
  const Vec residual = image - bound;
  const bool history = last_residual_.size() == residual.size();
  if (!history || residual.norm() >= last_residual_.norm()) {
    // No history, or the fixed point did not get closer (an extrapolation that overshot, or
    // solves' noise): the plain step, and the history restarts here.
    relaxation_ = 1.0;
    last_residual_ = residual;
    return image;
  }
  const Vec difference = residual - last_residual_;
  const double squared = difference.squaredNorm();
  if (squared > 0) {
    const double omega = -relaxation_ * last_residual_.dot(difference) / squared;
    relaxation_ = std::clamp(omega, kMinRelaxation, kMaxRelaxation);
  }
  last_residual_ = residual;
  accelerated_ = relaxation_ != 1.0;
  return (bound + relaxation_ * residual).cwiseMax(0.0);
}

void BoundAcceleration::reset() {
  last_residual_.resize(0);
  relaxation_ = 1.0;
  accelerated_ = false;
}

}  // namespace ffeti
