#include "qp/held_modes.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ffeti::qp {
namespace {

/// A mode counts as held by bounded blocks alone when its part on the other components is
/// below this share of it (squared: the generalized eigenvalue a'C_u C_u'a / a'CC'a).
constexpr double kHeldShare = 1e-10;
/// Newton steps on Phi at most; each costs k' + a few dozen passes over the bounded blocks,
/// no multiplication.
constexpr int kNewtonSteps = 30;
/// Balanced when ||U'x|| is below this share of the forces that enter it.
constexpr double kBalanced = 1e-12;

}  // namespace

HeldModes::HeldModes(const Eigen::MatrixXd& C, const ConstraintSet& set) : set_(set) {
  // Nothing to hold without a bounded block: a frictionless solve copies nothing (C is k x n,
  // dense).
  const auto& blocks = set.blocks();
  if (C.rows() == 0 || C.cols() != set.size() ||
      std::none_of(blocks.begin(), blocks.end(), [](const Block& block) { return block.compact(); }))
    return;
  Eigen::MatrixXd unbounded_part = C;  // C with the bounded blocks' columns zeroed
  for (const Block& block : blocks)
    if (block.compact()) unbounded_part.middleCols(block.first, block.size).setZero();
  // a with C_u'a = 0, C_u the unbounded columns: the generalized eigenvectors of
  // (C_u C_u', CC') with eigenvalue 0, normalized a'CC'a = 1, so U = C'a has orthonormal columns.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eigen(unbounded_part * unbounded_part.transpose(),
                                                                         C * C.transpose());
  if (eigen.info() != Eigen::Success) return;
  std::vector<Eigen::Index> held;
  for (Eigen::Index j = 0; j < eigen.eigenvalues().size(); ++j)
    if (eigen.eigenvalues()[j] <= kHeldShare) held.push_back(j);
  if (held.empty()) return;
  Eigen::MatrixXd A(C.rows(), static_cast<Eigen::Index>(held.size()));
  for (size_t j = 0; j < held.size(); ++j) A.col(static_cast<Eigen::Index>(j)) = eigen.eigenvectors().col(held[j]);
  U_ = C.transpose() * A;
  for (const Block& block : set.blocks())
    if (!block.compact()) U_.middleRows(block.first, block.size).setZero();  // round-off there
}

double HeldModes::exact_step(const Vec& y, const Vec& Up, Vec& x) const {
  const auto slope = [&](double t) {
    value(y + t * Up, x);
    return Up.dot(x);
  };
  double lo = 0, slope_lo = slope(0.0);
  if (!(slope_lo > 0)) return 0.0;
  double hi = 1, slope_hi = slope(hi);
  while (slope_hi > 0) {  // bracket the sign change
    lo = hi, slope_lo = slope_hi;
    hi *= 4;
    if (hi > 1e30) return -1.0;  // Phi rises without end along p: nothing holds the modes
    slope_hi = slope(hi);
  }
  // Illinois' false position: fast where the slope is smooth, sure where it jumps (boxes).
  int kept_side = 0;
  for (int k = 0; k < 200 && hi - lo > 1e-13 * hi; ++k) {
    const double t = lo + (hi - lo) * slope_lo / (slope_lo - slope_hi);
    if (!(t > lo && t < hi)) break;
    const double s = slope(t);
    if (s > 0) {
      lo = t, slope_lo = s;
      if (kept_side == 1) slope_hi *= 0.5;
      kept_side = 1;
    } else {
      hi = t, slope_hi = s;
      if (kept_side == -1) slope_lo *= 0.5;
      kept_side = -1;
      if (s == 0) return t;
    }
  }
  return lo;
}

bool HeldModes::balance(const Vec& g, Vec& d) const {
  d = Vec::Zero(g.size());
  if (empty()) return true;
  if (!g.allFinite()) return false;
  const Eigen::Index modes = U_.cols();
  Vec beta = Vec::Zero(modes), y = g, x = Vec::Zero(g.size()), dx(g.size());
  value(y, x);
  for (int step = 0; step < kNewtonSteps; ++step) {
    const Vec gradient = U_.transpose() * x;
    const double forces = (U_.cwiseAbs().transpose() * x.cwiseAbs()).norm();
    if (gradient.norm() <= kBalanced * forces) break;
    // -Phi's Hessian U' (-dx/dy) U: the discs' turn (zero on boxes, where Phi is piecewise
    // linear and the line search alone finds its kink).
    Eigen::MatrixXd curvature(modes, modes);
    for (Eigen::Index j = 0; j < modes; ++j) {
      dx.setZero();
      set_.add_linear_minimizer_change(y, U_.col(j), dx);
      curvature.col(j) = -(U_.transpose() * dx);
    }
    const double trace = curvature.trace();
    Vec p = gradient;
    if (trace > 0) {
      curvature.diagonal().array() += 1e-12 * trace;
      p = curvature.ldlt().solve(gradient);
      if (!p.allFinite() || p.dot(gradient) <= 0) p = gradient;
    }
    const Vec Up = U_ * p;
    const double t = exact_step(y, Up, x);
    if (t < 0) return false;
    beta += t * p;
    y = g + U_ * beta;
    value(y, x);
    if (t * p.norm() <= 1e-14 * beta.norm()) break;
  }
  if (!beta.allFinite()) return false;
  d = U_ * beta;
  return true;
}

}  // namespace ffeti::qp
