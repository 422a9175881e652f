#include "qp/norm_estimate.h"

#include <random>

namespace ffeti {

NormEstimate estimate_norm(const LinearOperator& A, Eigen::Index size,
                           const NormEstimateSettings& settings,
                           const std::function<void(Vec&)>& start_filter) {
  NormEstimate result;
  if (size == 0) return result;
  std::mt19937 generator(settings.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vec x(size), y(size);
  for (Eigen::Index i = 0; i < size; ++i) x[i] = uniform(generator);
  if (start_filter) start_filter(x);
  double rayleigh = 0;
  for (int k = 0; k < settings.iterations; ++k) {
    const double x_norm = x.norm();
    if (x_norm == 0) break;
    x /= x_norm;
    A(x, y);
    ++result.multiplications;
    rayleigh = x.dot(y);  // x'Ax with ||x|| = 1
    x.swap(y);
  }
  result.norm = settings.safety_factor * rayleigh;
  return result;
}

}  // namespace ffeti
