#include "feti/friction.h"

#include "feti/primal.h"
#include "feti/coulomb_newton.h"
#include "base/stopwatch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ffeti {
namespace {

/// g = mu max(lambda_n, 0) per friction row, mu its own. Without multipliers to start from, g = +inf:
/// the first solve sticks everywhere. (g = 0, a frictionless first solve, has no solution
/// where friction alone holds a body: a block on a slope, a cylinder pushed sideways.)
Vec coulomb_bounds(const Constraints& c, const Vec& lambda) {
  Vec g = Vec::Constant(c.friction_rows, std::numeric_limits<double>::infinity());
  if (lambda.size() != c.rows()) return g;
  for (int t = 0; t < c.friction_rows; ++t) {
    const auto k = static_cast<size_t>(t);
    g[t] = c.coulomb_coefficient[k] * std::max(lambda[c.normal_row[k]], 0.0);
  }
  return g;
}

/// The last solve's multipliers as the next one's start, each friction force at its old
/// bound (a row that slips) moved onto its new bound (scaled, its direction kept). Left where
/// it was, a slipping row just inside a grown bound is free, and its whole gradient (its
/// slip) counts in the projected gradient: every warm solve began about as far from the stop
/// test, however little the bounds had moved (the 2D sheared block: 1.4e-4 at the start of
/// each). In 3D it made the disc solves dearer while MPGP moved pairs round their circles by
/// projected gradient steps alone; with CG round the circles (qp/mprgp.cpp) it makes them
/// cheaper (the 3D sheared block's step 2: 91 instead of 137 multiplications, [log](docs/log.md)).
Vec start_on_new_bounds(const Constraints& c, Vec lambda, const Vec& old_bound, const Vec& new_bound) {
  for (int t = 0; t < c.friction_rows; t += c.tangent_directions) {
    const int row = c.first_friction_row() + t;
    if (!std::isfinite(old_bound[t]) || !at_slip_bound(c, lambda, row, old_bound[t])) continue;
    const double norm = tangential_norm(c, lambda, row);
    if (norm > 0) lambda.segment(row, c.tangent_directions) *= new_bound[t] / norm;
  }
  return lambda;
}

/// The Coulomb fixed point's first Tresca solve of a load step stops at this tolerance (or
/// the user's, if looser): its bounds are a guess (g = infinity, or the last step's), and
/// solving for them to tol is wasted. Measured against 1e-3 and the user's tol on every
/// friction scene ([log](docs/log.md), 2026-11-27).
constexpr double kFirstSolveTolerance = 1e-2;
/// ... looser still where the bounds come from a start (mu lambda_n of the last load step's
/// multipliers, or of a given start): the first solve only has to move the forces towards
/// the new load's. 0.3 against 1e-2 on the friction onset's 24 pulls: 2919 multiplications
/// instead of 3605; on every second step of the friction page's scenes as many or fewer (the
/// 3D sheared block 97 -> 82 at 1e-8). From g = infinity (no earlier step) 0.3 cost more (the
/// 3D slope: 51 -> 73): 1e-2 stays there ([log](docs/log.md), 2026-12-07).
constexpr double kWarmFirstSolveTolerance = 0.3;
/// The first solve settles its start (the last load step's multipliers) in at most this many
/// face solves, not settle='s default 2: each settles the face gradient to 1e-2 of its start,
/// more than a solve that stops at kWarmFirstSolveTolerance can use (the friction onset's
/// 3D block, mesh 2, q 0.5: 9 of the first solve's 12 multiplications settling). On the 24
/// pulls 2735 multiplications against 2893 with 2 and 2964 with none; the friction page's
/// cost scenes as many or fewer ([log](docs/log.md), 2026-12-07, twenty-first session).
constexpr int kFirstSolveSettleRounds = 1;
/// Each later solve stops at max(reachable (tol, or the residual a stagnated solve reached),
/// min(the last solve's tolerance, kBoundFollowing times the last relative change of the
/// bounds)): as exact as the fixed point's progress can use.
/// 0.1 left solves that stopped at once, their bounds crawling towards the fixed point.
constexpr double kBoundFollowing = 1e-2;
/// ... but at most this factor tighter than the last solve: a solve whose start already met
/// its loose tolerance leaves the bounds as they were (change 0), which says nothing about
/// how far the fixed point at a tighter tolerance lies. Without the limit the next solve ran
/// to tol at once (the 2D block forced to slide: 9e-3 -> 1e-6, after which the bounds still
/// moved by 19 %). Measured against 0.03, 0.05, 0.2 and none ([log](docs/log.md), 2026-11-28).
constexpr double kLargestTightening = 0.1;
/// Tolerances whose relative difference is below this are one (products rounded apart).
constexpr double kToleranceRounding = 1e-12;

}  // namespace

double next_tresca_tolerance(double last, double bound_change, double reachable) {
  const double next =
      std::max({reachable, std::min(last, kBoundFollowing * bound_change), kLargestTightening * last});
  // 0.1 times 1e-5 is one ulp above 1e-6: a tolerance within rounding of the reachable one is
  // that one, or the fixed point pays one more solve at tol to find it met (1 to 100
  // multiplications in the traces: docs/log.md, 2026-12-07, twenty-fifth session).
  return next <= reachable * (1 + kToleranceRounding) ? reachable : next;
}

FrictionSolution solve_with_friction(const DualSystem& dual, DualData data, const FrictionLaw& law,
                                     DualSolveSettings settings, const Vec& start, const std::vector<int>& bodies) {
  const Constraints& c = dual.constraints();
  if (settings.start.size() == 0) settings.start = start;
  FrictionSolution out;
  Vec g = law.coulomb() ? coulomb_bounds(c, settings.start) : law.slip_bound;
  IterationCounts counts;
  PhaseTimes times;
  long applications = 0;  // of F, summed like the counts and times
  // maxit holds over the whole fixed point: each Tresca solve gets what the ones before left.
  qp::Budget budget = settings.validate();  // the call's one check, charged by every Tresca solve
  const double tol = settings.tolerance;
  if (law.coulomb()) {
    settings.tolerance = std::max(tol, std::isfinite(g.sum()) ? kWarmFirstSolveTolerance : kFirstSolveTolerance);
    settings.settle = std::min(settings.settle, kFirstSolveSettleRounds);
  }
  if (settings.feasibility_tolerance == 0) settings.feasibility_tolerance = tol;  // each solve's check at the user's
  if (law.coulomb()) {
    const double resolution = std::max(tol, kFeasibilityResolution);
    const CoulombFeasibility f = dual.coulomb_feasibility(data, bodies, resolution);
    if (f.distance > resolution) {
      // No forces within the cones balance the loads: nor do those of g = 0, within every
      // cone, whose solve says so (the Farkas check) without iterating.
      data.slip_bound = Vec::Zero(c.friction_rows);
      out.dual = dual.solve(data, settings, {}, budget);
      out.dual.status = SolveStatus::infeasible;
      out.dual.equality_norm = f.distance * out.dual.equality_reference;  // the law's distance, not g = 0's
      out.slip_bound = data.slip_bound;
      out.iterations = 1;
      out.hessian.push_back(out.dual.counts.hessian);
      out.sliding_body = f.body;
      return out;
    }
  }
  // What the fixed point can reach: tol, or the residual of a Tresca solve that stopped at
  // round-off (stagnated: tol below what the data allow). Its bounds still move: the fixed
  // point goes on to bounds within that residual, not tighter (each later solve would only
  // stagnate again), and ends stagnated with the larger of the two residuals. Stopped at the
  // first such solve, the 3D sheared block at tol 1e-13 reported 7.8e-11 while its bounds
  // still moved by 6.4e-10.
  double reachable = tol;
  const bool use_newton = law.coulomb() && (settings.coulomb == CoulombMethod::newton ||
                                            (settings.coulomb == CoulombMethod::automatic && c.tangent_directions == 1));
  bool newton_tried = false;
  DualWarmStart warm;  // SMALBE's multiplier term, carried from solve to solve with the multipliers
  Vec feasible_bound, feasible_lambda;  // of the last converged Tresca solve
  for (;;) {
    data.slip_bound = g;
    DualSolution solved = dual.solve(data, settings, warm, budget);
    if (solved.status != SolveStatus::infeasible) warm.equality_multiplier = solved.equality_multiplier;
    ++out.iterations;
    out.hessian.push_back(solved.counts.hessian);
    const int estimate = counts.hessian_norm_estimate;  // estimated once: the later solves reuse it
    counts += solved.counts;
    counts.hessian_norm_estimate = out.iterations == 1 ? solved.counts.hessian_norm_estimate : estimate;
    times += solved.times;
    applications += solved.dual_operator_applications;
    out.dual = std::move(solved);
    out.slip_bound = g;
    if (law.coulomb() && out.dual.status == SolveStatus::infeasible && out.iterations < settings.friction_iterations &&
        !budget.exhausted()) {
      // The law admits an equilibrium (checked above); these bounds, from an iterate's normal
      // forces, do not (the 3D block sheared at 0.96 mu P: its first solve's normal forces fall
      // short of Q / mu, and the fixed point converges from there). Widened to the last
      // converged solve's, they contain its multipliers: feasible, and the fixed point goes on.
      const Vec widened = feasible_bound.size() ? Vec(g.cwiseMax(feasible_bound))
                                                : Vec(Vec::Constant(g.size(), std::numeric_limits<double>::infinity()));
      if (widened != g) {
        g = widened;
        if (feasible_lambda.size()) settings.start = feasible_lambda;
        else settings.tolerance = std::max(tol, kFirstSolveTolerance);  // from g = infinity: a cold first solve
        continue;
      }
    }
    const bool stagnated = out.dual.status == SolveStatus::stagnated;
    if (!law.coulomb() || !(out.dual.status == SolveStatus::converged || stagnated)) break;
    if (stagnated) reachable = std::max(reachable, out.dual.violation);
    feasible_bound = g;
    feasible_lambda = out.dual.lambda;
    const Vec next = coulomb_bounds(c, out.dual.lambda);
    const double scale = next.size() ? next.lpNorm<Eigen::Infinity>() : 0.0;
    const double change = next.size() ? (next - g).lpNorm<Eigen::Infinity>() : 0.0;
    out.bound_change = scale > 0 ? change / scale : change;
    // Done only when a solve to tol itself gave bounds within tol of the ones it solved with.
    if (settings.tolerance <= reachable && out.bound_change <= reachable) {
      if (std::max(out.dual.violation, out.bound_change) > tol) {  // the law holds only to what round-off allowed
        out.dual.status = SolveStatus::stagnated;
        out.dual.violation = std::max(out.dual.violation, out.bound_change);
      }
      break;
    }
    if (out.iterations >= settings.friction_iterations || budget.exhausted()) {
      out.dual.status = SolveStatus::max_iterations;
      break;
    }
    if (use_newton && !newton_tried && std::isfinite(g.sum())) {
      // After the first solve with finite bounds: Newton from its multipliers; its answer,
      // where it converged, is checked by the Tresca solve at tol of the loop (its bounds
      // must come back within tol), else the fixed point goes on from this solve.
      newton_tried = true;
      Stopwatch clock;
      const DualOperator& F = dual.F();  // its running totals, charged as a Tresca solve's are
      const double operator_seconds = F.application_seconds(), solve_seconds = F.solve_seconds();
      const long operator_applications = F.applications();
      const CoulombNewtonResult newton = coulomb_newton(dual, data, out.dual.lambda, tol, budget);
      counts.hessian += newton.hessian;
      counts.preconditioner += newton.preconditioner;
      times.solve += clock.seconds();
      times.dual_operator += F.application_seconds() - operator_seconds;
      times.factor_solves += F.solve_seconds() - solve_seconds;
      applications += F.applications() - operator_applications;
      out.newton_steps = newton.steps;
      out.newton_hessian = newton.hessian;
      if (newton.converged) {
        settings.tolerance = reachable;
        settings.start = newton.lambda;
        g = coulomb_bounds(c, newton.lambda);
        settings.settle = 0;
        continue;
      }
    }
    settings.tolerance = next_tresca_tolerance(settings.tolerance, out.bound_change, reachable);
    settings.start = start_on_new_bounds(c, out.dual.lambda, g, next);  // from the last one's multipliers
    g = next;
    // ... not settled: settling it on its contact set (settle=, tuned for a start from another
    // problem) costs about a frictionless solve each time (11 of 11 multiplications per late
    // solve of a block forced to slide) and moves it little.
    settings.settle = 0;
  }
  out.dual.counts = counts;
  out.dual.times = times;
  out.dual.dual_operator_applications = applications;
  return out;
}

ContactRowForces contact_row_forces(const Constraints& c, const Vec& lambda, const Vec& slip_bound, const Vec& slip) {
  ContactRowForces forces;
  const auto rows = static_cast<size_t>(c.contact_rows());
  for (auto* v : {&forces.tangential, &forces.second_tangential, &forces.slip, &forces.second_slip}) v->assign(rows, 0.0);
  forces.state.assign(rows, ContactState::open);
  if (lambda.size() != c.rows()) return forces;
  for (int i = 0; i < c.contact_rows(); ++i)
    if (lambda[c.equality_rows + i] > 0) forces.state[static_cast<size_t>(i)] = ContactState::stick;
  const bool slipped = slip.size() == c.friction_rows;
  for (int t = 0; t < c.friction_rows; t += c.tangent_directions) {
    const auto i = static_cast<size_t>(c.normal_row[static_cast<size_t>(t)] - c.equality_rows);
    const int row = c.first_friction_row() + t;
    forces.tangential[i] = lambda[row];
    if (slipped) forces.slip[i] = slip[t];
    if (c.tangent_directions == 2) {
      forces.second_tangential[i] = lambda[row + 1];
      if (slipped) forces.second_slip[i] = slip[t + 1];
    }
    if (tangential_norm(c, lambda, row) > 0) forces.state[i] = ContactState::stick;  // Tresca: closed or not
    if (forces.state[i] == ContactState::stick && at_slip_bound(c, lambda, row, slip_bound[t])) forces.state[i] = ContactState::slip;
  }
  return forces;
}

}  // namespace ffeti
