#include "feti/friction.h"

#include "feti/primal.h"

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
    g[t] = c.friction_coefficient[k] * std::max(lambda[c.normal_row[k]], 0.0);
  }
  return g;
}

}  // namespace

FrictionSolution solve_with_friction(const DualSystem& dual, DualData data, const FrictionLaw& law,
                                     DualSolveSettings settings, const Vec& start) {
  const Constraints& c = dual.constraints();
  if (settings.start.size() == 0) settings.start = start;
  FrictionSolution out;
  Vec g = law.coulomb() ? coulomb_bounds(c, settings.start) : law.slip_bound;
  IterationCounts counts;
  PhaseTimes times;
  // maxit holds over the whole fixed point: each Tresca solve gets what the ones before left.
  settings.validate();
  const qp::Budget budget(settings.max_hessian);
  DualWarmStart warm;  // SMALBE's multiplier term, carried from solve to solve with the multipliers
  for (;;) {
    data.slip_bound = g;
    settings.max_hessian = budget.remaining(counts.hessian);
    DualSolution solved = dual.solve(data, settings, warm);
    warm.equality_multiplier = solved.equality_multiplier;
    ++out.iterations;
    out.hessian.push_back(solved.counts.hessian);
    const int estimate = counts.hessian_norm_estimate;  // estimated once: the later solves reuse it
    counts += solved.counts;
    counts.hessian_norm_estimate = out.iterations == 1 ? solved.counts.hessian_norm_estimate : estimate;
    times += solved.times;
    out.dual = std::move(solved);
    out.slip_bound = g;
    if (!law.coulomb() || out.dual.status != SolveStatus::converged) break;
    const Vec next = coulomb_bounds(c, out.dual.lambda);
    const double scale = next.size() ? next.lpNorm<Eigen::Infinity>() : 0.0;
    const double change = next.size() ? (next - g).lpNorm<Eigen::Infinity>() : 0.0;
    out.bound_change = scale > 0 ? change / scale : change;
    if (out.bound_change <= settings.tolerance) break;
    if (out.iterations >= settings.friction_iterations || budget.remaining(counts.hessian) == 0) {
      out.dual.status = SolveStatus::max_iterations;
      break;
    }
    g = next;
    settings.start = out.dual.lambda;  // each Tresca solve starts from the last one's multipliers
  }
  out.dual.counts = counts;
  out.dual.times = times;
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
