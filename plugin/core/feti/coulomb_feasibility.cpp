#include "feti/coulomb_feasibility.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ffeti {
namespace {

/// At most this many steps: G and G' products only, small beside one solve's work; a
/// distance still falling after them is left undecided rather than called infeasible.
constexpr int kMaxSteps = 20000;
/// The distance has settled when the last half of the steps lowered it by less than this
/// fraction: FISTA's distance falls like 1/k while a feasible set is being reached.
constexpr double kSettled = 1e-3;

/// Euclidean projection of (n, t) onto {||t|| <= mu n}: the cone of half-angle atan(mu)
/// about the normal; its polar {mu ||t|| <= -n} goes to 0, the rest to the nearest ray.
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

/// lambda onto the cones: contact rows without friction lambda_n >= 0, friction pairs
/// (rows of one contact row) with their normal, equality rows free.
void project(const Constraints& c, Vec& lambda) {
  std::vector<char> paired(static_cast<size_t>(c.rows()), 0);
  for (int t = 0; t < c.friction_rows; t += c.tangent_directions) {
    const int normal = c.normal_row[static_cast<size_t>(t)];
    paired[static_cast<size_t>(normal)] = 1;
    project_onto_cone(lambda[normal], &lambda[c.first_friction_row() + t], c.tangent_directions,
                      c.friction_coefficient[static_cast<size_t>(t)]);
  }
  for (int i = c.equality_rows; i < c.first_friction_row(); ++i)
    if (!paired[static_cast<size_t>(i)]) lambda[i] = std::max(lambda[i], 0.0);
}

}  // namespace

CoulombFeasibility coulomb_feasibility(const CoarseSpace& coarse, const Constraints& c, const Vec& e,
                                       const std::vector<int>& bodies, double enough) {
  CoulombFeasibility result;
  const double e_norm = e.norm();
  if (coarse.empty() || !(e_norm > 0)) return result;
  const auto& G = coarse.G();
  // The step 1 / ||G G'||, from a few power iterations on G G' (r x r, r the rigid modes).
  Vec v = Vec::Ones(G.rows()), w;
  double norm = 0;
  for (int k = 0; k < 30; ++k) {
    w = G * (G.transpose() * v).eval();
    norm = w.norm() / v.norm();
    v = w / w.norm();
  }
  const double step = 1 / (1.1 * norm);  // 10 % above the estimate, which approaches from below
  Vec x = coarse.least_norm_solution(e);
  project(c, x);
  Vec y = x, previous = x;
  double momentum = 1, best = (G * x - e).norm() / e_norm, best_at_half = best;
  for (int k = 1; k <= kMaxSteps && best > enough; ++k) {
    const Vec residual = G * y - e;
    previous = x;
    x = y - step * (G.transpose() * residual);
    project(c, x);
    const double distance = (G * x - e).norm() / e_norm;
    const double next = (1 + std::sqrt(1 + 4 * momentum * momentum)) / 2;
    if (distance > best) {  // restart: momentum that overshoots costs more than it gains
      y = x;
      momentum = 1;
    } else {
      y = x + ((momentum - 1) / next) * (x - previous);
      momentum = next;
    }
    best = std::min(best, distance);
    if ((k & (k - 1)) == 0) {  // at each power of two: the last half of the steps settled it?
      if (k >= 256 && best > (1 - kSettled) * best_at_half) break;
      best_at_half = best;
    }
    if (k == kMaxSteps) return {-1, -1};
  }
  result.distance = best;
  if (best <= enough) return result;
  // The body that would slide: the largest share of the residual over its rigid modes.
  const Vec residual = G * x - e;
  std::map<int, double> share;
  for (Eigen::Index r = 0; r < residual.size(); ++r)
    share[bodies[static_cast<size_t>(coarse.row_owner()[static_cast<size_t>(r)].first)]] += residual[r] * residual[r];
  result.body = std::max_element(share.begin(), share.end(), [](const auto& a, const auto& b) {
                  return a.second < b.second;
                })->first;
  return result;
}

}  // namespace ffeti
