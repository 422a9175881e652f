#include "feti/dual_system.h"

#include "base/errors.h"
#include "feti/primal.h"
#include "base/stopwatch.h"
#include "qp/conjugate_gradient.h"
#include "qp/norm_estimate.h"

#include <algorithm>
#include <cmath>

namespace ffeti {
namespace {

/// The relative distance min ||G lambda - e|| / ||e|| over lambda_I >= 0 below which a scene
/// counts as feasible whatever tol: MPRGP on G'G resolves it only to about 1e-11 (a feasible
/// spanner gave 1.3e-11, depending on the expansion steps), so a smaller tol must not turn
/// that round-off into "infeasible"; infeasible scenes are off by far more (docs/algorithms.md).
constexpr double kFeasibilityResolution = 1e-8;

/// Multipliers exactly at their bound are exactly zero in lambda (not round-off).
Vec lambda_from_shifted(const Vec& mu, const Vec& lower, const Vec& lambda_tilde) {
  Vec lambda = mu + lambda_tilde;
  for (Eigen::Index i = 0; i < mu.size(); ++i)
    if (lower[i] != kUnbounded && mu[i] <= lower[i]) lambda[i] = 0.0;
  return lambda;
}

/// ||gP||_inf without forming gP: the stopping tests call this every iteration.
double projected_gradient_max(const Vec& x, const Vec& g, const Vec& lower) {
  double largest = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const bool at_bound = lower[i] != kUnbounded && x[i] <= lower[i];
    largest = std::max(largest, std::abs(at_bound ? std::min(g[i], 0.0) : g[i]));
  }
  return largest;
}

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
void record(DualSolution& result, const IterationCounts& counts, SolveStatus status, double gradient_norm) {
  const int estimate = result.counts.hessian_norm_estimate;
  result.counts = counts;
  result.counts.hessian_norm_estimate = estimate;
  result.status = status;
  result.gradient_norm = gradient_norm;
}

/// The solvers' first iterate mu = lambda - lambda~ from settings.start (zero without one).
Vec shifted_start(const DualSolveSettings& settings, const DualData& data, Eigen::Index rows) {
  if (settings.start.size() == 0) return Vec::Zero(rows);
  if (settings.start.size() != rows)
    throw InputError("start: has " + std::to_string(settings.start.size()) + " values, the problem has " +
                     std::to_string(rows) + " multipliers (fetiInfo(P, \"dual\"))");
  return settings.start - data.lambda_tilde;
}

}  // namespace

void DualSolveSettings::validate() const {
  if (!(tolerance > 0 && tolerance < 1)) throw InputError("tol: must lie in (0, 1)");
  if (max_hessian < 1) throw InputError("maxit: must be >= 1");
  const std::pair<const char*, double> positive[] = {
      {"rho", smalbe.rho_factor}, {"M", smalbe.M_factor}, {"eta", smalbe.eta_factor}, {"gamma", mprgp.gamma}};
  for (const auto& [name, value] : positive)
    if (!(value > 0)) throw InputError(std::string(name) + ": must be > 0");
  if (!start.allFinite()) throw InputError("start: has entries that are not finite numbers");
  if (settle < 0) throw InputError("settle: must be >= 0");
  try {
    smalbe.validate();
    mprgp.validate();
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
}

DualSystem::DualSystem(const SubdomainList& subdomains, const std::vector<int>& global_ids,
                       const std::vector<int>& owner, const std::vector<int>& bodies, Constraints constraints,
                       int threads, const Communicator& comm)
    : subdomains_(subdomains), comm_(comm), constraints_(std::move(constraints)) {
  std::vector<Eigen::Index> sizes;
  for (const auto& s : subdomains) sizes.push_back(s->size());
  local_ = split_by_subdomain(constraints_, sizes, global_ids);
  sum_ = std::make_unique<SubdomainSum>(rows_by_subdomain(constraints_, static_cast<int>(owner.size())), owner,
                                        constraints_.rows(), comm);
  F_ = std::make_unique<DualOperator>(subdomains_, local_, *sum_, constraints_.rows(), threads);
  int local_floating = 0;
  for (const auto& s : subdomains_) local_floating += s->floating() ? 1 : 0;
  if (comm.sum(local_floating) > 0)
    coarse_ = std::make_unique<CoarseSpace>(subdomains_, local_, global_ids, constraints_.rows(), bodies, comm);
}

void DualSystem::use_preconditioner(DualPreconditioner kind, const std::vector<const SparseMatrix*>& operator_matrices,
                                    int threads) {
  preconditioner_kind_ = kind;
  if (kind == DualPreconditioner::none) {
    preconditioner_.reset();
    return;
  }
  preconditioner_ = std::make_unique<DirichletPreconditioner>(operator_matrices, local_, constraints_, *sum_, threads,
                                                              kind == DualPreconditioner::lumped);
}

LinearOperator DualSystem::preconditioner_operator() const {
  if (!preconditioner_) return {};
  return [this](const Vec& x, Vec& y) { preconditioner_->apply(x, y); };
}

std::string DualSystem::path() const {
  const bool inequalities = constraints_.inequality_rows() > 0;
  const bool floating = coarse_ != nullptr;
  if (constraints_.rows() == 0) return "cholesky";
  if (!inequalities) return floating ? "projected_cg" : "cg";
  return floating ? "smalbe" : "mprgp";
}

DualData DualSystem::data(std::vector<Vec> loads, const Vec& c) const {
  DualData data;
  data.loads = std::move(loads);
  data.c = c;
  const int m = constraints_.rows();
  Vec d;
  F_->apply_B_pseudo_inverse(data.loads, d);
  data.data_norm = d.norm();
  d -= c;  // d = B K^+ f - c
  if (coarse_) {
    data.e = coarse_->kernel_load(data.loads);              // e = R'f
    data.lambda_tilde = coarse_->least_norm_solution(data.e);  // G lambda~ = e
    Vec F_lambda_tilde(m);
    F_->apply(data.lambda_tilde, F_lambda_tilde);
    coarse_->project(d - F_lambda_tilde, data.b);          // b = P(d - F lambda~)
  } else {
    data.e.resize(0);
    data.lambda_tilde = Vec::Zero(m);
    data.b = d;
  }
  return data;
}

double DualSystem::operator_norm(bool projected, const NormEstimateSettings& settings, DualSolution& result) const {
  std::optional<double>& cached = projected ? norm_PFP_ : norm_F_;
  int& cost = projected ? norm_PFP_cost_ : norm_F_cost_;
  if (!cached) {
    Stopwatch clock;
    const double operator_start = F_->application_seconds();
    NormEstimate estimate;
    if (projected) {
      estimate = estimate_norm([&](const Vec& x, Vec& y) { apply_PFP(x, y); }, rows(), settings,
                               [&](Vec& v) { coarse_->project(Vec(v), v); });
    } else {
      estimate = estimate_norm([&](const Vec& x, Vec& y) { F_->apply(x, y); }, rows(), settings);
    }
    cached = estimate.norm;
    cost = estimate.multiplications;
    result.norm_estimate_seconds = clock.seconds();
    result.operator_seconds -= F_->application_seconds() - operator_start;  // the estimate's, not the solve's
  }
  result.counts.hessian_norm_estimate += cost;
  return *cached;
}

void DualSystem::apply_PFP(const Vec& x, Vec& y) const {
  coarse_->project(x, projected_);
  F_->apply(projected_, applied_);
  coarse_->project(applied_, y);  // y = P F P x
}

void DualSystem::apply_PFP(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  block_projected_.resize(x.rows(), x.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    coarse_->project(x.col(j), projected_);
    block_projected_.col(j) = projected_;
  }
  F_->apply(block_projected_, block_applied_);
  y.resize(x.rows(), x.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    coarse_->project(block_applied_.col(j), projected_);
    y.col(j) = projected_;
  }
}

DualSolution DualSystem::prepared(const DualData& data, const DualSolveSettings& settings) const {
  DualSolution result;
  result.path = path();
  result.gradient_reference = std::max(data.b.norm(), settings.reference_includes_data ? data.data_norm : 0.0);
  if (!(result.gradient_reference > 0)) result.gradient_reference = 1.0;
  result.equality_reference = data.e.norm() > 0 ? data.e.norm() : 0.0;
  return result;
}

PrimalCheck DualSystem::primal_check(const DualData& data, const Vec& lambda) const {
  Stopwatch clock;
  const std::vector<Vec> u = recover_primal(*F_, coarse_.get(), constraints_, data.loads, data.c, lambda);
  PrimalCheck check;
  for (const Vec& us : u)
    if (us.size()) check.displacement = std::max(check.displacement, us.lpNorm<Eigen::Infinity>());
  check.displacement = comm_.max(check.displacement);
  Vec Bu;
  F_->apply_B(u, Bu);
  // Feasibility, and complementarity: a contact row with a positive multiplier must hold
  // with equality (both relative as kkt_residuals has them).
  double violation = 0, complementarity = 0;
  const double lambda_scale = lambda.size() ? lambda.lpNorm<Eigen::Infinity>() : 0.0;
  for (int i = 0; i < rows(); ++i) {
    const double r = Bu[i] - data.c[i];
    violation = std::max(violation, i < constraints_.equality_rows ? std::abs(r) : r);
    if (i >= constraints_.equality_rows && lambda_scale > 0)
      complementarity = std::max(complementarity, std::abs(lambda[i] * r) / lambda_scale);
  }
  violation = std::max(violation, complementarity);
  check.violation = check.displacement > 0 ? violation / check.displacement
                                           : (violation > 0 ? std::numeric_limits<double>::infinity() : 0.0);
  if (coarse_ && !coarse_->empty()) {
    double load_squares = 0;
    for (const Vec& f : data.loads) load_squares += f.squaredNorm();
    const double scale = std::sqrt(std::max(comm_.sum(load_squares), comm_.sum(F_->local_transpose_squared_norm(lambda))));
    const double residual = coarse_->equilibrium_residual_norm(coarse_->G() * lambda - data.e);
    check.equilibrium = scale > 0 ? residual / scale : residual;
  }
  check_seconds_ += clock.seconds();
  return check;
}

void DualSystem::recover(const DualData& data, Vec lambda, DualSolution& result) const {
  Stopwatch recovery_clock;
  result.u = recover_primal(*F_, coarse_.get(), constraints_, data.loads, data.c, lambda);
  result.lambda = std::move(lambda);
  result.recovery_seconds = recovery_clock.seconds();
}

std::vector<DualSolution> DualSystem::solve(const std::vector<DualData>& data,
                                            const DualSolveSettings& settings) const {
  std::vector<DualSolution> results;
  // Lockstep runs share the seed's test (a reference per run known in advance); the
  // relative_kkt test needs u of each run, so those solve one after the other.
  if (data.size() < 2 || settings.stopping != StoppingTest::seed || (path() != "cg" && path() != "projected_cg")) {
    for (const DualData& d : data) results.push_back(solve(d, settings));
    return results;
  }
  settings.validate();
  std::vector<Vec> b, mu(data.size(), Vec::Zero(rows())), g;
  std::vector<StopTest> stop;
  for (const DualData& d : data) {
    results.push_back(prepared(d, settings));
    b.push_back(d.b);
    const double b_tol = settings.tolerance * results.back().gradient_reference;
    stop.push_back([b_tol](const Vec&, const Vec&, double norm) { return norm <= b_tol; });
  }
  CgSettings cg;
  cg.max_hessian = settings.max_hessian;
  Stopwatch solve_clock;
  const double operator_start = F_->application_seconds();
  const std::vector<CgResult> cg_results = conjugate_gradient_block(
      [&](const Eigen::MatrixXd& x, Eigen::MatrixXd& y) {
        if (coarse_) apply_PFP(x, y);
        else F_->apply(x, y);
      },
      b, mu, g, cg, stop);
  const double seconds = solve_clock.seconds() / static_cast<double>(data.size());
  const double operator_seconds = (F_->application_seconds() - operator_start) / static_cast<double>(data.size());
  for (size_t j = 0; j < data.size(); ++j) {
    results[j].operator_seconds = operator_seconds;
    results[j].status = cg_results[j].status;
    results[j].counts = cg_results[j].counts;
    results[j].gradient_norm = cg_results[j].gradient_norm;
    results[j].solve_seconds = seconds;
    recover(data[j], mu[j] + data[j].lambda_tilde, results[j]);
  }
  return results;
}

const FreeRowProjector& DualSystem::free_rows() const {
  if (!free_rows_) free_rows_ = std::make_unique<FreeRowProjector>(coarse_->G(), constraints_.equality_rows);
  return *free_rows_;
}

void DualSystem::solve_by_free_rows(const DualData& data, const DualSolveSettings& settings, const Vec& lower_bounds,
                                    RelativeKktStop& kkt_stop, DualSolution& result, Vec& lambda) const {
  // mu = T nu: every iterate meets G mu = 0 but for the rows of C (docs/algorithms.md).
  Stopwatch projector_clock;
  const FreeRowProjector& T = free_rows();  // built at the first solve: its time is reported apart
  result.projector_seconds = projector_clock.seconds();
  const int m = rows();
  Vec Tx(m), PFPTx(m), kernel_free(m);
  const LinearOperator reduced = [&](const Vec& x, Vec& y) {  // T' P F P T
    T.apply(x, Tx);
    apply_PFP(Tx, PFPTx);
    T.apply_transpose(PFPTx, y);
  };
  // T'PFPT vanishes on Ker T (free multipliers only, orthogonal to b, to the bounds and to
  // C), which the iterates never enter in exact arithmetic; in floating point they drift
  // into it unseen, and T x then cancels large components: at tol = 1e-12 the model problem
  // at n = 512 diverged (KKT 2e-3 after 10,000 multiplications). Adding ||H|| (I - Pi) on
  // Ker T changes nothing on the problem's own subspace and keeps that drift at round-off.
  const LinearOperator hessian = [&](const Vec& x, Vec& y) {
    reduced(x, y);
    T.project_out_kernel(x, kernel_free);
    y += *norm_reduced_ * (x - kernel_free);
  };
  if (!norm_reduced_) {
    Stopwatch clock;
    const double operator_start = F_->application_seconds();
    const NormEstimate estimate = estimate_norm(reduced, m, settings.norm_estimate);
    norm_reduced_ = estimate.norm;
    norm_reduced_cost_ = estimate.multiplications;
    result.norm_estimate_seconds = clock.seconds();
    result.operator_seconds -= F_->application_seconds() - operator_start;  // the estimate's, not the solve's
  }
  result.counts.hessian_norm_estimate += norm_reduced_cost_;
  const double norm = *norm_reduced_;
  Vec b;
  T.apply_transpose(data.b, b);
  // The seed's test measures the gradient against its value at the start: here T'b.
  result.gradient_reference = std::max(b.norm(), settings.reference_includes_data ? data.data_norm : 0.0);
  if (!(result.gradient_reference > 0)) result.gradient_reference = 1.0;
  const double b_tol = settings.tolerance * result.gradient_reference;
  const double eq_reference =
      result.equality_reference > 0 ? result.equality_reference : result.gradient_reference / norm;
  result.equality_reference = eq_reference;
  Vec mu(m);
  const auto converged = [&](const Vec& x, double gp_inf, double gp_norm) {
    T.apply(x, mu);
    result.equality_norm = (coarse_->G() * mu).norm();  // G lambda - e = G mu
    if (settings.stopping == StoppingTest::relative_kkt)
      return kkt_stop(mu, gp_inf, result.equality_norm / eq_reference);
    return result.equality_norm <= settings.tolerance * eq_reference && gp_norm <= b_tol;
  };
  LinearOperator preconditioner;  // approximates (T'PFPT)^+ from M^{-1} ~ (PFP)^+
  if (preconditioner_)
    preconditioner = [&](const Vec& v, Vec& y) {
      T.project_out_kernel(v, Tx);
      coarse_->project(Tx, projected_);
      preconditioner_->apply(projected_, applied_);
      coarse_->project(applied_, Tx);
      T.project_out_kernel(Tx, y);
    };
  Vec x(m);  // without its part in Ker T, which T'PFPT does not see (free rows only: bounds kept)
  T.project_out_kernel(shifted_start(settings, data, m), x);
  if (T.remaining() == 0) {  // nothing floats as a whole: bounds only
    Vec g;
    const MprgpResult r = mprgp(hessian, b, lower_bounds, norm, x, g, false, mprgp_within(settings),
        [&](const Vec& xi, const Vec& gi, double norm_gp) {
          return converged(xi, projected_gradient_max(xi, gi, lower_bounds), norm_gp);
        },
        settings.monitor, preconditioner);
    record(result, r.counts, r.status, r.projected_gradient_norm);
  } else {
    SmalbeProblem problem;
    problem.hessian = hessian;
    problem.range_projector = [&](const Vec& v, Vec& y) { T.project_remaining_range(v, y); };
    problem.b = &b;
    problem.lower = &lower_bounds;
    problem.hessian_norm = norm;
    problem.preconditioner = preconditioner;
    const SmalbeResult r = smalbe(problem, x, smalbe_within(settings),
        [&](const Vec& xi, const Vec& gP, const Vec&) {
          return converged(xi, gP.lpNorm<Eigen::Infinity>(), gP.norm());
        },
        settings.monitor);
    record(result, r.counts, r.status, r.projected_gradient_norm);
  }
  T.apply(x, mu);
  result.equality_norm = (coarse_->G() * mu).norm();
  lambda = lambda_from_shifted(mu, lower_bounds, data.lambda_tilde);
}

DualSolution DualSystem::solve(const DualData& data, const DualSolveSettings& settings) const {
  settings.validate();
  DualSolution result = prepared(data, settings);
  const int m = rows();
  const double tolerance = settings.tolerance;
  Stopwatch solve_clock;
  const double operator_start = F_->application_seconds();
  const double preconditioner_start = preconditioner_ ? preconditioner_->application_seconds() : 0.0;
  const double check_start = check_seconds_;

  if (result.path == "cholesky") {
    result.status = SolveStatus::converged;
    result.lambda = Vec::Zero(0);
    result.u.resize(subdomains_.size());
    for (size_t s = 0; s < subdomains_.size(); ++s) subdomains_[s]->apply_pseudo_inverse(data.loads[s], result.u[s]);
    result.solve_seconds = solve_clock.seconds();
    return result;
  }

  Vec lambda;
  const Vec lower_bounds = [&] {
    Vec lower = Vec::Constant(m, kUnbounded);
    for (int i = constraints_.equality_rows; i < m; ++i) lower[i] = -data.lambda_tilde[i];  // lambda_I >= 0
    return lower;
  }();
  const double b_tol = tolerance * result.gradient_reference;
  // The gradient part of the stopping test at the solver's iterate x (lambda = x + lambda~,
  // multipliers at their bound exactly 0) with projected gradient gP of 2-norm gp_norm.
  RelativeKktStop kkt_stop(tolerance, [&](const Vec& x) {
    return primal_check(data, lambda_from_shifted(x, lower_bounds, data.lambda_tilde));
  });
  // gp_inf: ||gP||_inf, gp_norm: ||gP||_2.
  const auto gradient_converged = [&](const Vec& x, double gp_inf, double gp_norm) {
    return settings.stopping == StoppingTest::seed ? gp_norm <= b_tol : kkt_stop(x, gp_inf);
  };

  if (result.path == "cg" || result.path == "projected_cg") {
    const LinearOperator A = [&](const Vec& x, Vec& y) {
      if (coarse_) apply_PFP(x, y);
      else F_->apply(x, y);
    };
    LinearOperator M = preconditioner_operator();  // with a coarse space: P M^{-1} P on Ker G
    if (M && coarse_)
      M = [&](const Vec& x, Vec& y) {
        coarse_->project(x, projected_);
        preconditioner_->apply(projected_, applied_);
        coarse_->project(applied_, y);
      };
    CgSettings cg;
    cg.max_hessian = settings.max_hessian;
    Vec mu = shifted_start(settings, data, m), g;
    if (coarse_ && settings.start.size() > 0) coarse_->project(Vec(mu), mu);  // G mu = 0
    const CgResult cg_result = conjugate_gradient(
        A, data.b, mu, g, cg, [&](const Vec& x, const Vec& gx, double norm) {
          return gradient_converged(x, gx.lpNorm<Eigen::Infinity>(), norm);
        },
        settings.monitor, M);
    record(result, cg_result.counts, cg_result.status, cg_result.gradient_norm);
    lambda = mu + data.lambda_tilde;
  } else if (result.path == "mprgp") {
    const double norm = operator_norm(false, settings.norm_estimate, result);
    Vec x = shifted_start(settings, data, m), g;
    const LinearOperator M = preconditioner_operator();
    const MprgpResult r = mprgp(
        [&](const Vec& v, Vec& y) { F_->apply(v, y); }, data.b, lower_bounds, norm, x, g, false, mprgp_within(settings),
        [&](const Vec& xi, const Vec& gi, double norm_gp) {
          return gradient_converged(xi, projected_gradient_max(xi, gi, lower_bounds), norm_gp);
        },
        settings.monitor, M);
    record(result, r.counts, r.status, r.projected_gradient_norm);
    lambda = lambda_from_shifted(x, lower_bounds, data.lambda_tilde);
  } else if (const double resolution = std::max(tolerance, kFeasibilityResolution),
             distance = coarse_->feasibility_residual(data.e, constraints_.equality_rows, resolution);
             distance > resolution) {
    // No multipliers of the right signs balance the loads on the floating bodies (Farkas):
    // no equilibrium, and SMALBE could only iterate until maxit. The least-norm lambda~
    // (G lambda~ = e, some contact multipliers negative) gives the field the recovery shows.
    result.status = SolveStatus::infeasible;
    result.equality_norm = distance * result.equality_reference;
    lambda = data.lambda_tilde;
  } else if (settings.coarse_constraints == CoarseConstraints::free_rows) {
    solve_by_free_rows(data, settings, lower_bounds, kkt_stop, result, lambda);
  } else {  // smalbe
    const double norm = operator_norm(true, settings.norm_estimate, result);
    const double eq_reference =
        result.equality_reference > 0 ? result.equality_reference : result.gradient_reference / norm;
    result.equality_reference = eq_reference;
    SmalbeProblem problem;
    problem.hessian = [&](const Vec& x, Vec& y) { apply_PFP(x, y); };
    problem.range_projector = [&](const Vec& x, Vec& y) { coarse_->project_range(x, y); };
    problem.b = &data.b;
    problem.lower = &lower_bounds;
    problem.hessian_norm = norm;
    problem.preconditioner = preconditioner_operator();
    Vec mu = shifted_start(settings, data, m);
    const SmalbeResult r = smalbe(problem, mu, smalbe_within(settings),
        [&](const Vec& x, const Vec& gP, const Vec&) {
          result.equality_norm = (coarse_->G() * x).norm();  // G lambda - e = G mu
          if (settings.stopping == StoppingTest::relative_kkt) return kkt_stop(x, gP.lpNorm<Eigen::Infinity>(), result.equality_norm / eq_reference);
          return result.equality_norm <= tolerance * eq_reference && gP.norm() <= b_tol;
        },
        settings.monitor);
    record(result, r.counts, r.status, r.projected_gradient_norm);
    result.equality_norm = (coarse_->G() * mu).norm();
    lambda = lambda_from_shifted(mu, lower_bounds, data.lambda_tilde);
  }
  result.violation = kkt_stop.measure();
  result.scale_evaluations = kkt_stop.evaluations();
  result.solve_seconds = solve_clock.seconds() - result.norm_estimate_seconds - result.projector_seconds;
  result.operator_seconds += F_->application_seconds() - operator_start;
  if (preconditioner_) result.preconditioner_seconds = preconditioner_->application_seconds() - preconditioner_start;
  result.check_seconds = check_seconds_ - check_start;
  recover(data, std::move(lambda), result);
  return result;
}

}  // namespace ffeti
