#include "factor/dense_rate.h"

#include "base/stopwatch.h"
#include "parallel/process.h"

#include <Eigen/Core>

#include <algorithm>

namespace ffeti {
namespace {

double measure() {
  constexpr int n = 512;
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n), B = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd C(n, n);
  // The rate of one core: subdomains factorize one per thread. Through OpenMP's limit, which
  // Eigen follows, not Eigen::setNbThreads: setting Eigen's own count back to the value read
  // froze it there, so every later product ignored the ThreadLimit of the factorizations
  // (their rounding then depended on the thread count: cholmod_factor_test).
  const ThreadLimit one_thread(1);
  double best = 0;
  for (int run = 0; run < 3; ++run) {
    Stopwatch clock;
    C.noalias() = A * B;
    const double seconds = clock.seconds();
    if (seconds > 0) best = std::max(best, 2.0 * n * n * n / seconds / 1e9);
  }
  return best;
}

}  // namespace

double dense_gflops_one_thread() {
  static const double rate = measure();
  return rate;
}

}  // namespace ffeti
