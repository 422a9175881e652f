#include "feti/dual_system.h"

#include "base/errors.h"
#include "feti/held_bytes.h"
#include "feti/primal.h"
#include "base/stopwatch.h"
#include "qp/cone_distance.h"
#include "qp/norm_estimate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace ffeti {

qp::Budget DualSolveSettings::validate() const {
  if (!(tolerance > 0 && tolerance < 1)) throw InputError("tol: must lie in (0, 1)");
  const std::pair<const char*, double> positive[] = {
      {"rho", smalbe.rho_factor}, {"M", smalbe.M_factor}, {"eta", smalbe.eta_factor}, {"gamma", mprgp.gamma}};
  for (const auto& [name, value] : positive)
    if (!(value > 0)) throw InputError(std::string(name) + ": must be > 0");
  if (!start.allFinite()) throw InputError("start: has entries that are not finite numbers");
  if (settle < 0) throw InputError("settle: must be >= 0");
  if (friction_iterations < 1) throw InputError("frictionit: must be >= 1");
  try {
    smalbe.validate();
    mprgp.validate();
    return qp::Budget(max_hessian);  // its check of maxit
  } catch (const std::invalid_argument& error) {
    throw InputError(error.what());
  }
}

DualSystem::DualSystem(const SubdomainList& subdomains, const std::vector<int>& global_ids,
                       const std::vector<int>& owner, const std::vector<int>& bodies, Constraints constraints,
                       int threads, const Communicator& comm, GramLayout coarse_gram)
    : subdomains_(subdomains), global_ids_(global_ids), comm_(comm), constraints_(std::move(constraints)) {
  std::vector<Eigen::Index> sizes;
  for (const auto& s : subdomains) sizes.push_back(s->size());
  local_ = split_by_subdomain(constraints_, sizes, global_ids);
  sum_ = std::make_unique<SubdomainSum>(rows_by_subdomain(constraints_, static_cast<int>(owner.size())), owner,
                                        constraints_.rows(), comm);
  F_ = std::make_unique<DualOperator>(subdomains_, local_, *sum_, constraints_.rows(), threads);
  int local_floating = 0;
  for (const auto& s : subdomains_) local_floating += s->floating() ? 1 : 0;
  if (comm.sum(local_floating) > 0)
    coarse_ = std::make_unique<CoarseSpace>(subdomains_, local_, global_ids, constraints_.rows(),
                                            constraints_.equality_rows, bodies, comm, coarse_gram);
  // The path, once: the rows' kinds and the coarse space never change after this (a new
  // right-hand side keeps the rows, replace_right_hand_side).
  const bool inequalities = constraints_.inequality_rows() > 0, floating = coarse_ != nullptr;
  if (constraints_.rows() == 0) path_ = DualPath::cholesky;
  else if (!inequalities) path_ = floating ? DualPath::projected_cg : DualPath::cg;
  else path_ = floating ? DualPath::smalbe : DualPath::mprgp;
}

void DualSystem::replace_right_hand_side(Constraints rebuilt) {
  const auto same_entry = [](const ConstraintEntry& a, const ConstraintEntry& b) {
    return a.subdomain == b.subdomain && a.dof == b.dof && a.coefficient == b.coefficient;
  };
  if (rebuilt.row_start != constraints_.row_start || rebuilt.kind != constraints_.kind ||
      rebuilt.geometry.size() != constraints_.geometry.size() ||
      !std::equal(rebuilt.entries.begin(), rebuilt.entries.end(), constraints_.entries.begin(),
                  constraints_.entries.end(), same_entry))
    throw std::logic_error("replace_right_hand_side: the rebuilt rows differ from the factorized ones");
  constraints_.rhs = std::move(rebuilt.rhs);
  constraints_.geometry = std::move(rebuilt.geometry);
  constraints_.beyond_reach = std::move(rebuilt.beyond_reach);
}

void DualSystem::use_preconditioner(DualPreconditioner kind, const std::vector<const SparseMatrix*>& operator_matrices,
                                    int threads, bool share_factors, InterfaceScaling scaling) {
  preconditioner_kind_ = kind;
  if (kind == DualPreconditioner::none) {
    preconditioner_.reset();
    return;
  }
  preconditioner_ = std::make_unique<DirichletPreconditioner>(operator_matrices, local_, global_ids_, constraints_, *sum_, threads,
                                                              kind == DualPreconditioner::lumped, share_factors, scaling);
}

LinearOperator DualSystem::preconditioner_operator() const {
  if (!preconditioner_) return {};
  return [this](const Vec& x, Vec& y) { preconditioner_->apply(x, y); };
}

DualData DualSystem::data(std::vector<Vec> loads, const Vec& c) const {
  DualData data;
  data.loads = std::move(loads);
  data.c = c;
  Vec d, F_lambda_tilde;
  if (coarse_) {
    data.e = coarse_->kernel_load(data.loads);                 // e = R'f
    data.lambda_tilde = coarse_->least_norm_solution(data.e);  // G lambda~ = e
    F_->apply_B_pseudo_inverse_and_F(data.loads, data.lambda_tilde, d, F_lambda_tilde);
  } else {
    data.e.resize(0);
    data.lambda_tilde = Vec::Zero(constraints_.rows());
    F_->apply_B_pseudo_inverse(data.loads, d);
  }
  // b is computed from both B K^+ f and c: its round-off is relative to the larger. A
  // design that only moves the gaps under a floating body has f = 0 and c in Im G', so b
  // is round-off of c alone (a uniform dGap: the body moves rigidly, lambda' = 0).
  data.data_norm = std::max(d.norm(), c.norm());
  d -= c;  // d = B K^+ f - c
  if (coarse_)
    coarse_->project(d - F_lambda_tilde, data.b);  // b = P(d - F lambda~)
  else
    data.b = d;
  return data;
}

double DualSystem::estimated_norm(CachedNorm& cache, const LinearOperator& H,
                                  const std::function<void(Vec&)>& start_filter, const NormEstimateSettings& settings,
                                  DualSolution& result) const {
  if (!cache.norm) {
    Stopwatch clock;
    const OperatorUse operator_start = operator_use();
    const NormEstimate estimate = estimate_norm(H, rows(), settings, start_filter);
    cache.norm = estimate.norm;
    cache.cost = estimate.multiplications;
    result.times.norm_estimate = clock.seconds();
    charge_operator_use(operator_start, -1, 1, result);  // the estimate's, not the solve's
  }
  result.counts.hessian_norm_estimate += cache.cost;
  return *cache.norm;
}

void DualSystem::charge_operator_use(const OperatorUse& start, double sign, int runs, DualSolution& result) const {
  const OperatorUse now = operator_use();
  result.times.dual_operator += sign * (now.seconds - start.seconds) / runs;
  result.times.factor_solves += sign * (now.solve_seconds - start.solve_seconds) / runs;
  result.dual_operator_applications += static_cast<long>(sign) * (now.applications - start.applications) / runs;
}

void DualSystem::apply_PFP(const Vec& x, Vec& y) const {
  coarse_->project(x, work_.projected);
  F_->apply(work_.projected, work_.applied);
  coarse_->project(work_.applied, y);  // y = P F P x
}

void DualSystem::apply_PFP(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  work_.block_projected.resize(x.rows(), x.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    coarse_->project(x.col(j), work_.projected);
    work_.block_projected.col(j) = work_.projected;
  }
  F_->apply(work_.block_projected, work_.block_applied);
  y.resize(x.rows(), x.cols());
  for (Eigen::Index j = 0; j < x.cols(); ++j) {
    coarse_->project(work_.block_applied.col(j), work_.projected);
    y.col(j) = work_.projected;
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

PrimalCheck DualSystem::primal_check(const DualData& data, const Vec& lambda, std::vector<Vec>* recovered) const {
  Stopwatch clock;
  std::vector<Vec> u = recover_primal(*F_, coarse_.get(), constraints_, data.loads, data.c, lambda, data.slip_bound);
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
  const int first_friction = constraints_.first_friction_row();
  for (int i = 0; i < first_friction; ++i) {
    const double r = Bu[i] - data.c[i];
    violation = std::max(violation, i < constraints_.equality_rows ? std::abs(r) : r);
    if (i >= constraints_.equality_rows && lambda_scale > 0)
      complementarity = std::max(complementarity, std::abs(lambda[i] * r) / lambda_scale);
  }
  // A friction group slips (s = B_t u - c_t) only at its bound and along lambda_t (the force
  // on the slave, -lambda_t t, opposes the slip: docs/reference.md, "Signs of contact and friction").
  const Vec gap = Bu - data.c;
  const double force_scale = friction_force_scale(lambda_scale, data.slip_bound);
  for (int i = first_friction; i < rows(); i += constraints_.tangent_directions)
    complementarity = std::max(complementarity, friction_residual(constraints_, lambda, gap, i,
                                                                  data.slip_bound[i - first_friction], force_scale)
                                                        .complementarity / force_scale);
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
  if (recovered) *recovered = std::move(u);
  return check;
}

void DualSystem::recover(const DualData& data, Vec lambda, DualSolution& result) const {
  Stopwatch recovery_clock;
  result.u = recover_primal(*F_, coarse_.get(), constraints_, data.loads, data.c, lambda, data.slip_bound);
  result.lambda = std::move(lambda);
  result.times.recovery = recovery_clock.seconds();
}

CoulombFeasibility DualSystem::coulomb_feasibility(const DualData& data, const std::vector<int>& bodies,
                                                   double enough) const {
  const Constraints& c = constraints_;
  const double e_norm = data.e.norm();
  if (!coarse_ || coarse_->empty() || c.friction_rows == 0 || !(e_norm > 0)) return {};
  const FreeRowProjector& T = free_rows();
  if (T.remaining() == 0) return {};  // no body floats as a whole
  // Onto the cones: a friction pair with its contact row's normal multiplier, the other
  // contact rows lambda_n >= 0, equality rows free.
  std::vector<int> unpaired;
  std::vector<char> paired(static_cast<size_t>(c.rows()), 0);
  for (int t = 0; t < c.friction_rows; t += c.tangent_directions) paired[static_cast<size_t>(c.normal_row[static_cast<size_t>(t)])] = 1;
  for (int i = c.equality_rows; i < c.first_friction_row(); ++i)
    if (!paired[static_cast<size_t>(i)]) unpaired.push_back(i);
  const auto project = [&](Vec& lambda) {
    for (int t = 0; t < c.friction_rows; t += c.tangent_directions)
      qp::project_onto_cone(lambda[c.normal_row[static_cast<size_t>(t)]], &lambda[c.first_friction_row() + t],
                            c.tangent_directions, c.coulomb_coefficient[static_cast<size_t>(t)]);
    for (int i : unpaired) lambda[i] = std::max(lambda[i], 0.0);
  };
  const Eigen::MatrixXd& C = T.remaining_rows();
  const Vec target = T.remaining_basis().transpose() * data.e;
  const qp::ConeDistance found = qp::cone_distance(C, target, project, e_norm, enough);
  if (found.distance <= enough) return {found.distance, -1};  // within reach, or undecided (-1)
  // The body that would slide: the largest share of the residual over its rigid modes.
  const Vec residual = T.remaining_basis() * (C * found.x - target);
  std::map<int, double> share;
  for (Eigen::Index r = 0; r < residual.size(); ++r)
    share[bodies[static_cast<size_t>(coarse_->row_owner()[static_cast<size_t>(r)].first)]] += residual[r] * residual[r];
  const auto largest = std::max_element(share.begin(), share.end(),
                                        [](const auto& a, const auto& b) { return a.second < b.second; });
  return {found.distance, largest->first};
}

const FreeRowProjector& DualSystem::free_rows() const {
  if (!free_rows_) free_rows_ = std::make_unique<FreeRowProjector>(coarse_->gram(), constraints_.equality_rows);
  return *free_rows_;
}

qp::ConstraintSet DualSystem::multiplier_constraints(const DualData& data) const {
  qp::ConstraintSet set;
  set.add_free(constraints_.equality_rows);
  set.add_half_line(Vec::Zero(constraints_.contact_rows()));  // lambda_I >= 0
  if (constraints_.friction_rows == 0) return set;
  if (constraints_.tangent_directions == 1) {
    set.add_box(-data.slip_bound, data.slip_bound);  // |lambda_t| <= g
    return set;
  }
  // ||(lambda_t1, lambda_t2)|| <= g per contact row: isotropic friction (a box would not be).
  // g = inf (the first Coulomb solve sticks everywhere) leaves its pair free: runs of finite
  // and of infinite bounds become disc and free blocks in row order.
  const Eigen::Index pairs = constraints_.friction_rows / 2;
  for (Eigen::Index first = 0; first < pairs;) {
    const bool bounded = std::isfinite(data.slip_bound[2 * first]);
    Eigen::Index last = first + 1;
    while (last < pairs && std::isfinite(data.slip_bound[2 * last]) == bounded) ++last;
    if (bounded) {
      Vec radius(last - first);
      for (Eigen::Index j = first; j < last; ++j) radius[j - first] = data.slip_bound[2 * j];
      set.add_disc(Vec::Zero(2 * (last - first)), radius);
    } else {
      set.add_free(2 * (last - first));
    }
    first = last;
  }
  return set;
}

Vec DualSystem::lambda_from_shifted(const Vec& mu, const qp::ConstraintSet& bounds, const DualData& data) const {
  // Multipliers at a bound are the bound exactly (0, or -g, g, or a pair of norm g), not
  // the bound plus the round-off of lambda~.
  Vec lambda = mu + data.lambda_tilde;
  const Vec lower = bounds.lower(), upper = bounds.upper();
  const int first_friction = constraints_.first_friction_row();
  for (Eigen::Index i = 0; i < first_friction; ++i)
    if (lower[i] != kUnbounded && mu[i] <= lower[i]) lambda[i] = 0.0;
  if (constraints_.tangent_directions == 2) {  // a pair at its disc's boundary: on it exactly
    for (int i = first_friction; i < mu.size(); i += 2) {
      const double g = data.slip_bound[i - first_friction];
      const double norm = std::hypot(lambda[i], lambda[i + 1]);
      if (at_slip_bound(constraints_, lambda, i, g) && norm > 0) lambda.segment(i, 2) *= g / norm;
    }
    return lambda;
  }
  for (Eigen::Index i = first_friction; i < mu.size(); ++i) {
    const double g = data.slip_bound[i - first_friction];
    if (mu[i] <= lower[i]) lambda[i] = -g;
    else if (mu[i] >= upper[i]) lambda[i] = g;
  }
  return lambda;
}

void DualSystem::use_conjugate_projector(const std::vector<Eigen::MatrixXd>& modes) {
  if (coarse_) throw std::logic_error("use_conjugate_projector: a coarse space already holds the rigid modes");
  // C = B_E R: each local subdomain's modes on its equality rows, as (row, column, value)
  // triplets gathered from every rank; column = global subdomain x r + mode.
  const Eigen::Index r = modes.empty() ? 0 : modes.front().cols();
  const double per_subdomain = comm_.max(static_cast<double>(r));
  std::vector<double> mine;
  double last_id = -1;
  for (size_t k = 0; k < local_.size(); ++k) {
    const Eigen::MatrixXd traces = local_[k].B * modes[k];  // rows x r
    for (Eigen::Index i = 0; i < traces.rows(); ++i) {
      const int row = local_[k].rows[static_cast<size_t>(i)];
      if (row >= constraints_.equality_rows) continue;  // contact and friction rows: untouched by P
      for (Eigen::Index j = 0; j < r; ++j)
        if (traces(i, j) != 0) mine.insert(mine.end(), {double(row), double(global_ids_[k] * per_subdomain + j), traces(i, j)});
    }
    last_id = std::max(last_id, double(global_ids_[k]));
  }
  const Eigen::Index columns = static_cast<Eigen::Index>((comm_.max(last_id) + 1) * per_subdomain);
  const std::vector<double> all = comm_.allgather(mine);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(rows(), columns);
  for (size_t t = 0; t + 2 < all.size(); t += 3)
    C(static_cast<Eigen::Index>(all[t]), static_cast<Eigen::Index>(all[t + 1])) += all[t + 2];
  conjugate_ = std::make_unique<ConjugateProjector>(std::move(C), *F_);
}

DualSystem::HeldBytes DualSystem::held_bytes() const {
  HeldBytes bytes;
  bytes.rows = F_->held_bytes();
  for (const LocalConstraints& block : local_) bytes.rows += sparse_bytes(block.B) + vector_bytes(block.rows);
  if (coarse_) bytes.coarse = coarse_->held_bytes();
  if (preconditioner_) bytes.preconditioner = preconditioner_->held_bytes();
  return bytes;
}

}  // namespace ffeti
