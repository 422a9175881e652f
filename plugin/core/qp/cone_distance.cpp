#include "qp/cone_distance.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace ffeti::qp {
namespace {

/// At most this many steps: products with C and C', small beside a dual solve's work; a
/// distance still falling after them is left undecided rather than called positive.
constexpr int kMaxSteps = 20000;
/// The distance has settled when the last half of the steps lowered it by less than this
/// fraction: FISTA's distance falls like 1/k while a feasible set is being reached.
constexpr double kSettled = 1e-3;

}  // namespace

void project_onto_cone(double& n, double* t, int tangents, double mu) {
  double s = 0;
  for (int k = 0; k < tangents; ++k) s += t[k] * t[k];
  s = std::sqrt(s);
  if (s <= mu * n) return;
  if (mu * s <= -n) {
    n = 0;
    for (int k = 0; k < tangents; ++k) t[k] = 0;
    return;
  }
  const double along = (n + mu * s) / (1 + mu * mu);  // the ray's normal component
  for (int k = 0; k < tangents; ++k) t[k] *= mu * along / s;
  n = along;
}

ConeDistance cone_distance(const Eigen::MatrixXd& C, const Vec& target, const std::function<void(Vec&)>& project,
                           double scale, double enough) {
  // The step 1 / ||C||^2: C C' is small (C's rows are few).
  const double step = 1 / Eigen::MatrixXd(C * C.transpose()).eigenvalues().real().maxCoeff();
  Vec x = Vec::Zero(C.cols()), y = x, previous = x, residual = -target;
  ConeDistance best{residual.norm() / scale, x};
  double momentum = 1, last = best.distance, best_at_half = best.distance;
  for (int k = 1; best.distance > enough; ++k) {
    if (k > kMaxSteps) return {-1, Vec()};
    previous.swap(x);
    residual.noalias() = C * y - target;
    x = y;
    x.noalias() -= step * (C.transpose() * residual);
    project(x);
    residual.noalias() = C * x - target;
    const double distance = residual.norm() / scale;
    const double next = (1 + std::sqrt(1 + 4 * momentum * momentum)) / 2;
    if (distance > last) {  // restart: momentum that overshoots costs more than it gains
      y = x;
      momentum = 1;
    } else {
      y = x + ((momentum - 1) / next) * (x - previous);
      momentum = next;
    }
    last = distance;
    if (distance < best.distance) best = {distance, x};
    if ((k & (k - 1)) == 0) {  // at each power of two: did the last half of the steps settle it?
      if (k >= 256 && best.distance > (1 - kSettled) * best_at_half) break;
      best_at_half = best.distance;
    }
  }
  return best;
}

}  // namespace ffeti::qp
