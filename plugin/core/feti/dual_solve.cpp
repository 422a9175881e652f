// The dual solve: the path the constraints call for, its formulation's QP, the solver of
// qp/ that fits it, one stopping test for all, and the primal solution recovered; for one
// right-hand side or several (sharing each application of F on the CG paths).
#include "feti/dual_system.h"

#include "base/errors.h"
#include "base/stopwatch.h"
#include "qp/conjugate_gradient.h"
#include "qp/mprgp.h"
#include "qp/smalbe.h"

#include <algorithm>
#include <stdexcept>

namespace ffeti {
namespace {

/// MPRGP's settings on this solve: the start, if given, is settled first.
MprgpSettings mprgp_for(const DualSolveSettings& settings) {
  MprgpSettings mprgp = settings.mprgp;
  mprgp.settle_rounds = settings.start.size() > 0 ? settings.settle : 0;  // nothing to settle from zero
  return mprgp;
}

SmalbeSettings smalbe_for(const DualSolveSettings& settings) {
  SmalbeSettings smalbe = settings.smalbe;
  smalbe.inner = mprgp_for(settings);  // its first inner solve settles the start
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

Vec DualSystem::run(Formulation formulation, const DualStop& stop, const DualSolveSettings& settings,
                    const DualWarmStart& warm, qp::Budget& budget, DualSolution& result) const {
  // The solver's Hessian multiplications timed as a whole: F with its projections around it.
  formulation.qp.hessian = [hessian = std::move(formulation.qp.hessian), &result](const Vec& x, Vec& y) {
    const Stopwatch clock;
    hessian(x, y);
    result.times.hessian += clock.seconds();
  };
  const qp::Problem& qp = formulation.qp;
  Vec mu_of_x;
  const auto multipliers = [&](const Vec& x) -> const Vec& {
    if (!formulation.to_multipliers) return x;
    formulation.to_multipliers(x, mu_of_x);
    return mu_of_x;
  };
  // The stopping test at the solver's iterate x with projected gradient gP (inf- and 2-norm);
  // x's multipliers formed only for a primal check.
  const auto converged = [&](const Vec& x, double gradient_inf, double gradient_norm) {
    const RelativeKktStop::Multipliers mu = [&]() -> const Vec& { return multipliers(x); };
    if (!formulation.equality_norm) return stop(x, mu, gradient_inf, gradient_norm);
    result.equality_norm = formulation.iterate_equality_norm ? formulation.iterate_equality_norm(x)
                                                             : formulation.equality_norm(mu());
    return stop(x, mu, gradient_inf, gradient_norm, result.equality_norm, result.equality_reference);
  };
  Vec& x = formulation.start;
  switch (formulation.solver) {
    case QpSolver::cg:
      record(result, conjugate_gradient(
                         qp, CgSettings{}, x, budget,
                         [&](const Vec& xi, const Vec& gi, double norm) {
                           return converged(xi, gi.lpNorm<Eigen::Infinity>(), norm);
                         },
                         settings.monitor));
      break;
    case QpSolver::smalbe: {
      qp::Problem warm_started = std::move(formulation.qp);
      warm_started.equality_multiplier = warm.equality_multiplier;
      SmalbeResult r = smalbe(
          warm_started, smalbe_for(settings), x, budget,
          [&](const Vec& xi, const Vec& gP, double norm) { return converged(xi, gP.lpNorm<Eigen::Infinity>(), norm); },
          settings.monitor);
      result.equality_multiplier = std::move(r.multiplier);
      record(result, r);
      break;
    }
    case QpSolver::mprgp:
      record(result, mprgp(
                         qp, mprgp_for(settings), x, budget,
                         [&](const Vec& xi, const Vec& gi, double norm) {
                           return converged(xi, qp.constraints.projected_gradient_max(xi, gi), norm);
                         },
                         settings.monitor));
      break;
  }
  Vec mu = multipliers(x);
  if (formulation.equality_norm) result.equality_norm = formulation.equality_norm(mu);
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

DualSolution DualSystem::solve(const DualData& data, const DualSolveSettings& settings,
                               const DualWarmStart& warm) const {
  qp::Budget budget = settings.validate();
  return solve(data, settings, warm, budget);
}

DualSolution DualSystem::solve(const DualData& data, const DualSolveSettings& settings, const DualWarmStart& warm,
                               qp::Budget& budget) const {
  DualSolution result = prepared(data, settings);
  const DualPath route = path();
  if (route == DualPath::cholesky) return solved_by_subdomains(data, std::move(result));
  Stopwatch solve_clock;
  const OperatorUse operator_start = operator_use();
  const double preconditioner_start = preconditioner_ ? preconditioner_->application_seconds() : 0.0;
  const double check_start = check_seconds_;
  if (data.slip_bound.size() != constraints_.friction_rows)
    throw InputError("slipBound: needs one bound per friction row (" + std::to_string(constraints_.friction_rows) +
                     "), got " + std::to_string(data.slip_bound.size()));
  const qp::ConstraintSet multiplier_bounds = multiplier_constraints(data);
  const qp::ConstraintSet bounds = multiplier_bounds.shifted(data.lambda_tilde);  // of mu = lambda - lambda~
  // The primal check of the stopping test at shifted multipliers mu (lambda = mu + lambda~,
  // multipliers at a bound exactly there). Its last u is kept: the solve usually ends at the
  // multipliers it accepted, whose recovery would repeat it (a K^+ solve per subdomain and the
  // normal equations of the rigid modes: 0.9 s at 1024 3D boxes).
  Vec checked_lambda;
  std::vector<Vec> checked_u;
  RelativeKktStop kkt_stop(settings.tolerance, [&](const Vec& mu) {
    checked_lambda = lambda_from_shifted(mu, bounds, data);
    return primal_check(data, checked_lambda, &checked_u);
  });
  const auto stop_for = [&](const DualSolution& r) {  // built once the formulation has set the references
    return DualStop(settings.stopping, settings.tolerance, r.gradient_reference, kkt_stop);
  };

  Vec lambda;
  if (route == DualPath::cg || route == DualPath::projected_cg) {
    Formulation qp = route == DualPath::cg ? plain_qp(data, settings, result, nullptr) : projected_qp(data, settings);
    lambda = run(std::move(qp), stop_for(result), settings, warm, budget, result) + data.lambda_tilde;
  } else if (route == DualPath::mprgp) {
    Formulation qp = conjugate_ ? conjugate_qp(data, settings, result, bounds) : plain_qp(data, settings, result, &bounds);
    lambda = lambda_from_shifted(run(std::move(qp), stop_for(result), settings, warm, budget, result), bounds, data);
  } else if (const double resolution = std::max(settings.feasibility_tolerance > 0 ? settings.feasibility_tolerance
                                                                                : settings.tolerance,
                                                kFeasibilityResolution),
             distance = coarse_->feasibility_residual(data.e, multiplier_bounds, resolution);
             distance > resolution) {
    // No multipliers within their bounds balance the loads on the floating bodies (Farkas):
    // no equilibrium, and SMALBE could only iterate until maxit. The least-norm lambda~
    // (G lambda~ = e, some contact multipliers negative or friction forces beyond their
    // bound: a body that would slide away) gives the field the recovery shows.
    result.status = SolveStatus::infeasible;
    result.equality_norm = distance * result.equality_reference;
    lambda = data.lambda_tilde;
  } else {
    Formulation qp = settings.coarse_constraints == CoarseConstraints::free_rows
                         ? free_rows_qp(data, settings, result, bounds)
                         : penalty_qp(data, settings, result, bounds);
    lambda = lambda_from_shifted(run(std::move(qp), stop_for(result), settings, warm, budget, result), bounds, data);
  }
  // Stopped at round-off: not converged to tol, and not a solve cut short by maxit either.
  if (kkt_stop.stagnated() && result.status == SolveStatus::converged) result.status = SolveStatus::stagnated;
  result.violation = kkt_stop.measure();
  result.scale_evaluations = kkt_stop.evaluations();
  result.times.solve = solve_clock.seconds() - result.times.norm_estimate - result.times.free_rows;
  charge_operator_use(operator_start, 1, 1, result);
  if (preconditioner_) result.times.preconditioner = preconditioner_->application_seconds() - preconditioner_start;
  result.times.primal_checks = check_seconds_ - check_start;
  if (checked_lambda.size() == lambda.size() && checked_lambda == lambda) {
    result.u = std::move(checked_u);  // the same function of the same lambda: bit for bit
    result.lambda = std::move(lambda);
    result.times.recovery = 0;
  } else {
    recover(data, std::move(lambda), result);
  }
  return result;
}

std::vector<DualSolution> DualSystem::solve(const std::vector<DualData>& data,
                                            const DualSolveSettings& settings) const {
  std::vector<DualSolution> results;
  // Lockstep runs share the seed's test (a reference per run known in advance); the
  // relative_kkt test needs u of each run, so those solve one after the other.
  if (data.size() < 2 || settings.stopping != StoppingTest::seed ||
      (path() != DualPath::cg && path() != DualPath::projected_cg)) {
    for (const DualData& d : data) results.push_back(solve(d, settings));
    return results;
  }
  const qp::Budget budget = settings.validate();
  std::vector<Vec> b, mu(data.size(), Vec::Zero(rows()));
  std::vector<StopTest> stop;
  for (const DualData& d : data) {
    results.push_back(prepared(d, settings));
    b.push_back(d.b);
    const double b_tol = settings.tolerance * results.back().gradient_reference;
    stop.push_back([b_tol](const Vec&, const Vec&, double norm) { return norm <= b_tol; });
  }
  Stopwatch solve_clock;
  const OperatorUse operator_start = operator_use();
  const double preconditioner_start = preconditioner_ ? preconditioner_->application_seconds() : 0.0;
  double hessian_seconds = 0;
  const std::vector<CgResult> cg_results = conjugate_gradient_block(
      [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) {
        const Stopwatch hessian_clock;
        if (coarse_) apply_PFP(x, y);
        else F_->apply(x, y);
        hessian_seconds += hessian_clock.seconds();
      },
      b, mu, CgSettings{}, budget, stop,
      coarse_ ? projected_preconditioner() : preconditioner_operator());
  const double seconds = solve_clock.seconds() / static_cast<double>(data.size());
  const int runs = static_cast<int>(data.size());
  for (size_t j = 0; j < data.size(); ++j) {
    charge_operator_use(operator_start, 1, runs, results[j]);
    results[j].times.hessian = hessian_seconds / runs;
    if (preconditioner_)
      results[j].times.preconditioner =
          (preconditioner_->application_seconds() - preconditioner_start) / static_cast<double>(data.size());
    results[j].status = cg_results[j].status;
    results[j].counts = cg_results[j].counts;
    results[j].gradient_norm = cg_results[j].gradient_norm;
    results[j].times.solve = seconds;
    recover(data[j], mu[j] + data[j].lambda_tilde, results[j]);
  }
  return results;
}

}  // namespace ffeti
