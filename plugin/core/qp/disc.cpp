#include "qp/disc.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ffeti::qp {
namespace {

/// A pair within this relative distance of its circle counts as on it.
constexpr double kCircleTolerance = 1e-12;

/// A pair on its circle whose curvature there, -n'g / ||d||, exceeds this times ||A|| has its
/// tangent held (hold_stiff_circle_pairs). Measured on the 3D friction scenes ([log](docs/log.md),
/// 2026-11-27, "stiff circles"): the lowest sum of 0.1 ... 3; 1 and 0.5 cost more on the
/// Cattaneo-Mindlin scene's step 2 (166, 160 against 121), 0.1 more on the sheared blocks.
constexpr double kStiffCircle = 0.3;

/// Calls visit(i) with the first component i of every disc pair, in order.
template <class Visit>
void for_each_disc_pair(const ConstraintSet& set, Visit visit) {
  for (const Block& block : set.blocks())
    if (block.kind == BlockKind::disc)
      for (Eigen::Index i = block.first; i < block.first + block.size; i += 2) visit(i);
}

Eigen::Vector2d offset_from_centre(const Vec& x, const ConstraintSet& set, Eigen::Index i) {
  return x.segment<2>(i) - set.disc_centre.segment<2>(i);
}

bool strictly_inside(const Eigen::Vector2d& d, double radius) { return d.norm() < radius * (1 - kCircleTolerance); }

}  // namespace

std::vector<Eigen::Index> held_disc_pairs(const Vec& x, const ConstraintSet& set) {
  std::vector<Eigen::Index> held;
  for_each_disc_pair(set, [&](Eigen::Index i) {
    if (!strictly_inside(offset_from_centre(x, set, i), set.disc_radius[i])) held.push_back(i);
  });
  return held;
}

void restrict_to_disc_faces(const Vec& x, const ConstraintSet& set, Vec& v) {
  for (const Eigen::Index i : held_disc_pairs(x, set)) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i);
    const double norm = d.norm();
    if (set.disc_radius[i] == 0 || norm == 0) {
      v.segment<2>(i).setZero();  // pinned: no direction is feasible
      continue;
    }
    const Eigen::Vector2d n = d / norm;  // outward unit normal
    v.segment<2>(i) -= n.dot(v.segment<2>(i)) * n;
  }
}

Vec circle_curvature(const Vec& x, const Vec& g, const ConstraintSet& set, const Vec& p) {
  Vec curvature = Vec::Zero(x.size());
  for (const Eigen::Index i : held_disc_pairs(x, set)) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i);
    const double norm = d.norm();
    if (set.disc_radius[i] == 0 || norm == 0) continue;  // pinned: p is 0 there
    const double holding = std::max(-d.dot(g.segment<2>(i)) / norm, 0.0);  // -n'g where -g points out
    curvature.segment<2>(i) = (holding / norm) * p.segment<2>(i);
  }
  return curvature;
}

void precondition_circle_curvature(const Vec& x, const Vec& g, const ConstraintSet& set, double a_norm, Vec& v) {
  for (const Eigen::Index i : held_disc_pairs(x, set)) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i);
    const double norm = d.norm();
    if (set.disc_radius[i] == 0 || norm == 0) continue;
    const double holding = std::max(-d.dot(g.segment<2>(i)) / norm, 0.0);
    v.segment<2>(i) /= 1 + holding / norm / a_norm;
  }
}

namespace {
/// Calls visit(i) with the first component i of every pair on its circle whose curvature
/// there exceeds kStiffCircle a_norm.
template <class Visit>
void for_each_stiff_circle_pair(const Vec& x, const Vec& g, const ConstraintSet& set, double a_norm, Visit visit) {
  for (const Eigen::Index i : held_disc_pairs(x, set)) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i);
    const double norm = d.norm();
    if (set.disc_radius[i] == 0 || norm == 0) continue;
    const double holding = std::max(-d.dot(g.segment<2>(i)) / norm, 0.0);
    if (holding / norm > kStiffCircle * a_norm) visit(i);
  }
}
}  // namespace

void hold_stiff_circle_pairs(const Vec& x, const Vec& g, const ConstraintSet& set, double a_norm, Vec& v) {
  for_each_stiff_circle_pair(x, g, set, a_norm, [&](Eigen::Index i) { v.segment<2>(i).setZero(); });
}

bool has_stiff_circle_pairs(const Vec& x, const Vec& g, const ConstraintSet& set, double a_norm) {
  bool found = false;
  for_each_stiff_circle_pair(x, g, set, a_norm, [&](Eigen::Index) { found = true; });
  return found;
}

int project_onto_discs(Vec& x, const ConstraintSet& set) {
  int moved = 0;
  for_each_disc_pair(set, [&](Eigen::Index i) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i);
    const double radius = set.disc_radius[i], norm = d.norm();
    if (norm <= radius) return;
    x.segment<2>(i) = set.disc_centre.segment<2>(i) + (radius / norm) * d;  // radially back onto the circle
    ++moved;
  });
  return moved;
}

void overwrite_disc_projected_gradient(const Vec& x, const Vec& g, const ConstraintSet& set, Vec& gp) {
  for_each_disc_pair(set, [&](Eigen::Index i) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i), gi = g.segment<2>(i);
    const double radius = set.disc_radius[i];
    if (strictly_inside(d, radius)) {
      gp.segment<2>(i) = gi;
    } else if (radius == 0) {
      gp.segment<2>(i).setZero();  // pinned: no direction is feasible
    } else {
      const Eigen::Vector2d n = d / d.norm();  // outward unit normal
      gp.segment<2>(i) = gi - std::min(n.dot(gi), 0.0) * n;
    }
  });
}

double disc_feasible_step(const Vec& x, const Vec& p, const ConstraintSet& set, bool slide_on_circles) {
  double step = std::numeric_limits<double>::infinity();
  for_each_disc_pair(set, [&](Eigen::Index i) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i), pi = p.segment<2>(i);
    const double pp = pi.squaredNorm();
    if (pp == 0) return;
    const double radius = set.disc_radius[i], dp = d.dot(pi);
    if (slide_on_circles && !strictly_inside(d, radius)) return;
    const double room = std::max(radius * radius - d.squaredNorm(), 0.0);  // g^2 - ||d||^2
    const double root = std::sqrt(dp * dp + pp * room);
    // a^2 pp - 2 a dp - room = 0; its larger root, written without cancellation either way.
    // On the circle (room 0) and not moving inward (dp <= 0) no step is feasible.
    step = std::min(step, dp > 0 ? (dp + root) / pp : room > 0 ? room / (root - dp) : 0.0);
  });
  return step;
}

void overwrite_disc_reduced_free_gradient(const Vec& x, const Vec& phi, const ConstraintSet& set, double abar,
                                          Vec& phit) {
  for_each_disc_pair(set, [&](Eigen::Index i) {
    const Eigen::Vector2d d = offset_from_centre(x, set, i);
    Eigen::Vector2d moved = d - abar * phi.segment<2>(i);  // x - abar phi, from the centre
    const double radius = set.disc_radius[i], norm = moved.norm();
    if (norm > radius) moved *= radius / norm;
    phit.segment<2>(i) = (d - moved) / abar;
  });
}

}  // namespace ffeti::qp
