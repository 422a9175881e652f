#include "qp/norm_estimate.h"

#include <Eigen/Eigenvalues>

#include <random>
#include <vector>

namespace ffeti {

NormEstimate estimate_norm(const LinearOperator& A, Eigen::Index size, const NormEstimateSettings& settings,
                           const std::function<void(Vec&)>& start_filter) {
  NormEstimate result;
  if (size == 0 || settings.iterations < 1) return result;
  std::mt19937 generator(settings.seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vec v(size), w(size);
  for (Eigen::Index i = 0; i < size; ++i) v[i] = uniform(generator);
  if (start_filter) start_filter(v);
  std::vector<Vec> basis;
  Eigen::VectorXd alpha(settings.iterations), beta(settings.iterations);  // the tridiagonal matrix
  double ritz = 0, norm = v.norm();
  for (int k = 0; k < settings.iterations && norm > 0; ++k) {
    v /= norm;
    basis.push_back(v);
    A(v, w);
    ++result.multiplications;
    alpha[k] = v.dot(w);
    // Against every kept vector, twice: in floating point the three-term recurrence loses
    // orthogonality exactly as the largest Ritz value converges.
    for (int pass = 0; pass < 2; ++pass)
      for (const Vec& q : basis) w -= q.dot(w) * q;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> tridiagonal;
    tridiagonal.computeFromTridiagonal(alpha.head(k + 1), beta.head(k), Eigen::EigenvaluesOnly);
    const double previous = ritz;
    ritz = tridiagonal.eigenvalues()[k];  // ascending: the largest
    if (k > 0 && ritz - previous <= settings.tolerance * ritz) break;
    norm = beta[k] = w.norm();
    if (!(norm > 1e-14 * ritz)) break;  // an invariant subspace: the Ritz values are exact
    v.swap(w);
  }
  result.norm = settings.safety_factor * ritz;
  return result;
}

}  // namespace ffeti
