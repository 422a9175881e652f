// The dual solve: the path the constraints call for, its formulation's QP, the solver of
// qp/ that fits it, one stopping test for all, and the primal solution recovered.
#include "feti/dual_system.h"

#include "base/errors.h"
#include "base/stopwatch.h"
#include "qp/conjugate_gradient.h"
#include "qp/mprgp.h"

#include <algorithm>

namespace ffeti {
namespace {

/// The relative distance min ||G lambda - e|| / ||e|| over lambda_I >= 0 below which a scene
/// counts as feasible whatever tol: MPRGP on G'G resolves it only to about 1e-11 (a feasible
/// spanner gave 1.3e-11, depending on the expansion steps), so a smaller tol must not turn
/// that round-off into "infeasible"; infeasible scenes are off by far more (docs/algorithms.md).
constexpr double kFeasibilityResolution = 1e-8;

/// The inner solvers' settings, limited by the whole solve's multiplications.
MprgpSettings mprgp_within(const DualSolveSettings& settings) {
  MprgpSettings mprgp = settings.mprgp;
  mprgp.max_hessian = settings.max_hessian;
  mprgp.settle_rounds = settings.start.size() > 0 ? settings.settle : 0;  // nothing to settle from zero
  return mprgp;
}

SmalbeSettings smalbe_within(const DualSolveSettings& settings) {
  SmalbeSettings smalbe = settings.smalbe;
  smalbe.max_hessian = settings.max_hessian;
  smalbe.inner = mprgp_within(settings);  // its first inner solve settles the start
  return smalbe;
}

/// A solver's outcome into the solution, keeping the norm estimate's count.
void record(DualSolution& result, const QpResult& solved) {
  const int estimate = result.counts.hessian_norm_estimate;
  result.counts = solved.counts;
  result.counts.hessian_norm_estimate = estimate;
  result.status = solved.status;
  result.gradient_norm = solved.gradient_norm;
}

}  // namespace

const char* path_name(DualPath path) {
  switch (path) {
    case DualPath::cholesky: return "cholesky";
    case DualPath::cg: return "cg";
    case DualPath::projected_cg: return "projected_cg";
    case DualPath::mprgp: return "mprgp";
    case DualPath::smalbe: break;
  }
  return "smalbe";
}

Vec DualSystem::run(const DualQp& qp, const Bounds* bounds, const DualStop& stop, const DualSolveSettings& settings,
                    DualSolution& result) const {
  Vec mu_of_x;
  const auto multipliers = [&](const Vec& x) -> const Vec& {
    if (!qp.to_multipliers) return x;
    qp.to_multipliers(x, mu_of_x);
    return mu_of_x;
  };
  // The stopping test at the solver's iterate x with projected gradient gP (inf- and 2-norm).
  const auto converged = [&](const Vec& x, double gradient_inf, double gradient_norm) {
    const Vec& mu = multipliers(x);
    if (!qp.equality_norm) return stop(mu, gradient_inf, gradient_norm);
    result.equality_norm = qp.equality_norm(mu);
    return stop(mu, gradient_inf, gradient_norm, result.equality_norm, result.equality_reference);
  };
  Vec x = qp.start, g;
  if (!bounds) {  // equality rows only: CG
    CgSettings cg;
    cg.max_hessian = settings.max_hessian;
    const CgResult r = conjugate_gradient(
        qp.hessian, qp.b, x, g, cg,
        [&](const Vec& xi, const Vec& gi, double norm) { return converged(xi, gi.lpNorm<Eigen::Infinity>(), norm); },
        settings.monitor, qp.preconditioner);
    record(result, r);
  } else if (!qp.range_projector) {  // bounds only: MPRGP
    const MprgpResult r = mprgp(
        qp.hessian, qp.b, *bounds, qp.hessian_norm, x, g, false, mprgp_within(settings),
        [&](const Vec& xi, const Vec& gi, double norm) {
          return converged(xi, projected_gradient_max(xi, gi, *bounds), norm);
        },
        settings.monitor, qp.preconditioner);
    record(result, r);
  } else {  // bounds and an equality part: SMALBE
    SmalbeProblem problem;
    problem.hessian = qp.hessian;
    problem.range_projector = qp.range_projector;
    problem.b = &qp.b;
    problem.lower = &bounds->lower;
    problem.upper = bounds->upper;
    problem.hessian_norm = qp.hessian_norm;
    problem.preconditioner = qp.preconditioner;
    problem.multiplier = settings.equality_multiplier;
    const SmalbeResult r = smalbe(
        problem, x, smalbe_within(settings),
        [&](const Vec& xi, const Vec& gP, const Vec&) { return converged(xi, gP.lpNorm<Eigen::Infinity>(), gP.norm()); },
        settings.monitor);
    record(result, r);
  }
  Vec mu = multipliers(x);
  if (qp.equality_norm) result.equality_norm = qp.equality_norm(mu);
  return mu;
}

DualSolution DualSystem::solved_by_subdomains(const DualData& data, DualSolution result) const {
  Stopwatch clock;
  result.status = SolveStatus::converged;
  result.lambda = Vec::Zero(0);
  result.u.resize(subdomains_.size());
  for (size_t s = 0; s < subdomains_.size(); ++s) subdomains_[s]->apply_pseudo_inverse(data.loads[s], result.u[s]);
  result.times.solve = clock.seconds();
  return result;
}

DualSolution DualSystem::solve(const DualData& data, const DualSolveSettings& settings) const {
  settings.validate();
  DualSolution result = prepared(data, settings);
  const DualPath route = path();
  if (route == DualPath::cholesky) return solved_by_subdomains(data, std::move(result));
  Stopwatch solve_clock;
  const double operator_start = F_->application_seconds();
  const double preconditioner_start = preconditioner_ ? preconditioner_->application_seconds() : 0.0;
  const double check_start = check_seconds_;
  if (data.slip_bound.size() != constraints_.friction_rows)
    throw InputError("slipBound: needs one bound per friction row (" + std::to_string(constraints_.friction_rows) +
                     "), got " + std::to_string(data.slip_bound.size()));
  const Vec multiplier_lower = lower_bounds(data), multiplier_upper = upper_bounds(data);
  // Of mu = lambda - lambda~, the solvers' variable (-inf stays -inf).
  const Vec lower = multiplier_lower - data.lambda_tilde;
  const Vec upper = multiplier_upper.size() ? Vec(multiplier_upper - data.lambda_tilde) : Vec();
  const Bounds bounds{lower, upper.size() ? &upper : nullptr};
  // The primal check of the stopping test at shifted multipliers mu (lambda = mu + lambda~,
  // multipliers at a bound exactly there).
  RelativeKktStop kkt_stop(settings.tolerance, [&](const Vec& mu) {
    return primal_check(data, lambda_from_shifted(mu, bounds, data));
  });
  const auto stop_for = [&](const DualSolution& r) {  // built once the formulation has set the references
    return DualStop(settings.stopping, settings.tolerance, r.gradient_reference, kkt_stop);
  };

  Vec lambda;
  if (route == DualPath::cg || route == DualPath::projected_cg) {
    const DualQp qp = route == DualPath::cg ? plain_qp(data, settings, result, false) : projected_qp(data, settings);
    lambda = run(qp, nullptr, stop_for(result), settings, result) + data.lambda_tilde;
  } else if (route == DualPath::mprgp) {
    const DualQp qp = plain_qp(data, settings, result, true);
    lambda = lambda_from_shifted(run(qp, &bounds, stop_for(result), settings, result), bounds, data);
  } else if (const double resolution = std::max(settings.tolerance, kFeasibilityResolution),
             distance = coarse_->feasibility_residual(data.e, multiplier_lower, multiplier_upper, resolution);
             distance > resolution) {
    // No multipliers within their bounds balance the loads on the floating bodies (Farkas):
    // no equilibrium, and SMALBE could only iterate until maxit. The least-norm lambda~
    // (G lambda~ = e, some contact multipliers negative or friction forces beyond their
    // bound: a body that would slide away) gives the field the recovery shows.
    result.status = SolveStatus::infeasible;
    result.equality_norm = distance * result.equality_reference;
    lambda = data.lambda_tilde;
  } else {
    const DualQp qp = settings.coarse_constraints == CoarseConstraints::free_rows
                          ? free_rows_qp(data, settings, result)
                          : penalty_qp(data, settings, result);
    lambda = lambda_from_shifted(run(qp, &bounds, stop_for(result), settings, result), bounds, data);
  }
  result.violation = kkt_stop.measure();
  result.scale_evaluations = kkt_stop.evaluations();
  result.times.solve = solve_clock.seconds() - result.times.norm_estimate - result.times.free_rows;
  result.times.dual_operator += F_->application_seconds() - operator_start;
  if (preconditioner_) result.times.preconditioner = preconditioner_->application_seconds() - preconditioner_start;
  result.times.primal_checks = check_seconds_ - check_start;
  recover(data, std::move(lambda), result);
  return result;
}

}  // namespace ffeti
