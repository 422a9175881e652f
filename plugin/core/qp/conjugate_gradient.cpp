#include "qp/conjugate_gradient.h"

#include <cmath>
#include <stdexcept>

namespace ffeti {
namespace {
constexpr int kMaxResidualReplacements = 2;
}  // namespace

void CgSettings::validate() const {
  if (max_hessian < 1) throw std::invalid_argument("CG max_hessian must be >= 1");
}

CgResult conjugate_gradient(const LinearOperator& A, const Vec& b, Vec& x, Vec& g,
                            const CgSettings& settings, const StopTest& stop,
                            const Monitor& monitor) {
  settings.validate();
  CgResult result;
  if (x.size() != b.size()) throw std::invalid_argument("CG: x and b differ in size");
  IterationCounts& counts = result.counts;
  Vec Ap(b.size());
  A(x, Ap);
  ++counts.hessian;
  g = Ap - b;  // g = A x - b
  Vec p = g;
  double g_sq = g.squaredNorm();
  int replacements = 0;
  for (int iteration = 0;; ++iteration) {
    result.gradient_norm = std::sqrt(g_sq);
    if (monitor) monitor({"cg", iteration, result.gradient_norm, 0.0});
    if (stop(x, g, result.gradient_norm)) {
      if (counts.cg == 0) {  // g is the true gradient
        result.status = SolveStatus::converged;
        return result;
      }
      // The updated g drifts from A x - b by round-off; asked for more than the data's
      // accuracy allows, it keeps falling while x does not improve. Check the true one,
      // and restart from it (residual replacement) at most twice.
      A(x, Ap);
      ++counts.hessian;
      g = Ap - b;
      g_sq = g.squaredNorm();
      result.gradient_norm = std::sqrt(g_sq);
      if (stop(x, g, result.gradient_norm)) {
        result.status = SolveStatus::converged;
        return result;
      }
      if (++replacements > kMaxResidualReplacements) {
        result.status = SolveStatus::stagnated;
        return result;
      }
      p = g;
      continue;
    }
    if (counts.hessian >= settings.max_hessian) return result;
    A(p, Ap);
    ++counts.hessian;
    const double pAp = p.dot(Ap);
    if (!(pAp > 0)) {
      result.status = SolveStatus::not_positive_definite;
      return result;
    }
    const double a = g_sq / pAp;
    x -= a * p;   // x_{k+1} = x_k - a p
    g -= a * Ap;  // g = A x - b
    const double g_sq_next = g.squaredNorm();
    p = g + (g_sq_next / g_sq) * p;  // next A-conjugate direction
    g_sq = g_sq_next;
    ++counts.cg;
  }
}

}  // namespace ffeti
