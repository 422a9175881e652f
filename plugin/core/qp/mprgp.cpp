#include "qp/mprgp.h"

#include "qp/disc.h"
#include "qp/start_settling.h"

#include <cmath>
#include <stdexcept>

namespace ffeti {
namespace {

/// Free gradient phi: g on the free set, 0 on the active set; on a disc pair on its circle
/// g's tangential part (the circle's tangent is free, qp::restrict_to_disc_faces), but 0 where
/// the circle curves much more than A (qp::hold_stiff_circle_pairs: the tangent held).
void free_gradient(const Vec& x, const Vec& g, const qp::ConstraintSet& bounds, double a_norm, Vec& phi) {
  for (Eigen::Index i = 0; i < x.size(); ++i) phi[i] = bounds.free(i, x[i]) ? g[i] : 0.0;
  if (bounds.has_discs()) {
    qp::restrict_to_disc_faces(x, bounds, phi);
    qp::hold_stiff_circle_pairs(x, g, bounds, a_norm, phi);
  }
}

/// phi'phit and ||phit||^2 of the reduced free gradient on the free set: phit_i =
/// min((x_i - l_i) / abar, phi_i), then max((x_i - u_i) / abar, .) where bounded (phi_i where
/// unbounded, 0 on the active set): the part of phi a step abar can take without leaving
/// the box.
struct ReducedFreeGradient {
  double dot_phi = 0, squared_norm = 0;
};

ReducedFreeGradient reduced_free_gradient(const Vec& x, const Vec& phi, const qp::ConstraintSet& bounds, double abar) {
  const Vec& lower = bounds.lower;
  const auto component = [&](Eigen::Index i) {
    double phit = phi[i];
    if (bounds.free(i, x[i])) {
      if (lower[i] != kUnbounded) phit = std::min((x[i] - lower[i]) / abar, phit);
      if (bounds.has_upper(i)) phit = std::max((x[i] - bounds.upper[i]) / abar, phit);
    }
    return phit;
  };
  ReducedFreeGradient r;
  if (bounds.has_discs()) {  // the disc pairs' phit couples their two components
    Vec phit(x.size());
    for (Eigen::Index i = 0; i < x.size(); ++i) phit[i] = component(i);
    qp::overwrite_disc_reduced_free_gradient(x, phi, bounds, abar, phit);
    r.dot_phi = phit.dot(phi);
    r.squared_norm = phit.squaredNorm();
    return r;
  }
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double phit = component(i);
    r.dot_phi += phit * phi[i];
    r.squared_norm += phit * phit;
  }
  return r;
}

/// Largest step a >= 0 with l <= x - a p <= u on the bounded components and the disc pairs in
/// their discs (with `slide_on_circles` but those on their circle, which p moves round it).
double feasible_step(const Vec& x, const Vec& p, const qp::ConstraintSet& bounds, bool slide_on_circles) {
  const Vec& lower = bounds.lower;
  double step = std::numeric_limits<double>::infinity();
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (lower[i] != kUnbounded && p[i] > 0) step = std::min(step, (x[i] - lower[i]) / p[i]);
    if (p[i] < 0 && bounds.has_upper(i)) step = std::min(step, (x[i] - bounds.upper[i]) / p[i]);
  }
  if (bounds.has_discs()) step = std::min(step, qp::disc_feasible_step(x, p, bounds, slide_on_circles));
  return step;
}

}  // namespace

int off_bound_count(const Vec& x, const Vec& lower) {
  int count = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) count += lower[i] != kUnbounded && x[i] > lower[i] ? 1 : 0;
  return count;
}

int project_onto_bounds(Vec& x, const qp::ConstraintSet& bounds) {
  const Vec& lower = bounds.lower;
  int projected = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (lower[i] != kUnbounded && x[i] < lower[i]) {
      x[i] = lower[i];
      ++projected;
    } else if (bounds.has_upper(i) && x[i] > bounds.upper[i]) {
      x[i] = bounds.upper[i];
      ++projected;
    }
  }
  if (bounds.has_discs()) projected += qp::project_onto_discs(x, bounds);
  return projected;
}

namespace {
/// Component i of the projected gradient.
double projected_component(const Vec& x, const Vec& g, const qp::ConstraintSet& bounds, Eigen::Index i) {
  if (bounds.free(i, x[i])) return g[i];
  if (bounds.pinned(i, x[i])) return 0.0;  // at both bounds: no direction is feasible
  if (!above_bound(x[i], bounds.lower[i])) return std::min(g[i], 0.0);  // at the lower bound
  return std::max(g[i], 0.0);                                          // at the upper bound
}

/// The fixed projected step x = P(x - abar v), v = phi: MPRGP's expansion step. With discs v =
/// g - beta, phi plus the part of g pointing out of the set (0 on boxes once projected; on a
/// pair on its circle the normal part of g when -g points out): phi alone, tangential there,
/// is not guaranteed to decrease f (the projection back onto the circle costs n'g times its
/// inward move), P(x - abar (g - beta)) decreases f by at least (1/abar - ||A||/2) ||dx||^2.
void fixed_projected_step(Vec& x, const Vec& g, const Vec& phi, const qp::ConstraintSet& bounds, double abar) {
  if (bounds.has_discs()) x -= abar * (g - projected_gradient(x, g, bounds) + phi);
  else x -= abar * phi;
  project_onto_bounds(x, bounds);
}

/// g within this relative part of ||gP|| is taken as known: a CG step that slides round the
/// circles updates g along the tangent lines and leaves out A times the projection's move
/// back onto the circles (bounded by ||A|| times its norm) until the sum of those bounds
/// exceeds it; g is recomputed then, and before any return.
constexpr double kSlideGradientError = 1e-2;

/// The CG step x - a_cg p on a set with discs (a_cg within the free pairs' feasible step).
/// Pairs on their circle move along its tangent and leave it by a second-order amount: they
/// go back onto it radially (delta), which changes g by A delta; `gradient_error` bounds
/// the g so left out (||A|| ||delta|| per step), and g is recomputed (one multiplication)
/// when it exceeds kSlideGradientError ||gP||. The step is kept if f falls by at least half
/// what it takes on the tangent lines, (g'p) a_cg / 2, by the bound f(y + delta) <= f(y) +
/// g(y)'delta + ||A|| ||delta||^2 / 2; otherwise (the circles curve too much for the step)
/// the fixed projected step P(x - abar (g - beta)) instead, and the CG recurrence restarts
/// (returns true).
bool slide_cg_step(const qp::Problem& problem, double abar, double a_cg, const Vec& p, const Vec& Ap, Vec& x,
                   Vec& g, const Vec& phi, double& gradient_error, IterationCounts& counts) {
  const Vec& b = problem.b;
  const double a_norm = problem.hessian_norm;
  const double g_p = g.dot(p);
  Vec moved = x - a_cg * p;
  Vec moved_gradient = g - a_cg * Ap;  // at moved, before the projection
  const Vec before_projection = moved;
  if (qp::project_onto_discs(moved, problem.constraints) == 0) {  // no pair slid: a plain CG step
    x.swap(moved);
    g.swap(moved_gradient);
    return false;
  }
  const Vec delta = moved - before_projection;
  const double delta_norm = delta.norm();
  const double decrease_bound = a_cg * g_p - 0.5 * a_cg * a_cg * p.dot(Ap) - moved_gradient.dot(delta) -
                                0.5 * a_norm * delta_norm * delta_norm;
  Vec A_x(x.size());
  if (decrease_bound >= 0.25 * a_cg * g_p) {
    x.swap(moved);
    g.swap(moved_gradient);
    gradient_error += a_norm * delta_norm;
    if (gradient_error > kSlideGradientError * projected_gradient(x, g, problem.constraints).norm()) {
      problem.hessian(x, A_x);
      ++counts.hessian;
      g = A_x - b;
      gradient_error = 0;
    }
    return false;
  }
  fixed_projected_step(x, g, phi, problem.constraints, abar);
  problem.hessian(x, A_x);
  ++counts.hessian;
  g = A_x - b;
  gradient_error = 0;
  return true;
}
}  // namespace

Vec projected_gradient(const Vec& x, const Vec& g, const qp::ConstraintSet& bounds) {
  Vec gp(x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) gp[i] = projected_component(x, g, bounds, i);
  if (bounds.has_discs()) qp::overwrite_disc_projected_gradient(x, g, bounds, gp);
  return gp;
}

double projected_gradient_max(const Vec& x, const Vec& g, const qp::ConstraintSet& bounds) {
  if (bounds.has_discs()) return projected_gradient(x, g, bounds).lpNorm<Eigen::Infinity>();
  double largest = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) largest = std::max(largest, std::abs(projected_component(x, g, bounds, i)));
  return largest;
}

void MprgpSettings::validate() const {
  if (!(gamma > 0)) throw std::invalid_argument("MPRGP gamma must be > 0");
  if (!(step_factor > 0 && step_factor <= 2))
    throw std::invalid_argument("MPRGP step_factor must lie in (0, 2]");
  if (settle_rounds < 0) throw std::invalid_argument("MPRGP settle_rounds must be >= 0");
}


MprgpResult mprgp(const qp::Problem& problem, const MprgpSettings& settings, Vec& x, const qp::Budget& budget,
                  const StopTest& stop, const Monitor& monitor) {
  Vec g;
  double g_unused_error = 0;  // g is not returned: not recomputed at the end either
  return mprgp_with_gradient(problem, settings, x, g, false, budget, stop, monitor, &g_unused_error);
}

MprgpResult mprgp_with_gradient(const qp::Problem& problem, const MprgpSettings& settings, Vec& x, Vec& g,
                                bool gradient_is_current, const qp::Budget& budget, const StopTest& stop,
                                const Monitor& monitor, double* inexact_gradient) {
  const LinearOperator& A = problem.hessian;
  const Vec& b = problem.b;
  const qp::ConstraintSet& bounds = problem.constraints;
  const double a_norm = problem.hessian_norm;
  const LinearOperator& preconditioner = problem.preconditioner;
  settings.validate();
  const Vec& lower = bounds.lower;
  MprgpResult result;
  const Eigen::Index n = b.size();
  if (x.size() != n || lower.size() != n || (bounds.upper.size() && bounds.upper.size() != n))
    throw std::invalid_argument("MPRGP: x, b and the bounds differ in size");
  if (!(a_norm > 0)) throw std::invalid_argument("MPRGP: the norm estimate of A must be > 0");
  if (problem.range_projector) throw std::invalid_argument("MPRGP: the problem has an equality part (SMALBE's)");
  const double abar = settings.step_factor / a_norm;
  IterationCounts& counts = result.counts;

  auto multiply = [&](const Vec& v, Vec& Av) { A(v, Av); ++counts.hessian; };
  Vec phi(n), beta(n), p(n), Ap(n), z(n), trial, trial_gradient, A_trial, curved_Ap;
  // z = M phi on the free set, 0 on the active set (z = phi without a preconditioner).
  // With discs z is also divided by 1 + the circles' curvature / ||A|| on the pairs on a
  // circle (qp::precondition_circle_curvature: without it a pair of small radius and large
  // -n'g, a row slipping fast under a small bound, sets every CG step: the 3D forced slide
  // did not converge in 10000 multiplications).
  const auto precondition_in_face = [&]() -> const Vec& {
    if (!preconditioner && !bounds.has_discs()) return phi;
    if (preconditioner) {
      preconditioner(phi, z);
      ++counts.preconditioner;
    } else {
      z = phi;
    }
    for (Eigen::Index i = 0; i < n; ++i)
      if (!bounds.free(i, x[i])) z[i] = 0.0;
    if (bounds.has_discs()) {
      qp::restrict_to_disc_faces(x, bounds, z);
      qp::hold_stiff_circle_pairs(x, g, bounds, a_norm, z);
      qp::precondition_circle_curvature(x, g, bounds, a_norm, z);
    }
    return z;
  };

  // Bound on the part of g that sliding CG steps left out (slide_cg_step); 0 without discs.
  // With `inexact_gradient` it comes in with g and goes out with it instead of a
  // multiplication on every return (SMALBE's inner solves: one per outer iteration).
  double gradient_error = gradient_is_current && inexact_gradient ? *inexact_gradient : 0.0;
  const auto recompute_gradient = [&]() {
    multiply(x, Ap);
    g = Ap - b;
    gradient_error = 0;
  };
  const auto exact_gradient = [&]() {
    if (inexact_gradient) *inexact_gradient = gradient_error;
    else if (gradient_error > 0) recompute_gradient();
  };
  if (!gradient_is_current) {
    project_onto_bounds(x, bounds);
    g.resize(n);
    multiply(x, Ap);
    g = Ap - b;  // g = A x - b
  }
  free_gradient(x, g, bounds, a_norm, phi);
  p = precondition_in_face();

  // True while the direction descends from one carried across a face change (expansion
  // projected_cg): such a direction is not a Krylov direction of the current face, so a step
  // along it must decrease f at least as much as the fixed step abar along the reduced free
  // gradient is guaranteed to; a step that does not restarts CG from the free gradient.
  bool continued = false;
  for (int iteration = 0;; ++iteration) {
    // Split the gradient: chopped gradient beta (at a bound, the part pointing into the box), and the reduced free gradient's products.
    double beta_sq = 0, gp_sq = 0;
    if (bounds.has_discs()) {  // gP = phi + beta, their supports apart; on a circle gP couples the pair
      beta = projected_gradient(x, g, bounds) - phi;
      beta_sq = beta.squaredNorm();
      gp_sq = phi.squaredNorm() + beta_sq;
    } else {
      for (Eigen::Index i = 0; i < n; ++i) {
        beta[i] = bounds.free(i, x[i]) ? 0.0 : projected_component(x, g, bounds, i);
        beta_sq += beta[i] * beta[i];
        gp_sq += phi[i] * phi[i] + beta[i] * beta[i];
      }
    }
    const ReducedFreeGradient reduced = reduced_free_gradient(x, phi, bounds, abar);
    const double phit_phi = reduced.dot_phi, phit_sq = reduced.squared_norm;
    result.gradient_norm = std::sqrt(gp_sq);
    if (gradient_error > kSlideGradientError * result.gradient_norm) {  // g carried in, or gP fell since
      recompute_gradient();  // no stop decision on a g off by more
      free_gradient(x, g, bounds, a_norm, phi);
      p = precondition_in_face();
      continued = false;
      --iteration;
      continue;
    }
    if (monitor) monitor({"mprgp", iteration, result.gradient_norm, 0.0, counts.hessian, off_bound_count(x, lower)});
    if (stop(x, g, result.gradient_norm)) {
      result.status = SolveStatus::converged;
      exact_gradient();
      return result;
    }
    if (counts.hessian >= budget.max_hessian()) {
      result.status = SolveStatus::max_iterations;
      exact_gradient();
      return result;
    }
    if (iteration == 0 && settings.settle_rounds > 0) {  // a start that passes the test is kept as is
      settle_start(A, b, bounds, settings.settle_rounds, budget.max_hessian(), x, g, counts, preconditioner, monitor);
      free_gradient(x, g, bounds, a_norm, phi);
      p = precondition_in_face();
      continue;
    }

    if (beta_sq <= settings.gamma * settings.gamma * phit_phi) {
      // x is proportional: conjugate gradient step, or expansion if it would leave the set.
      // Not conjugate_gradient(): each step chooses among CG, expansion and proportioning on a
      // face that changes, and conjugacy is kept only within a face.
      multiply(p, Ap);
      // With discs the step and the conjugacy use A plus the circles' curvature (the Hessian
      // round them, qp::circle_curvature); Ap alone updates g.
      if (bounds.has_discs()) curved_Ap = Ap + qp::circle_curvature(x, g, bounds, p);
      const Vec& step_Ap = bounds.has_discs() ? curved_Ap : Ap;
      const double pAp = p.dot(step_Ap);
      if (!(pAp > 0)) {
        result.status = SolveStatus::not_positive_definite;
        exact_gradient();
        return result;
      }
      const double g_p = g.dot(p);
      const double a_cg = g_p / pAp;
      const double a_f = feasible_step(x, p, bounds, true);
      if (a_cg <= a_f) {
        // Exact line search decreases f by (g'p)^2 / (2 p'Ap); the fixed step's guarantee:
        const bool guaranteed = 0.5 * a_cg * g_p >= abar * phit_phi - 0.5 * a_norm * abar * abar * phit_sq;
        bool restart = continued && !guaranteed;
        if (bounds.has_discs()) {
          restart = slide_cg_step(problem, abar, a_cg, p, Ap, x, g, phi, gradient_error, counts) || restart;
        } else {
          x -= a_cg * p;   // x_{k+1} = x_k - a_cg p
          g -= a_cg * Ap;  // g = A x - b
        }
        free_gradient(x, g, bounds, a_norm, phi);
        const Vec& direction = precondition_in_face();
        if (restart) {
          p = direction;
          continued = false;
        } else {
          p = direction - (direction.dot(step_Ap) / pAp) * p;  // A-conjugate to the previous direction
          if (bounds.has_discs()) {  // round the circles the face has turned: p on its new tangents
            qp::restrict_to_disc_faces(x, bounds, p);
            qp::hold_stiff_circle_pairs(x, g, bounds, a_norm, p);
            if (!(p.dot(g) > 0)) p = direction;
          }
        }
        ++counts.cg;
      } else {
        ++counts.expansion;
        bool expanded = false;
        if (settings.expansion != MprgpExpansion::fixed_step) {
          // The CG step taken in full and projected: it can add many bounds at once, where
          // the fixed step moves at most abar |phi| per step. Kept only if it decreases f at
          // least as much as the fixed-step expansion is guaranteed to (the bound below).
          const double f_x = 0.5 * x.dot(g - b);
          const double f_half = f_x - a_f * g.dot(p) + 0.5 * a_f * a_f * pAp;
          trial = x - a_cg * p;
          project_onto_bounds(trial, bounds);
          x -= a_f * p;
          g -= a_f * Ap;
          // Pairs sliding on their circle went a little out (second order in a_f): back onto
          // it, g there inexact by A times that, until the step below recomputes it.
          if (bounds.has_discs()) qp::project_onto_discs(x, bounds);
          free_gradient(x, g, bounds, a_norm, phi);
          const ReducedFreeGradient at_half = reduced_free_gradient(x, phi, bounds, abar);  // at x - a_f p
          const double guaranteed =
              f_half - abar * at_half.dot_phi + 0.5 * a_norm * abar * abar * at_half.squared_norm;
          multiply(trial, A_trial);
          trial_gradient = A_trial - b;
          if (0.5 * trial.dot(trial_gradient - b) <= guaranteed) {
            x.swap(trial);
            g.swap(trial_gradient);
            expanded = true;
          } else {
            ++counts.expansion_fallback;
          }
        } else {
          x -= a_f * p;
          g -= a_f * Ap;
          if (bounds.has_discs()) qp::project_onto_discs(x, bounds);  // as above
          free_gradient(x, g, bounds, a_norm, phi);
        }
        if (!expanded) {
          fixed_projected_step(x, g, phi, bounds, abar);  // expansion: fixed-step projected gradient step
          multiply(x, Ap);
          g = Ap - b;
        }
        gradient_error = 0;  // g computed anew at the new x, either way
        free_gradient(x, g, bounds, a_norm, phi);
        const Vec& direction = precondition_in_face();
        continued = false;
        if (expanded && settings.expansion == MprgpExpansion::projected_cg) {
          // The CG recurrence goes on in the new face: a restart from the free gradient after
          // every expansion is steepest descent where the contact zone's edge moves a band per
          // step (the large contact zone: 1.7 times the multiplications, docs/algorithms.md).
          for (Eigen::Index i = 0; i < n; ++i)
            if (!bounds.free(i, x[i])) p[i] = 0.0;
          if (bounds.has_discs()) {
            qp::restrict_to_disc_faces(x, bounds, p);
            qp::hold_stiff_circle_pairs(x, g, bounds, a_norm, p);
          }
          trial = direction - (direction.dot(step_Ap) / pAp) * p;  // Ap = A p of the last direction
          continued = trial.dot(g) > 0;                       // a descent direction, or restart
        }
        if (continued) p.swap(trial);
        else p = direction;
      }
    } else {
      // Proportioning: release components of the active set along the chopped gradient (on a
      // disc pair on its circle its inward normal part: the tangential part is free).
      // Where stiff circle pairs hold their tangent, the projected step P(x - abar (g - phi))
      // instead (the free components stay; phi, tangential on the other circle pairs, does
      // not change f to first order along their radial moves): it turns those pairs by
      // about Newton's step round their circles and decreases f by at least
      // (1/abar - ||A||/2) ||dx||^2 (the projection's variational inequality).
      if (bounds.has_discs() && qp::has_stiff_circle_pairs(x, g, bounds, a_norm)) {
        x -= abar * (g - phi);
        project_onto_bounds(x, bounds);
        multiply(x, Ap);
        g = Ap - b;
        gradient_error = 0;
        free_gradient(x, g, bounds, a_norm, phi);
        p = precondition_in_face();
        continued = false;
        ++counts.proportioning;
        continue;
      }
      multiply(beta, Ap);
      const double dAd = beta.dot(Ap);
      if (!(dAd > 0)) {
        result.status = SolveStatus::not_positive_definite;
        exact_gradient();
        return result;
      }
      // Exact line search along beta, held inside the box: with upper bounds a component
      // released from one bound could otherwise pass the other (lower bounds only: no cap).
      const double a_feasible = feasible_step(x, beta, bounds, false);
      const double a = std::min(g.dot(beta) / dAd, a_feasible);
      x -= a * beta;
      if (a == a_feasible) project_onto_bounds(x, bounds);  // the bound reached exactly, not round-off past it
      g -= a * Ap;
      free_gradient(x, g, bounds, a_norm, phi);
      p = precondition_in_face();
      continued = false;
      ++counts.proportioning;
    }
  }
}

}  // namespace ffeti
