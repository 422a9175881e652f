#include "qp/gmres.h"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace ffeti::qp {

GmresResult gmres(const LinearOperator& A, const Vec& b, Vec& x, double tol, int max_applications, int restart) {
  GmresResult result;
  const double b_norm = b.norm();
  if (x.size() != b.size()) x = Vec::Zero(b.size());
  if (b_norm == 0) {
    x.setZero();
    result.converged = true;
    return result;
  }
  Vec w(b.size());
  bool zero_start = x.isZero(0.0);  // r = b: no application
  while (result.applications < max_applications) {
    Vec r = b;
    if (!zero_start) {
      A(x, w);
      ++result.applications;
      r -= w;
    }
    zero_start = false;
    const double beta = r.norm();
    result.relative_residual = beta / b_norm;
    if (result.relative_residual <= tol) break;
    const int m = std::min(restart, max_applications - result.applications);
    if (m <= 0) break;
    std::vector<Vec> V;  // the Krylov basis of this cycle
    V.reserve(static_cast<size_t>(m) + 1);
    V.push_back(r / beta);
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m + 1, m);
    Vec cs = Vec::Zero(m), sn = Vec::Zero(m), s = Vec::Zero(m + 1);
    s[0] = beta;
    int k = 0;
    while (k < m) {
      A(V[static_cast<size_t>(k)], w);
      ++result.applications;
      for (int i = 0; i <= k; ++i) {
        H(i, k) = w.dot(V[static_cast<size_t>(i)]);
        w -= H(i, k) * V[static_cast<size_t>(i)];
      }
      const double next_norm = w.norm();
      H(k + 1, k) = next_norm;
      for (int i = 0; i < k; ++i) {  // the earlier rotations on the new column
        const double t = cs[i] * H(i, k) + sn[i] * H(i + 1, k);
        H(i + 1, k) = -sn[i] * H(i, k) + cs[i] * H(i + 1, k);
        H(i, k) = t;
      }
      const double d = std::hypot(H(k, k), H(k + 1, k));
      cs[k] = d > 0 ? H(k, k) / d : 1.0;
      sn[k] = d > 0 ? H(k + 1, k) / d : 0.0;
      H(k, k) = d;
      H(k + 1, k) = 0;
      s[k + 1] = -sn[k] * s[k];
      s[k] *= cs[k];
      ++k;
      result.relative_residual = std::abs(s[k]) / b_norm;
      if (result.relative_residual <= tol || !(next_norm > 0) || !(d > 0)) break;  // met, or the space exhausted
      V.push_back(w / next_norm);
    }
    // x += V_k y, H_k y = s_k (upper triangular).
    const Vec y = H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(s.head(k));
    for (int i = 0; i < k; ++i) x += y[i] * V[static_cast<size_t>(i)];
    if (result.relative_residual <= tol) break;  // by the least-squares residual: the caller applies A to x anyway
  }
  result.converged = result.relative_residual <= tol;
  return result;
}

}  // namespace ffeti::qp
