#include "feti/coulomb_feasibility.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <Eigen/Eigenvalues>

namespace ffeti {
namespace {

/// At most this many steps: products with C (k x m) and C', small beside one solve's work;
/// a distance still falling after them is left undecided rather than called infeasible.
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

CoulombFeasibility coulomb_feasibility(const CoarseSpace& coarse, const FreeRowProjector& free_rows,
                                       const Constraints& c, const Vec& e, const std::vector<int>& bodies,
                                       double enough) {
  CoulombFeasibility result;
  const double e_norm = e.norm();
  if (free_rows.remaining() == 0 || !(e_norm > 0)) return result;  // no body floats as a whole
  const Eigen::MatrixXd& C = free_rows.remaining_rows();
  const Vec target = free_rows.remaining_basis().transpose() * e;
  const double step = 1 / Eigen::MatrixXd(C * C.transpose()).eigenvalues().real().maxCoeff();  // 1 / ||C||^2
  Vec x = Vec::Zero(C.cols()), y = x, previous = x;
  const auto distance_of = [&](const Vec& v) { return (C * v - target).norm() / e_norm; };
  double momentum = 1, last = distance_of(x), best = last, best_at_half = best;
  Vec best_x = x;
  for (int k = 1; best > enough; ++k) {
    if (k > kMaxSteps) return {-1, -1};
    previous = x;
    x = y - step * (C.transpose() * (C * y - target));
    project(c, x);
    const double distance = distance_of(x);
    const double next = (1 + std::sqrt(1 + 4 * momentum * momentum)) / 2;
    if (distance > last) {  // restart: momentum that overshoots costs more than it gains
      y = x;
      momentum = 1;
    } else {
      y = x + ((momentum - 1) / next) * (x - previous);
      momentum = next;
    }
    last = distance;
    if (distance < best) best = distance, best_x = x;
    if ((k & (k - 1)) == 0) {  // at each power of two: did the last half of the steps settle it?
      if (k >= 256 && best > (1 - kSettled) * best_at_half) break;
      best_at_half = best;
    }
  }
  result.distance = best;
  if (best <= enough) return result;
  // The body that would slide: the largest share of the residual over its rigid modes.
  const Vec residual = free_rows.remaining_basis() * (C * best_x - target);
  std::map<int, double> share;
  for (Eigen::Index r = 0; r < residual.size(); ++r)
    share[bodies[static_cast<size_t>(coarse.row_owner()[static_cast<size_t>(r)].first)]] += residual[r] * residual[r];
  result.body = std::max_element(share.begin(), share.end(), [](const auto& a, const auto& b) {
                  return a.second < b.second;
                })->first;
  return result;
}

}  // namespace ffeti
