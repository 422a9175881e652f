#include "sens/sensitivity.h"

#include "base/errors.h"
#include "base/stopwatch.h"
#include "qp/stopping_test.h"
#include "parallel/process.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace ffeti {
namespace {

/// Sum of per-item values from all ranks in a fixed order of their keys, so that the
/// result is bitwise the same for any number of ranks. `local` holds (key..., value) tuples
/// of `width` doubles, the value last.
double ordered_sum(const std::vector<double>& local, size_t width, const Communicator& comm) {
  const std::vector<double> all = comm.allgather(local);
  std::vector<size_t> order;
  for (size_t p = 0; p + width <= all.size(); p += width) order.push_back(p);
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::lexicographical_compare(all.begin() + static_cast<long>(a), all.begin() + static_cast<long>(a + width - 1),
                                        all.begin() + static_cast<long>(b), all.begin() + static_cast<long>(b + width - 1));
  });
  double sum = 0;
  for (size_t p : order) sum += all[p + width - 1];
  return sum;
}

/// An answer whose residuals are not numbers is an overflow. A sensitivity or adjoint answer
/// whose KKT residuals, recomputed in primal form, meet the
/// tolerance is right, whatever the dual stop test said: at a weakly active point the seed's
/// test also asks ||G mu|| <= tol ||e||, which round-off can keep out of reach (a right answer
/// once came back as not_positive_definite after 2866 multiplications). One that CG called
/// stagnated with residuals above the round-off ceiling did not stop at round-off: max_iterations.
SolveStatus checked_status(SolveStatus dual_status, const KktResiduals& kkt, double tolerance) {
  if (!kkt.finite()) return SolveStatus::overflow;
  if (dual_status == SolveStatus::max_iterations || dual_status == SolveStatus::stagnated ||
      dual_status == SolveStatus::not_positive_definite) {
    if (kkt.max() <= tolerance) return SolveStatus::converged;
    if (dual_status == SolveStatus::stagnated && kkt.max() > kRoundOffCeiling) return SolveStatus::max_iterations;
  }
  return dual_status;
}

void check_size(bool ok, const std::string& name, int subdomain, const std::string& what) {
  if (!ok) throw InputError(name + "[" + std::to_string(subdomain) + "]: " + what);
}

}  // namespace

double default_classification_threshold(double state_tolerance) {
  // Not below 1e-8: gaps recovered from u carry round-off that tol does not bound (5e-11 of
  // max |u| on glued membranes of stiffness contrast 1e6 at tol 1e-12), so a threshold that
  // followed tol down classified zero-gap rows as open: the classification would depend on
  // how tightly the state was solved. 1e-8 ~ sqrt(machine epsilon), the accuracy of a
  // difference of solution values.
  return std::clamp(10 * state_tolerance, 1e-8, 1e-2);
}

ContactClassification classify_contact(const FetiProblem& problem, const FetiResult& state, double threshold) {
  if (!(threshold > 0 && threshold < 1)) throw InputError("activeTol: must lie in (0, 1)");
  const Constraints& c = problem.constraints();
  ContactClassification result;
  result.threshold = threshold;
  Vec Bu;
  problem.dual().F().apply_B(state.u, Bu);
  double u_max = 0;
  for (const Vec& us : state.u) u_max = std::max(u_max, us.size() ? us.cwiseAbs().maxCoeff() : 0.0);
  result.gap_scale = problem.communicator().max(u_max);
  for (int i = c.equality_rows; i < c.rows(); ++i) result.lambda_scale = std::max(result.lambda_scale, state.lambda[i]);
  for (int i = c.equality_rows; i < c.rows(); ++i) {
    const double gap = c.rhs[static_cast<size_t>(i)] - Bu[i];  // >= 0 where the row holds
    if (state.lambda[i] > threshold * result.lambda_scale) result.strong.push_back(i);
    else if (gap <= threshold * result.gap_scale) result.weak.push_back(i);
    else result.inactive.push_back(i);
  }
  return result;
}

SensitivityProblem::SensitivityProblem(const FetiProblem& problem, const FetiResult& state, double threshold)
    : problem_(problem), u_(state.u), lambda_(state.lambda) {
  const ThreadLimit limit(problem.settings().threads);
  Stopwatch clock;
  if (state.lambda.size() != problem.dual_dimension() || state.u.size() != problem.inputs().size())
    throw InputError("P: the solution does not belong to this problem (call fetiSolve first)");
  for (ContactKind kind : problem.constraints().contact_kinds) {
    require(kind, Feature::sensitivity, problem.space_dimension(), "P");
    if (problem.has_friction()) require(kind, Feature::sensitivity_with_friction, problem.space_dimension(), "P");
  }
  classification_ = classify_contact(problem, state, threshold);
  const Constraints& full = problem.constraints();
  Constraints rows;  // E, then S as equalities, then W as inequalities; right-hand sides per direction
  const auto keep = [&](int i) {
    for (int k = full.row_start[static_cast<size_t>(i)]; k < full.row_start[static_cast<size_t>(i) + 1]; ++k)
      rows.entries.push_back(full.entries[static_cast<size_t>(k)]);
    rows.row_start.push_back(static_cast<int>(rows.entries.size()));
    rows.rhs.push_back(0.0);
    rows.kind.push_back(full.kind[static_cast<size_t>(i)]);
    kept_.push_back(i);
  };
  for (int i = 0; i < full.equality_rows; ++i) keep(i);
  for (int i : classification_.strong) keep(i);
  rows.equality_rows = static_cast<int>(kept_.size());
  for (int i : classification_.weak) {
    keep(i);
    rows.geometry.push_back(full.geometry[static_cast<size_t>(i - full.equality_rows)]);
  }
  try {
    system_ = std::make_unique<DualSystem>(problem.subdomains(), problem.global_ids(), problem.owners(),
                                           problem.bodies(), std::move(rows), problem.settings().threads,
                                           problem.communicator());
  } catch (const InputError& error) {
    throw InputError(std::string("sensitivity: without its inactive contact rows the problem is singular, ") +
                     "so u has no unique derivative: " + error.what());
  }
  // Preconditioned as the state's solves are (a direction took twice the state's Hessian
  // multiplications without), by the lumped preconditioner also behind a Dirichlet one: it
  // factorizes nothing, where the Dirichlet one would factorize each K_ii of these rows anew.
  if (problem.settings().preconditioner != DualPreconditioner::none)
    problem.precondition(*system_, DualPreconditioner::lumped);
  counters_.setup_seconds = problem.communicator().max(clock.seconds());
}

void SensitivityProblem::check(const DesignDerivative& d) const {
  const auto& inputs = problem_.inputs();
  const auto& ids = problem_.global_ids();
  collectively(problem_.communicator(), [&] {
    const auto count_ok = [&](size_t n) { return n == 0 || n == inputs.size(); };
    if (!count_ok(d.dK.size()) || !count_ok(d.df.size()) || !count_ok(d.velocity_x.size()) ||
        !count_ok(d.velocity_y.size()) || !count_ok(d.velocity_z.size()) || !count_ok(d.dgap.size()))
      throw InputError("dK, dF, velocityX, velocityY, velocityZ, dGap: need one entry per subdomain");
    if (problem_.space_dimension() != 3)
      for (const auto& v : d.velocity_z)
        if (!v.empty()) throw InputError("velocityZ: the problem is plane (fetiSetup without Z=); give velocityX, velocityY");
    // In 3D a velocity without its z part would be read as moving in the plane only, and
    // velocityZ alone as moving along z only, silently: all three or none.
    const auto given = [](const std::vector<std::vector<double>>& field) {
      return std::any_of(field.begin(), field.end(), [](const auto& v) { return !v.empty(); });
    };
    if (problem_.space_dimension() == 3) {
      const std::pair<const std::vector<std::vector<double>>*, const char*> components[] = {
          {&d.velocity_x, "velocityX"}, {&d.velocity_y, "velocityY"}, {&d.velocity_z, "velocityZ"}};
      const bool any = given(d.velocity_x) || given(d.velocity_y) || given(d.velocity_z);
      for (const auto& [field, name] : components)
        if (any && !given(*field))
          throw InputError(std::string(name) + ": missing: in three dimensions give velocityX, velocityY and velocityZ "
                           "together (zeros for a component that does not move)");
    }
    for (size_t k = 0; k < inputs.size(); ++k) {
      const Eigen::Index n = inputs[k].K.rows();
      const int s = ids[k];
      if (!d.dK.empty() && d.dK[k].size() > 0) {
        check_size(d.dK[k].rows() == n && d.dK[k].cols() == n, "dK", s, "must be " + std::to_string(n) + " x " +
                   std::to_string(n) + " like K[" + std::to_string(s) + "] (or empty)");
        for (Eigen::Index j = 0; j < d.dK[k].outerSize(); ++j)
          for (SparseMatrix::InnerIterator it(d.dK[k], j); it; ++it)
            check_size(std::isfinite(it.value()), "dK", s, "has a non-finite entry");
      }
      if (!d.df.empty() && d.df[k].size() > 0)
        check_size(d.df[k].size() == n && d.df[k].allFinite(), "dF", s, "needs " + std::to_string(n) + " finite entries (or none)");
      const std::pair<const std::vector<std::vector<double>>*, const char*> fields[] = {
          {&d.velocity_x, "velocityX"}, {&d.velocity_y, "velocityY"}, {&d.velocity_z, "velocityZ"}, {&d.dgap, "dGap"}};
      for (const auto& [v, name] : fields) {
        if (v->empty() || (*v)[k].empty()) continue;
        bool finite = true;
        for (double x : (*v)[k]) finite = finite && std::isfinite(x);
        check_size(static_cast<Eigen::Index>((*v)[k].size()) == n && finite, name, s,
                   "needs " + std::to_string(n) + " finite entries, one per dof (or none)");
      }
    }
  });
}

SensitivityProblem::DirectionData SensitivityProblem::direction_data(const DesignDerivative& d) const {
  check(d);
  const Constraints& full = problem_.constraints();
  const auto& inputs = problem_.inputs();
  const auto& ids = problem_.global_ids();
  // The rows whose derivatives enter: the kept ones (c~) and those carrying a force (B''lambda).
  std::vector<bool> in_use(full.geometry.size(), false);
  for (size_t r = 0; r < in_use.size(); ++r) in_use[r] = lambda_[full.equality_rows + static_cast<int>(r)] != 0;
  for (size_t j = static_cast<size_t>(full.equality_rows); j < kept_.size(); ++j)
    in_use[static_cast<size_t>(kept_[j] - full.equality_rows)] = true;
  const std::vector<RowDerivative> rows = contact_row_derivatives(
      full, ids, {&d.velocity_x, &d.velocity_y, &d.velocity_z}, in_use, problem_.communicator());
  std::map<int, size_t> local_index;
  for (size_t k = 0; k < ids.size(); ++k) local_index[ids[k]] = k;

  DirectionData data;
  for (const RowDerivative& row : rows) data.one_sided_rows += row.one_sided ? 1 : 0;
  for (size_t k = 0; k < inputs.size(); ++k) {
    Vec fbar = !d.df.empty() && d.df[k].size() > 0 ? d.df[k] : Vec::Zero(inputs[k].K.rows());
    if (!d.dK.empty() && d.dK[k].size() > 0) fbar.noalias() -= d.dK[k] * u_[k];  // f' - K'u
    data.fbar.push_back(std::move(fbar));
  }
  for (size_t r = 0; r < rows.size(); ++r) {  // - B''lambda
    const double lambda = lambda_[full.equality_rows + static_cast<int>(r)];
    if (lambda == 0) continue;
    for (const ConstraintEntry& e : rows[r].entries)
      if (const auto it = local_index.find(e.subdomain); it != local_index.end())
        data.fbar[it->second][e.dof] -= e.coefficient * lambda;
  }

  // c~ = c' - B'u on the kept contact rows (gluing and Dirichlet rows do not move): the
  // products B'_ij u_j, and minus the gap's own change (entry -1), are gathered and summed
  // in entry order, the same on every rank.
  std::vector<double> products;
  for (size_t j = static_cast<size_t>(full.equality_rows); j < kept_.size(); ++j) {
    const size_t row = static_cast<size_t>(kept_[j] - full.equality_rows);
    const auto& entries = rows[row].entries;
    for (size_t k = 0; k < entries.size(); ++k)
      if (const auto it = local_index.find(entries[k].subdomain); it != local_index.end())
        products.insert(products.end(), {double(j), double(k), entries[k].coefficient * u_[it->second][entries[k].dof]});
    const auto [gap_subdomain, gap_dof] = full.geometry[row]->slave_dof();
    if (const auto it = local_index.find(gap_subdomain); it != local_index.end() && !d.dgap.empty() &&
                                                          !d.dgap[it->second].empty())
      products.insert(products.end(), {double(j), -1.0, -d.dgap[it->second][static_cast<size_t>(gap_dof)]});
  }
  const std::vector<double> all = problem_.communicator().allgather(products);
  std::vector<std::vector<std::pair<int, double>>> by_row(kept_.size());
  for (size_t p = 0; p + 3 <= all.size(); p += 3)
    by_row[static_cast<size_t>(all[p])].emplace_back(static_cast<int>(all[p + 1]), all[p + 2]);
  data.c = Vec::Zero(static_cast<Eigen::Index>(kept_.size()));
  for (size_t j = static_cast<size_t>(full.equality_rows); j < kept_.size(); ++j) {
    std::sort(by_row[j].begin(), by_row[j].end());
    double value = rows[static_cast<size_t>(kept_[j] - full.equality_rows)].rhs;
    for (const auto& [entry, product] : by_row[j]) value -= product;
    data.c[static_cast<Eigen::Index>(j)] = value;
  }
  return data;
}

SensitivityResult SensitivityProblem::direct(const DesignDerivative& direction, const DualSolveSettings& settings) {
  return std::move(direct(std::vector<DesignDerivative>{direction}, settings).front());
}

std::vector<SensitivityResult> SensitivityProblem::direct(const std::vector<DesignDerivative>& directions,
                                                          const DualSolveSettings& settings) {
  const ThreadLimit limit(problem_.settings().threads);
  Stopwatch clock;
  std::vector<DirectionData> d;
  std::vector<DualData> dual;
  for (const DesignDerivative& direction : directions) {
    d.push_back(direction_data(direction));
    dual.push_back(system_->data(problem_.operator_loads(d.back().fbar, true), d.back().c));
  }
  DualSolveSettings relative_to_data = settings;
  relative_to_data.reference_includes_data = true;  // fbar = f' - K'u is nearly self-equilibrated
  relative_to_data.stopping = StoppingTest::seed;
  std::vector<DualSolution> solutions = system_->solve(dual, relative_to_data);
  std::vector<SensitivityResult> results(directions.size());
  for (size_t j = 0; j < directions.size(); ++j) {
    SensitivityResult& result = results[j];
    DualSolution& s = solutions[j];
    result.status = s.status;
    result.path = s.path;
    result.counts = s.counts;
    result.kkt = kkt_residuals(problem_.inputs(), d[j].fbar, d[j].c, true, system_->local(), system_->F(),
                               system_->constraints(), problem_.variant() == FetiVariant::feti1, s.u, s.lambda,
                               problem_.communicator());
    result.status = checked_status(result.status, result.kkt, settings.tolerance);
    result.one_sided_rows = d[j].one_sided_rows;
    if (result.one_sided_rows > 0 && result.status == SolveStatus::converged) result.status = SolveStatus::weakly_active;
    counters_.hessian += result.counts.hessian + result.counts.hessian_norm_estimate;
    const Constraints& full = problem_.constraints();
    result.contact_multipliers = Vec::Zero(full.inequality_rows());
    for (size_t r = static_cast<size_t>(full.equality_rows); r < kept_.size(); ++r)
      result.contact_multipliers[kept_[r] - full.equality_rows] = s.lambda[static_cast<Eigen::Index>(r)];
    result.z = std::move(s.u);
    result.multipliers = std::move(s.lambda);
  }
  const double seconds = problem_.communicator().max(clock.seconds());
  for (SensitivityResult& result : results) result.seconds = seconds / static_cast<double>(directions.size());
  counters_.directions += static_cast<int>(directions.size());
  counters_.seconds += seconds;
  if (!results.empty()) {
    counters_.last = results.back();
    counters_.last.z.clear();
    counters_.last.multipliers.resize(0);
    counters_.last.contact_multipliers.resize(0);
  }
  return results;
}

AdjointResult SensitivityProblem::adjoint(const std::vector<Vec>& dJdu, const DualSolveSettings& settings,
                                          const Vec& dJdlambda) {
  const ThreadLimit limit(problem_.settings().threads);
  Stopwatch clock;
  adjoint_.reset();
  AdjointResult result;
  const auto& inputs = problem_.inputs();
  const Constraints& full = problem_.constraints();
  collectively(problem_.communicator(), [&] {
    if (dJdu.size() != inputs.size()) throw InputError("dJdu: needs one entry per subdomain");
    for (size_t k = 0; k < inputs.size(); ++k)
      check_size(dJdu[k].size() == inputs[k].K.rows() && dJdu[k].allFinite(), "dJdu", problem_.global_ids()[k],
                 "needs " + std::to_string(inputs[k].K.rows()) + " finite entries");
    if (dJdlambda.size() != 0 && (dJdlambda.size() != full.inequality_rows() || !dJdlambda.allFinite()))
      throw InputError("dJdlambda: needs " + std::to_string(full.inequality_rows()) +
                       " finite entries, one per contact row (fetiContact's order), got " +
                       std::to_string(dJdlambda.size()));
  });
  if (!classification_.weak.empty()) {
    result.status = SolveStatus::weakly_active;
    result.path = system_->path();
    counters_.adjoint = result;
    return result;
  }
  Vec rhs = Vec::Zero(system_->rows());  // B w = dJ/dlambda on the kept contact rows
  if (dJdlambda.size() != 0)
    for (size_t r = static_cast<size_t>(full.equality_rows); r < kept_.size(); ++r)
      rhs[static_cast<Eigen::Index>(r)] = dJdlambda[kept_[r] - full.equality_rows];
  DualSolveSettings relative_to_data = settings;
  relative_to_data.stopping = StoppingTest::seed;
  DualSolution s = system_->solve(system_->data(problem_.operator_loads(dJdu, true), rhs), relative_to_data);
  result.status = s.status;
  result.path = s.path;
  result.counts = s.counts;
  result.kkt = kkt_residuals(inputs, dJdu, rhs, true, system_->local(), system_->F(), system_->constraints(),
                             problem_.variant() == FetiVariant::feti1, s.u, s.lambda, problem_.communicator());
  result.status = checked_status(result.status, result.kkt, settings.tolerance);
  // Stopped at round-off (stagnated: checked_status keeps that verdict only within the
  // round-off ceiling): as accurate as the data allow, and usable like the state.
  if (result.status == SolveStatus::converged || result.status == SolveStatus::stagnated) adjoint_ = std::move(s);
  result.seconds = problem_.communicator().max(clock.seconds());
  counters_.adjoint_solves += 1;
  counters_.adjoint = result;
  return result;
}

double SensitivityProblem::adjoint_gradient(const DesignDerivative& direction) {
  if (!adjoint_)
    throw InputError("P: no adjoint solution (call fetiAdjoint first; its solve must converge or stop at round-off)");
  const ThreadLimit limit(problem_.settings().threads);
  Stopwatch clock;
  const DirectionData d = direction_data(direction);
  std::vector<double> local;  // (subdomain, w_s'fbar_s)
  for (size_t k = 0; k < d.fbar.size(); ++k)
    local.insert(local.end(), {double(problem_.global_ids()[k]), adjoint_->u[k].dot(d.fbar[k])});
  const double value = ordered_sum(local, 2, problem_.communicator()) + adjoint_->lambda.dot(d.c);
  counters_.adjoint.one_sided_rows = d.one_sided_rows;
  counters_.adjoint_gradients += 1;
  counters_.adjoint_gradient_seconds += problem_.communicator().max(clock.seconds());
  return value;
}

}  // namespace ffeti
