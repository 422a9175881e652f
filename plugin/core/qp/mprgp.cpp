#include "qp/mprgp.h"

#include "qp/start_settling.h"

#include <cmath>
#include <stdexcept>

namespace ffeti {
namespace {

/// The fixed projected step x = P(x - abar v), v = g - beta: MPRGP's expansion step. On flat
/// faces it equals P(x - abar phi) (the chopped gradient points out of the set, which the
/// projection undoes); on a disc pair on its circle v adds to the tangential phi the normal
/// part of g when -g points out: phi alone is not guaranteed to decrease f (the projection
/// back onto the circle costs n'g times its inward move), P(x - abar (g - beta)) decreases f
/// by at least (1/abar - ||A||/2) ||dx||^2.
void fixed_projected_step(Vec& x, const Vec& g, const Vec& phi, const qp::ConstraintSet& set, double abar) {
  x -= abar * (g - set.projected_gradient(x, g) + phi);
  set.project(x);
}

/// g within this relative part of ||gP|| is taken as known: a CG step that slides round the
/// circles updates g along the tangent lines and leaves out A times the projection's move
/// back onto the circles (bounded by ||A|| times its norm) until the sum of those bounds
/// exceeds it; g is recomputed then, and before any return.
constexpr double kSlideGradientError = 1e-2;

/// Charges the budget with a solve's multiplications, whichever way the solve returns.
class BudgetCharge {
 public:
  BudgetCharge(qp::Budget& budget, const IterationCounts& counts) : budget_(budget), counts_(counts) {}
  BudgetCharge(const BudgetCharge&) = delete;
  BudgetCharge& operator=(const BudgetCharge&) = delete;
  ~BudgetCharge() { budget_.charge(counts_.hessian); }

 private:
  qp::Budget& budget_;
  const IterationCounts& counts_;
};

/// The CG step x - a_cg p (a_cg within the feasible step, pairs on their circle left out).
/// On flat faces that is all. Pairs on their circle move along its tangent and leave it by
/// a second-order amount: they go back onto it radially (delta), which changes g by A delta;
/// `gradient_error` bounds the g so left out (||A|| ||delta|| per step), and g is recomputed
/// (one multiplication) when it exceeds kSlideGradientError ||gP||. The step is kept if f
/// falls by at least half what it takes on the tangent lines, (g'p) a_cg / 2, by the bound
/// f(y + delta) <= f(y) + g(y)'delta + ||A|| ||delta||^2 / 2; otherwise (the circles curve too
/// much for the step) the fixed projected step P(x - abar (g - beta)) instead, and the CG
/// recurrence restarts (returns true).
bool cg_step(const qp::Problem& problem, double abar, double a_cg, const Vec& p, const Vec& Ap, Vec& x, Vec& g,
             const Vec& phi, double& gradient_error, IterationCounts& counts) {
  const Vec& b = problem.b;
  const qp::ConstraintSet& set = problem.constraints;
  const double a_norm = problem.hessian_norm;
  if (!set.curved()) {  // the step stays in the flat faces: in place, nothing to project back
    x -= a_cg * p;
    g -= a_cg * Ap;
    return false;
  }
  Vec moved = x - a_cg * p;
  Vec moved_gradient = g - a_cg * Ap;  // at moved, before the projection
  if (set.project_curved(moved) == 0) {  // no pair slid: a plain CG step
    x.swap(moved);
    g.swap(moved_gradient);
    return false;
  }
  const double g_p = g.dot(p);
  const Vec delta = moved - (x - a_cg * p);
  const double delta_norm = delta.norm();
  const double decrease_bound = a_cg * g_p - 0.5 * a_cg * a_cg * p.dot(Ap) - moved_gradient.dot(delta) -
                                0.5 * a_norm * delta_norm * delta_norm;
  Vec A_x(x.size());
  if (decrease_bound >= 0.25 * a_cg * g_p) {
    x.swap(moved);
    g.swap(moved_gradient);
    gradient_error += a_norm * delta_norm;
    if (gradient_error > kSlideGradientError * set.projected_gradient(x, g).norm()) {
      problem.hessian(x, A_x);
      ++counts.hessian;
      g = A_x - b;
      gradient_error = 0;
    }
    return false;
  }
  fixed_projected_step(x, g, phi, set, abar);
  problem.hessian(x, A_x);
  ++counts.hessian;
  g = A_x - b;
  gradient_error = 0;
  return true;
}
}  // namespace

void MprgpSettings::validate() const {
  if (!(gamma > 0)) throw std::invalid_argument("MPRGP gamma must be > 0");
  if (!(step_factor > 0 && step_factor <= 2))
    throw std::invalid_argument("MPRGP step_factor must lie in (0, 2]");
  if (settle_rounds < 0) throw std::invalid_argument("MPRGP settle_rounds must be >= 0");
}


MprgpResult mprgp(const qp::Problem& problem, const MprgpSettings& settings, Vec& x, qp::Budget& budget,
                  const StopTest& stop, const Monitor& monitor) {
  settings.validate();
  Vec g;
  double g_unused_error = 0;  // g is not returned: not recomputed at the end either
  return mprgp_with_gradient(problem, settings, x, g, false, budget, stop, monitor, &g_unused_error);
}

MprgpResult mprgp_with_gradient(const qp::Problem& problem, const MprgpSettings& settings, Vec& x, Vec& g,
                                bool gradient_is_current, qp::Budget& budget, const StopTest& stop,
                                const Monitor& monitor, double* inexact_gradient) {
  const LinearOperator& A = problem.hessian;
  const Vec& b = problem.b;
  const qp::ConstraintSet& set = problem.constraints;
  const double a_norm = problem.hessian_norm;
  const LinearOperator& preconditioner = problem.preconditioner;
  MprgpResult result;
  const Eigen::Index n = b.size();
  if (x.size() != n || set.size() != n)
    throw std::invalid_argument("MPRGP: x, b and the bounds differ in size");
  if (!(a_norm > 0)) throw std::invalid_argument("MPRGP: the norm estimate of A must be > 0");
  if (problem.range_projector) throw std::invalid_argument("MPRGP: the problem has an equality part (SMALBE's)");
  const double abar = settings.step_factor / a_norm;
  IterationCounts& counts = result.counts;
  const int max_hessian = budget.remaining();  // this solve's share
  const BudgetCharge charge(budget, counts);

  auto multiply = [&](const Vec& v, Vec& Av) { A(v, Av); ++counts.hessian; };
  Vec phi(n), beta(n), p(n), Ap(n), z(n), step_Ap(n), phit_work(n), trial, trial_gradient, A_trial;
  // z = M phi restricted to the face (z = phi without a preconditioner), divided on disc
  // pairs on their circle by 1 + the circle's curvature / ||A|| (without that a pair of small
  // radius and large -n'g, a row slipping fast under a small bound, sets every CG step: the
  // 3D forced slide did not converge in 10000 multiplications).
  const auto precondition_in_face = [&]() -> const Vec& {
    if (preconditioner) {
      preconditioner(phi, z);
      ++counts.preconditioner;
    } else {
      z = phi;
    }
    set.restrict_to_face(x, g, a_norm, z);
    set.precondition_curvature(x, g, a_norm, z);
    return z;
  };

  // Bound on the part of g that sliding CG steps left out (cg_step); 0 on flat faces.
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
    set.project(x);
    g.resize(n);
    multiply(x, Ap);
    g = Ap - b;  // g = A x - b
  }
  set.free_gradient(x, g, a_norm, phi);
  p = precondition_in_face();

  // True while the direction descends from one carried across a face change (expansion
  // projected_cg): such a direction is not a Krylov direction of the current face, so a step
  // along it must decrease f at least as much as the fixed step abar along the reduced free
  // gradient is guaranteed to; a step that does not restarts CG from the free gradient.
  bool continued = false;
  for (int iteration = 0;; ++iteration) {
    // Split the gradient gP = phi + beta: the chopped gradient beta (at a bound, the part
    // pointing into the set; on a circle gP couples the pair), and the reduced free
    // gradient's products. The sums run component by component.
    set.projected_gradient(x, g, beta);
    beta -= phi;
    double beta_sq = 0, gp_sq = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
      beta_sq += beta[i] * beta[i];
      gp_sq += phi[i] * phi[i] + beta[i] * beta[i];
    }
    const qp::ReducedFreeGradient reduced = set.reduced_free_gradient(x, phi, abar, phit_work);
    const double phit_phi = reduced.dot_phi, phit_sq = reduced.squared_norm;
    result.gradient_norm = std::sqrt(gp_sq);
    if (gradient_error > kSlideGradientError * result.gradient_norm) {  // g carried in, or gP fell since
      recompute_gradient();  // no stop decision on a g off by more
      set.free_gradient(x, g, a_norm, phi);
      p = precondition_in_face();
      continued = false;
      --iteration;
      continue;
    }
    if (monitor) monitor({"mprgp", iteration, result.gradient_norm, 0.0, counts.hessian, set.off_bound_count(x)});
    if (stop(x, g, result.gradient_norm)) {
      result.status = SolveStatus::converged;
      exact_gradient();
      return result;
    }
    if (counts.hessian >= max_hessian) {
      result.status = SolveStatus::max_iterations;
      exact_gradient();
      return result;
    }
    if (iteration == 0 && settings.settle_rounds > 0) {  // a start that passes the test is kept as is
      settle_start(A, b, set, settings.settle_rounds, max_hessian, x, g, counts, preconditioner, monitor);
      set.free_gradient(x, g, a_norm, phi);
      p = precondition_in_face();
      continue;
    }

    if (beta_sq <= settings.gamma * settings.gamma * phit_phi) {
      // x is proportional: conjugate gradient step, or expansion if it would leave the set.
      // Not conjugate_gradient(): each step chooses among CG, expansion and proportioning on a
      // face that changes, and conjugacy is kept only within a face.
      multiply(p, Ap);
      // The step and the conjugacy use A plus the curvature of the set's curved faces (the
      // Hessian round a disc's circle, qp::DiscSet::add_curvature); Ap alone updates g.
      step_Ap = Ap;
      set.add_curvature(x, g, p, step_Ap);
      const double pAp = p.dot(step_Ap);
      if (!(pAp > 0)) {
        result.status = SolveStatus::not_positive_definite;
        exact_gradient();
        return result;
      }
      const double g_p = g.dot(p);
      const double a_cg = g_p / pAp;
      const double a_f = set.feasible_step(x, p, true);
      if (a_cg <= a_f) {
        // Exact line search decreases f by (g'p)^2 / (2 p'Ap); the fixed step's guarantee:
        const bool guaranteed = 0.5 * a_cg * g_p >= abar * phit_phi - 0.5 * a_norm * abar * abar * phit_sq;
        bool restart = continued && !guaranteed;
        restart = cg_step(problem, abar, a_cg, p, Ap, x, g, phi, gradient_error, counts) || restart;
        set.free_gradient(x, g, a_norm, phi);
        const Vec& direction = precondition_in_face();
        if (restart) {
          p = direction;
          continued = false;
        } else {
          p = direction - (direction.dot(step_Ap) / pAp) * p;  // A-conjugate to the previous direction
          set.restrict_to_face(x, g, a_norm, p);  // round the circles the face has turned: p on its new tangents
          if (!(p.dot(g) > 0)) p = direction;
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
          set.project(trial);
          x -= a_f * p;
          g -= a_f * Ap;
          // Pairs sliding on their circle went a little out (second order in a_f): back onto
          // it, g there inexact by A times that, until the step below recomputes it.
          set.project_curved(x);
          set.free_gradient(x, g, a_norm, phi);
          const qp::ReducedFreeGradient at_half = set.reduced_free_gradient(x, phi, abar, phit_work);  // at x - a_f p
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
          set.project_curved(x);  // as above
          set.free_gradient(x, g, a_norm, phi);
        }
        if (!expanded) {
          fixed_projected_step(x, g, phi, set, abar);  // expansion: fixed-step projected gradient step
          multiply(x, Ap);
          g = Ap - b;
        }
        gradient_error = 0;  // g computed anew at the new x, either way
        set.free_gradient(x, g, a_norm, phi);
        const Vec& direction = precondition_in_face();
        continued = false;
        if (expanded && settings.expansion == MprgpExpansion::projected_cg) {
          // The CG recurrence goes on in the new face: a restart from the free gradient after
          // every expansion is steepest descent where the contact zone's edge moves a band per
          // step (the large contact zone: 1.7 times the multiplications, docs/algorithms.md).
          set.restrict_to_face(x, g, a_norm, p);
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
      if (set.holds_tangents(x, g, a_norm)) {
        x -= abar * (g - phi);
        set.project(x);
        multiply(x, Ap);
        g = Ap - b;
        gradient_error = 0;
        set.free_gradient(x, g, a_norm, phi);
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
      const double a_feasible = set.feasible_step(x, beta, false);
      const double a = std::min(g.dot(beta) / dAd, a_feasible);
      x -= a * beta;
      if (a == a_feasible) set.project(x);  // the bound reached exactly, not round-off past it
      g -= a * Ap;
      set.free_gradient(x, g, a_norm, phi);
      p = precondition_in_face();
      continued = false;
      ++counts.proportioning;
    }
  }
}

}  // namespace ffeti
