#include "feti/feti_problem.h"

#include "feti/dirichlet.h"
#include "feti/errors.h"
#include "feti/input_checks.h"
#include "feti/kernel.h"
#include "parallel/process.h"

#include <chrono>
#include <algorithm>
#include <exception>

namespace ffeti {
namespace {

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

/// Multipliers exactly at their bound are exactly zero in lambda (not round-off).
Vec lambda_from_shifted(const Vec& mu, const Vec& lower, const Vec& lambda_tilde) {
  Vec lambda = mu + lambda_tilde;
  for (Eigen::Index i = 0; i < mu.size(); ++i)
    if (lower[i] != kUnbounded && mu[i] <= lower[i]) lambda[i] = 0.0;
  return lambda;
}

}  // namespace

void DualSolveSettings::validate() const {
  if (!(tolerance > 0 && tolerance < 1)) throw InputError("tol: must lie in (0, 1)");
  if (max_hessian < 1) throw InputError("maxit: must be >= 1");
  try {
    smalbe.validate();
    mprgp.validate();
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
}

FetiProblem::FetiProblem(std::vector<SubdomainInput> subdomains, const ContactInput& contact,
                         const FetiSetupSettings& settings)
    : settings_(settings), comm_(std::make_shared<SerialCommunicator>()), inputs_(std::move(subdomains)) {
  global_count_ = static_cast<int>(inputs_.size());
  for (int s = 0; s < global_count_; ++s) global_ids_.push_back(s);
  set_up(contact);
}

FetiProblem::FetiProblem(std::vector<SubdomainInput> local, std::vector<int> global_ids, int global_count,
                         const ContactInput& local_contact, const FetiSetupSettings& settings,
                         std::shared_ptr<const Communicator> comm)
    : settings_(settings), comm_(std::move(comm)), inputs_(std::move(local)),
      global_ids_(std::move(global_ids)), global_count_(global_count) {
  set_up(local_contact);
}

void FetiProblem::set_up(const ContactInput& local_contact) {
  if (settings_.factor == FactorKind::supernodal) settings_.threads = 1;
  const Communicator& comm = *comm_;
  Stopwatch constraints_clock;
  collectively(comm, [&] {
    if (global_count_ < 1) throw InputError("K: no subdomains given");
    if (global_ids_.size() != inputs_.size()) throw InputError("K: one global index per local subdomain needed");
    for (size_t k = 0; k < global_ids_.size(); ++k)
      if (global_ids_[k] < 0 || global_ids_[k] >= global_count_ || (k > 0 && global_ids_[k] <= global_ids_[k - 1]))
        throw InputError("K: local subdomains need ascending global indices in 0.." + std::to_string(global_count_ - 1));
    validate_input(inputs_, local_contact, global_ids_);
  });

  // Who holds what: boxes, bodies and owners of all subdomains on every rank.
  std::vector<double> mine;
  for (size_t k = 0; k < inputs_.size(); ++k) {
    const BoundingBox b = bounding_box(inputs_[k]);
    mine.insert(mine.end(), {double(global_ids_[k]), double(inputs_[k].body), b.x0, b.y0, b.x1, b.y1});
  }
  std::vector<int> counts;
  const std::vector<double> all = comm.allgather(mine, &counts);
  std::vector<BoundingBox> boxes(static_cast<size_t>(global_count_));
  std::vector<int> bodies(static_cast<size_t>(global_count_)), owner(static_cast<size_t>(global_count_), -1);
  std::string ownership_error;
  for (size_t r = 0, p = 0; r < counts.size(); ++r)
    for (int end = static_cast<int>(p) + counts[r]; static_cast<int>(p) < end; p += 6) {
      const auto s = static_cast<size_t>(all[p]);
      if (owner[s] >= 0) ownership_error = "K[" + std::to_string(s) + "]: given by two ranks";
      owner[s] = static_cast<int>(r);
      bodies[s] = static_cast<int>(all[p + 1]);
      boxes[s] = {all[p + 2], all[p + 3], all[p + 4], all[p + 5]};
    }
  for (size_t s = 0; s < owner.size(); ++s)
    if (owner[s] < 0) ownership_error = "K[" + std::to_string(s) + "]: given by no rank";
  if (!ownership_error.empty()) throw InputError(ownership_error);  // the same on every rank

  const double snap = snapping_length(boxes);
  std::vector<DofRecord> records =
      unpack(comm.allgather(pack(constraint_candidates(inputs_, global_ids_, local_contact, boxes, bodies, snap))));
  const std::vector<SegmentRecord> segments =
      unpack_segments(comm.allgather(pack(segment_records(inputs_, global_ids_, local_contact))));
  constraints_ = build_constraints(records, segments, local_contact, settings_.variant, snap);
  std::sort(records.begin(), records.end(), [](const DofRecord& a, const DofRecord& b) {
    return std::make_pair(a.subdomain, a.dof) < std::make_pair(b.subdomain, b.dof);
  });
  for (int i = constraints_.equality_rows; i < constraints_.rows(); ++i) {
    const ConstraintEntry& slave = constraints_.entries[static_cast<size_t>(constraints_.row_start[static_cast<size_t>(i)])];
    const auto it = std::lower_bound(records.begin(), records.end(), std::make_pair(slave.subdomain, slave.dof),
                                     [](const DofRecord& r, const std::pair<int, int>& key) {
                                       return std::make_pair(r.subdomain, r.dof) < key;
                                     });
    contact_positions_.push_back({it->x, it->y});
  }
  std::vector<Eigen::Index> sizes;
  for (const auto& sub : inputs_) sizes.push_back(sub.K.rows());
  local_ = split_by_subdomain(constraints_, sizes, global_ids_);
  sum_ = std::make_unique<SubdomainSum>(rows_by_subdomain(constraints_, global_count_), owner,
                                        constraints_.rows(), comm);
  setup_times_.constraints = constraints_clock.seconds();

  Stopwatch factor_clock;
  factorize();
  F_ = std::make_unique<DualOperator>(subdomains_, local_, *sum_, constraints_.rows(), settings_.threads);
  setup_times_.factorization = local_factor_seconds_ = factor_clock.seconds();

  int local_floating = 0;
  for (const auto& s : subdomains_) local_floating += s->floating() ? 1 : 0;
  if (comm.sum(local_floating) > 0) {
    Stopwatch coarse_clock;
    coarse_ = std::make_unique<CoarseSpace>(subdomains_, local_, global_ids_, constraints_.rows(), bodies, comm);
    setup_times_.coarse_space = coarse_clock.seconds();
  }
  compute_dual_data();

  long local_primal = 0;
  double local_nonzeros = 0;
  for (size_t k = 0; k < inputs_.size(); ++k) local_primal += inputs_[k].K.rows();
  for (const auto& s : subdomains_) local_nonzeros += s->factor_nonzeros();
  primal_dimension_ = static_cast<long>(comm.sum(static_cast<double>(local_primal)));
  factor_nonzeros_ = comm.sum(local_nonzeros);
  gather_rank_statistics(0.0);
  setup_times_ = {comm.max(setup_times_.constraints), comm.max(setup_times_.factorization),
                  comm.max(setup_times_.coarse_space), comm.max(setup_times_.dual_data), 0, 0, 0, 0};
}

void FetiProblem::factorize() {
  const bool eliminate = settings_.variant == FetiVariant::feti1;
  const int count = local_subdomain_count();
  subdomains_.resize(inputs_.size());
  std::vector<std::exception_ptr> failures(inputs_.size());
#pragma omp parallel for schedule(dynamic) num_threads(resolve_thread_count(settings_.threads))
  for (int k = 0; k < count; ++k) {
    const SubdomainInput& in = inputs_[static_cast<size_t>(k)];
    try {
      const bool eliminated = eliminate && !in.dirichlet_dofs.empty();
      subdomains_[static_cast<size_t>(k)] = std::make_unique<Subdomain>(
          global_ids_[static_cast<size_t>(k)], eliminated ? eliminate_dirichlet(in.K, in.dirichlet_dofs) : in.K,
          candidate_kernel(in.x, in.y, in.component), settings_.factor);
    } catch (...) {
      failures[static_cast<size_t>(k)] = std::current_exception();
    }
  }
  collectively(*comm_, [&] {
    for (const auto& failure : failures)
      if (failure) std::rethrow_exception(failure);
  });
}

void FetiProblem::gather_rank_statistics(double solve_seconds) const {
  long primal = 0;
  for (const auto& in : inputs_) primal += in.K.rows();
  const std::vector<double> all = comm_->allgather(std::vector<double>{
      double(local_subdomain_count()), double(primal), local_factor_seconds_, solve_seconds, peak_memory_mb()});
  rank_statistics_.clear();
  for (size_t p = 0; p + 5 <= all.size(); p += 5)
    rank_statistics_.push_back({static_cast<int>(p / 5), static_cast<int>(all[p]), static_cast<long>(all[p + 1]),
                                all[p + 2], all[p + 3], all[p + 4]});
}

void FetiProblem::set_loads(const std::vector<Vec>& loads) {
  collectively(*comm_, [&] {
    if (loads.size() != inputs_.size())
      throw InputError("f: has " + std::to_string(loads.size()) + " entries for " +
                       std::to_string(inputs_.size()) + " subdomains");
    for (size_t k = 0; k < loads.size(); ++k)
      if (loads[k].size() != inputs_[k].K.rows() || !loads[k].allFinite())
        throw InputError("f[" + std::to_string(global_ids_[k]) + "]: needs " +
                         std::to_string(inputs_[k].K.rows()) + " finite entries");
  });
  for (size_t k = 0; k < loads.size(); ++k) inputs_[k].f = loads[k];
  compute_dual_data();
}

void FetiProblem::compute_dual_data() {
  Stopwatch clock;
  operator_loads_.clear();
  for (const auto& in : inputs_)
    operator_loads_.push_back(settings_.variant == FetiVariant::feti1 && !in.dirichlet_dofs.empty()
                                  ? eliminated_load(in.K, in.f, in.dirichlet_dofs, in.dirichlet_values)
                                  : in.f);
  const int m = constraints_.rows();
  F_->apply_B_pseudo_inverse(operator_loads_, d_);
  d_ -= Eigen::Map<const Vec>(constraints_.rhs.data(), m);  // d = B K^+ f - c
  if (coarse_) {
    e_ = coarse_->kernel_load(operator_loads_);              // e = R'f
    lambda_tilde_ = coarse_->least_norm_solution(e_);        // G lambda~ = e
    Vec F_lambda_tilde(m);
    F_->apply(lambda_tilde_, F_lambda_tilde);
    coarse_->project(d_ - F_lambda_tilde, b_);               // b = P(d - F lambda~)
  } else {
    e_.resize(0);
    lambda_tilde_ = Vec::Zero(m);
    b_ = d_;
  }
  setup_times_.dual_data = clock.seconds();
}

std::string FetiProblem::path() const {
  const bool inequalities = constraints_.inequality_rows() > 0;
  const bool floating = coarse_ != nullptr;
  if (constraints_.rows() == 0) return "cholesky";
  if (!inequalities) return floating ? "projected_cg" : "cg";
  return floating ? "smalbe" : "mprgp";
}

double FetiProblem::operator_norm(bool projected, IterationCounts& counts, double& seconds) const {
  std::optional<double>& cached = projected ? norm_PFP_ : norm_F_;
  int& cost = projected ? norm_PFP_cost_ : norm_F_cost_;
  if (!cached) {
    Stopwatch clock;
    const int m = constraints_.rows();
    NormEstimate estimate;
    if (projected) {
      estimate = estimate_norm([&](const Vec& x, Vec& y) { apply_PFP(x, y); }, m, {},
                               [&](Vec& v) { coarse_->project(Vec(v), v); });
    } else {
      estimate = estimate_norm([&](const Vec& x, Vec& y) { F_->apply(x, y); }, m);
    }
    cached = estimate.norm;
    cost = estimate.multiplications;
    seconds = clock.seconds();
  }
  counts.hessian_norm_estimate += cost;
  return *cached;
}

void FetiProblem::apply_PFP(const Vec& x, Vec& y) const {
  coarse_->project(x, projected_);
  F_->apply(projected_, applied_);
  coarse_->project(applied_, y);  // y = P F P x
}

FetiResult FetiProblem::solve(const DualSolveSettings& settings) const {
  settings.validate();
  FetiResult result;
  result.path = path();
  const int m = constraints_.rows();
  const double tolerance = settings.tolerance;
  result.gradient_reference = b_.norm() > 0 ? b_.norm() : 1.0;
  result.equality_reference = e_.norm() > 0 ? e_.norm() : 0.0;
  std::string phases = "constraints,factorization";
  if (coarse_) phases += ",coarse_space";
  Stopwatch solve_clock;

  if (result.path == "cholesky") {
    result.status = SolveStatus::converged;
    result.phases = phases;
    result.times.solve = solve_clock.seconds();
    return finish(std::move(result), Vec::Zero(0));
  }
  phases += ",dual_data";

  Vec lambda;
  const Vec lower_bounds = [&] {
    Vec lower = Vec::Constant(m, kUnbounded);
    for (int i = constraints_.equality_rows; i < m; ++i) lower[i] = -lambda_tilde_[i];  // lambda_I >= 0
    return lower;
  }();
  const double b_tol = tolerance * result.gradient_reference;

  if (result.path == "cg" || result.path == "projected_cg") {
    const LinearOperator A = [&](const Vec& x, Vec& y) {
      if (coarse_) apply_PFP(x, y);
      else F_->apply(x, y);
    };
    CgSettings cg;
    cg.max_hessian = settings.max_hessian;
    Vec mu = Vec::Zero(m), g;
    const CgResult cg_result = conjugate_gradient(
        A, b_, mu, g, cg, [&](const Vec&, const Vec&, double norm) { return norm <= b_tol; },
        settings.monitor);
    result.status = cg_result.status;
    result.counts = cg_result.counts;
    result.gradient_norm = cg_result.gradient_norm;
    lambda = mu + lambda_tilde_;
    phases += "," + result.path;
  } else if (result.path == "mprgp") {
    double seconds = 0;
    const double norm = operator_norm(false, result.counts, seconds);
    result.times.norm_estimate = seconds;
    MprgpSettings mprgp_settings = settings.mprgp;
    mprgp_settings.max_hessian = settings.max_hessian;
    Vec x = Vec::Zero(m), g;
    const MprgpResult r = mprgp(
        [&](const Vec& v, Vec& y) { F_->apply(v, y); }, b_, lower_bounds, norm, x, g, false, mprgp_settings,
        [&](const Vec&, const Vec&, double norm_gp) { return norm_gp <= b_tol; }, settings.monitor);
    const IterationCounts estimate = result.counts;
    result.counts = r.counts;
    result.counts.hessian_norm_estimate = estimate.hessian_norm_estimate;
    result.status = r.status;
    result.gradient_norm = r.projected_gradient_norm;
    lambda = lambda_from_shifted(x, lower_bounds, lambda_tilde_);
    phases += ",norm_estimate,mprgp";
  } else {  // smalbe
    double seconds = 0;
    const double norm = operator_norm(true, result.counts, seconds);
    result.times.norm_estimate = seconds;
    const double eq_reference =
        result.equality_reference > 0 ? result.equality_reference : result.gradient_reference / norm;
    result.equality_reference = eq_reference;
    SmalbeProblem problem;
    problem.hessian = [&](const Vec& x, Vec& y) { apply_PFP(x, y); };
    problem.range_projector = [&](const Vec& x, Vec& y) { coarse_->project_range(x, y); };
    problem.b = &b_;
    problem.lower = &lower_bounds;
    problem.hessian_norm = norm;
    SmalbeSettings smalbe_settings = settings.smalbe;
    smalbe_settings.max_hessian = settings.max_hessian;
    smalbe_settings.inner = settings.mprgp;
    Vec mu = Vec::Zero(m);
    const SmalbeResult r = smalbe(problem, mu, smalbe_settings,
        [&](const Vec& x, double gp_norm, const Vec&) {
          result.equality_norm = (coarse_->G() * x).norm();  // G lambda - e = G mu
          return gp_norm <= b_tol && result.equality_norm <= tolerance * eq_reference;
        },
        settings.monitor);
    const int estimate = result.counts.hessian_norm_estimate;
    result.counts = r.counts;
    result.counts.hessian_norm_estimate = estimate;
    result.status = r.status;
    result.gradient_norm = r.projected_gradient_norm;
    result.equality_norm = (coarse_->G() * mu).norm();
    lambda = lambda_from_shifted(mu, lower_bounds, lambda_tilde_);
    phases += ",norm_estimate,smalbe";
  }
  result.times.solve = solve_clock.seconds() - result.times.norm_estimate;
  result.phases = phases;
  return finish(std::move(result), lambda);
}

FetiResult FetiProblem::finish(FetiResult result, const Vec& lambda) const {
  Stopwatch recovery_clock;
  result.lambda = lambda;
  if (constraints_.rows() == 0) {
    result.u.resize(subdomains_.size());
    for (size_t s = 0; s < subdomains_.size(); ++s)
      subdomains_[s]->apply_pseudo_inverse(operator_loads_[s], result.u[s]);
  } else {
    result.u = recover_primal(*F_, coarse_.get(), constraints_, operator_loads_, lambda);
  }
  result.times.recovery = recovery_clock.seconds();
  Stopwatch kkt_clock;
  const bool eliminated = settings_.variant == FetiVariant::feti1;
  result.kkt = kkt_residuals(inputs_, local_, *F_, constraints_, eliminated, result.u, result.lambda, *comm_);
  result.energy = energy(inputs_, result.u, *comm_);
  for (int i = constraints_.equality_rows; i < constraints_.rows(); ++i)
    if (constraints_.kind[static_cast<size_t>(i)] == RowKind::contact && lambda[i] > 0)
      ++result.active_contact;
  result.times.kkt = kkt_clock.seconds();
  result.phases += ",recovery,kkt";
  gather_rank_statistics(result.times.norm_estimate + result.times.solve);
  PhaseTimes& t = result.times;
  t = {0, 0, 0, 0, comm_->max(t.norm_estimate), comm_->max(t.solve), comm_->max(t.recovery), comm_->max(t.kkt)};
  return result;
}

}  // namespace ffeti
