#include "qp/disc_set.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace ffeti::qp {
namespace {

/// A pair within this relative distance of its circle counts as on it.
constexpr double kCircleTolerance = 1e-12;

/// A pair on its circle whose curvature there, -n'g / ||d||, exceeds this times ||A|| has its
/// tangent held (restrict_to_face). Measured on the 3D friction scenes ([log](docs/log.md),
/// 2026-11-27, "stiff circles"): the lowest sum of 0.1 ... 3; 1 and 0.5 cost more on the
/// Cattaneo-Mindlin scene's step 2 (166, 160 against 121), 0.1 more on the sheared blocks.
constexpr double kStiffCircle = 0.3;

bool strictly_inside(const Eigen::Vector2d& d, double radius) { return d.norm() < radius * (1 - kCircleTolerance); }

}  // namespace

DiscSet::DiscSet(Eigen::Index first, const Vec& centre, const Vec& radius)
    : SetKind({first, centre.size(), BlockKind::disc}), centre_(centre), radius_(radius) {
  if (centre.size() != 2 * radius.size()) throw std::invalid_argument("disc block: centre needs two entries per radius");
  if (!((radius.array() >= 0).all() && radius.allFinite() && centre.allFinite()))
    throw std::invalid_argument("disc block: radii must be finite and >= 0, centres finite");
}

std::shared_ptr<const SetKind> DiscSet::shifted(const Vec& offset) const {
  return std::make_shared<DiscSet>(block().first, centre_ - offset.segment(block().first, block().size), radius_);
}

Eigen::Vector2d DiscSet::offset_from_centre(const Vec& x, Eigen::Index i) const {
  return x.segment<2>(i) - centre_.segment<2>(i - block().first);
}

std::vector<Eigen::Index> DiscSet::held_pairs(const Vec& x) const {
  std::vector<Eigen::Index> held;
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2)
    if (!strictly_inside(offset_from_centre(x, i), radius(i))) held.push_back(i);
  return held;
}

double DiscSet::curvature(const Vec& x, const Vec& g, Eigen::Index i) const {
  const Eigen::Vector2d d = offset_from_centre(x, i);
  const double norm = d.norm();
  if (radius(i) == 0 || norm == 0) return -1.0;
  const double holding = std::max(-d.dot(g.segment<2>(i)) / norm, 0.0);  // -n'g where -g points out
  return holding / norm;
}

int DiscSet::project(Vec& x) const {
  int moved = 0;
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2) {
    const Eigen::Vector2d d = offset_from_centre(x, i);
    const double r = radius(i), norm = d.norm();
    if (norm <= r) continue;
    x.segment<2>(i) = centre_.segment<2>(i - block().first) + (r / norm) * d;  // radially back onto the circle
    ++moved;
  }
  return moved;
}

bool DiscSet::contains(const Vec& x) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2)
    if (offset_from_centre(x, i).norm() > radius(i)) return false;
  return true;
}

void DiscSet::restrict_to_face(const Vec& x, const Vec& g, double a_norm, Vec& v) const {
  for (const Eigen::Index i : held_pairs(x)) {
    const double c = curvature(x, g, i);
    if (c < 0 || c > kStiffCircle * a_norm) {  // pinned, or a stiff circle: the tangent held
      v.segment<2>(i).setZero();
      continue;
    }
    const Eigen::Vector2d d = offset_from_centre(x, i);
    const Eigen::Vector2d n = d / d.norm();  // outward unit normal
    v.segment<2>(i) -= n.dot(v.segment<2>(i)) * n;
  }
}

void DiscSet::mark_free(const Vec& x, std::vector<char>& face) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2)
    face[i] = face[i + 1] = strictly_inside(offset_from_centre(x, i), radius(i));
}

void DiscSet::projected_gradient(const Vec& x, const Vec& g, Vec& gp) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2) {
    const Eigen::Vector2d d = offset_from_centre(x, i), gi = g.segment<2>(i);
    if (strictly_inside(d, radius(i))) {
      gp.segment<2>(i) = gi;
    } else if (radius(i) == 0) {
      gp.segment<2>(i).setZero();  // pinned: no direction is feasible
    } else {
      const Eigen::Vector2d n = d / d.norm();  // outward unit normal
      gp.segment<2>(i) = gi - std::min(n.dot(gi), 0.0) * n;
    }
  }
}

void DiscSet::reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2) {
    const Eigen::Vector2d d = offset_from_centre(x, i);
    Eigen::Vector2d moved = d - abar * phi.segment<2>(i);  // x - abar phi, from the centre
    const double r = radius(i), norm = moved.norm();
    if (norm > r) moved *= r / norm;
    phit.segment<2>(i) = (d - moved) / abar;
  }
}

double DiscSet::feasible_step(const Vec& x, const Vec& p, bool slide_on_circles) const {
  double step = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2) {
    const Eigen::Vector2d d = offset_from_centre(x, i), pi = p.segment<2>(i);
    const double pp = pi.squaredNorm();
    if (pp == 0) continue;
    const double r = radius(i), dp = d.dot(pi);
    if (slide_on_circles && !strictly_inside(d, r)) continue;
    const double room = std::max(r * r - d.squaredNorm(), 0.0);  // g^2 - ||d||^2
    const double root = std::sqrt(dp * dp + pp * room);
    // a^2 pp - 2 a dp - room = 0; its larger root, written without cancellation either way.
    // On the circle (room 0) and not moving inward (dp <= 0) no step is feasible.
    step = std::min(step, dp > 0 ? (dp + root) / pp : room > 0 ? room / (root - dp) : 0.0);
  }
  return step;
}

void DiscSet::add_curvature(const Vec& x, const Vec& g, const Vec& p, Vec& Ap) const {
  for (const Eigen::Index i : held_pairs(x)) {
    const double c = curvature(x, g, i);
    if (c >= 0) Ap.segment<2>(i) += c * p.segment<2>(i);  // pinned: p is 0 there
  }
}

void DiscSet::precondition_curvature(const Vec& x, const Vec& g, double a_norm, Vec& v) const {
  for (const Eigen::Index i : held_pairs(x)) {
    const double c = curvature(x, g, i);
    if (c >= 0) v.segment<2>(i) /= 1 + c / a_norm;
  }
}

bool DiscSet::holds_tangents(const Vec& x, const Vec& g, double a_norm) const {
  for (const Eigen::Index i : held_pairs(x))
    if (curvature(x, g, i) > kStiffCircle * a_norm) return true;
  return false;
}

double DiscSet::linear_minimum(const Vec& y, Vec& x) const {
  double value = 0;
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2) {
    const Eigen::Vector2d yi = y.segment<2>(i), c = centre_.segment<2>(i - block().first);
    const double norm = yi.norm();
    x.segment<2>(i) = norm > 0 ? Eigen::Vector2d(c - (radius(i) / norm) * yi) : c;
    value += yi.dot(x.segment<2>(i));
  }
  return value;
}

void DiscSet::add_linear_minimizer_change(const Vec& y, const Vec& dy, Vec& dx) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; i += 2) {
    const Eigen::Vector2d yi = y.segment<2>(i), dyi = dy.segment<2>(i);
    const double norm = yi.norm();
    if (norm == 0) continue;
    const Eigen::Vector2d across = dyi - (yi.dot(dyi) / (norm * norm)) * yi;
    dx.segment<2>(i) -= (radius(i) / norm) * across;
  }
}

}  // namespace ffeti::qp
