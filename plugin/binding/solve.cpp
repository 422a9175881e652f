// fetiSolve (the dual solve and the primal recovery) and what a script reads of its outcome:
// fetiInfo, fetiHistory, fetiReport.
#include "binding/arguments.h"
#include "binding/convert.h"
#include "binding/functions.h"
#include "binding/handles.h"

#include "base/errors.h"
#include "service/progress_monitor.h"
#include "service/statistics.h"
#include "service/sensitivity_statistics.h"

#include <cstdio>

namespace ffeti::binding {
namespace {

// ---- int status = fetiSolve(P, U, lambda=..., tol=..., maxit=..., algorithm=..., verbosity=...)
class FetiSolve : public WithNamedArguments {
 public:
  typedef long Result;
  static NamedParameters name_param;
  Expression id, U;

  explicit FetiSolve(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
    id = to<long>(args[0]);
    U = to<KN<KN<double>>*>(args[1]);
  }
  static ArrayOfaType typeargs() { return ArrayOfaType(atype<long>(), atype<KN<KN<double>>*>()); }
  static E_F0* f(const basicAC_F0& args) { return new FetiSolve(args); }

  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiSolve", [&] { return solve(stack); }));
  }

 private:
  // Named parameters by position in name_param: these, then the solve options.
  enum Named { kLambda, kHistory, kStart, kOptions };

  long solve(Stack stack) const {
    Handle& h = handle(GetAny<long>((*id)(stack)));
    const SolverSettings solver = given_options(OptionScope::solve, &nargs[kOptions], stack).solve(h.problem->variant());
    DualSolveSettings settings = solver.solve;
    const int verbosity = solver.verbosity;
    if (auto* start = optional_pointer<KN<double>>(nargs[kStart], stack)) settings.start = to_vec(*start);
    settings.monitor = h.history.start(progress_monitor(verbosity, h.problem->communicator()));
    h.sensitivity.reset();
    h.result.reset();
    h.tolerance = settings.tolerance;
    h.result = h.problem->solve(settings);
    const FetiResult& r = *h.result;
    if (nargs[kHistory])  // written by rank 0; a failure raised on every rank alike
      collectively(h.problem->communicator(), [&] {
        if (h.problem->communicator().rank() == 0) h.history.write_csv(optional_string(nargs[kHistory], stack, ""));
      });
    auto& u = *GetAny<KN<KN<double>>*>((*U)(stack));
    const std::vector<int>& ids = h.problem->global_ids();
    u.resize(h.problem->subdomain_count());
    for (long s = 0; s < u.N(); ++s) u[s].resize(0);  // subdomains of other ranks stay empty
    for (size_t k = 0; k < r.u.size(); ++k) copy_to(r.u[k], u[ids[k]]);
    if (auto* lambda = optional_pointer<KN<double>>(nargs[kLambda], stack)) copy_to(r.lambda, *lambda);
    if (verbosity >= 1 && h.problem->communicator().rank() == 0)
      std::printf("ffeti: %s after %d Hessian multiplications (%d outer), path %s, ||gP||/||b|| %.2e, "
                  "KKT check %.2e\n",
                  to_string(r.status).c_str(), r.counts.hessian, r.counts.outer, path_name(r.path),
                  r.gradient_norm / r.gradient_reference, r.violation);
    if (verbosity >= 1 && h.problem->communicator().rank() == 0 && r.friction_iterations > 0)
      std::printf("ffeti: friction: %d Tresca solves (Hessian multiplications %s), last change of the bounds %.2e\n",
                  r.friction_iterations, friction_counts(r).c_str(), r.friction_bound_change);
    // Whatever the verbosity: which body friction cannot hold.
    if (h.problem->communicator().rank() == 0 && r.status == SolveStatus::infeasible && r.sliding_body >= 0)
      std::printf("ffeti: fetiSolve: infeasible: no contact forces within their friction cones balance the loads on "
                  "body %d, which would slide away (status 4, distance from equilibrium %.2e of the loads)\n",
                  r.sliding_body, r.equality_reference > 0 ? r.equality_norm / r.equality_reference : 0.0);
    // Whatever the verbosity: a tol below what round-off allows is said, with what was reached.
    if (r.status == SolveStatus::stagnated)  // violation: the stop test's measure (-1 where none ran, e.g. stop="seed")
      say_stagnated(h, "fetiSolve", r.counts.hessian, r.violation >= 0 ? r.violation : r.kkt.max(), h.tolerance);
    // Whatever the verbosity: an answer whose slaves pass through the master is not silent.
    if (h.problem->communicator().rank() == 0 && r.beyond_reach.penetrating > 0)
      std::printf("ffeti: WARNING fetiSolve: %s\n", r.beyond_reach.warning().c_str());
    std::fflush(stdout);
    return status_code(r.status);
  }
};

NamedParameters FetiSolve::name_param = named_parameters(
    {{"lambda", &typeid(KN<double>*)}, {"history", &typeid(std::string*)}, {"start", &typeid(KN<double>*)}},
    OptionScope::solve);

// int rows = fetiHistory(P, key, values): one column of the last fetiSolve's convergence
// history (time, hessian, gradient, equality, active, iteration) into values.
long feti_history(const long& id, std::string* const& key, KN<double>* const& values) {
  return guarded("fetiHistory", [&] {
    const Handle& h = handle(id);
    if (!h.result) throw InputError("P: no solve yet: call fetiSolve first");
    const std::vector<double> column = h.history.column(*key);
    values->resize(static_cast<long>(column.size()));
    for (size_t i = 0; i < column.size(); ++i) (*values)[static_cast<long>(i)] = column[i];
    return static_cast<long>(column.size());
  });
}

double feti_info(const long& id, std::string* const& key_given) {
  return guarded("fetiInfo", [&] {
    // "settle" counted CG steps while fetiSolve's settle= counts rounds: renamed, old name kept.
    static bool settle_deprecation_said = false;
    const std::string* key = key_given;
    const std::string renamed = "settle_steps";
    if (*key_given == "settle") {
      if (!settle_deprecation_said) std::printf("ffeti: fetiInfo(P, \"settle\") is deprecated; use \"settle_steps\"\n");
      settle_deprecation_said = true;
      key = &renamed;
    }
    const Handle& h = handle(id);
    const FetiResult* result = h.result ? &*h.result : nullptr;
    std::string known;
    Statistics all = statistics(*h.problem, result);
    if (h.sensitivity) {
      const Statistics sens = statistics(*h.sensitivity);
      all.insert(all.end(), sens.begin(), sens.end());
    }
    for (const auto& [name, value] : all) {
      if (name == *key) return value;
      known += " " + name;
    }
    throw InputError("key: \"" + *key + "\" is not a statistic" +
                     (result ? "" : " before fetiSolve") + "; known keys:" + known);
  });
}

std::string* feti_report(Stack stack, const long& id) {
  const std::string text = guarded("fetiReport", [&] {
    const Handle& h = handle(id);
    const std::string state = format_report(*h.problem, h.result ? &*h.result : nullptr);
    return h.sensitivity ? state + " " + format_report(*h.sensitivity) : state;
  });
  return Add2StackOfPtr2Free(stack, new std::string(text));
}

}  // namespace

void add_solve_functions() {
  Global.Add("fetiSolve", "(", new OneOperatorCode<FetiSolve>());
  Global.Add("fetiInfo", "(", new OneOperator2_<double, long, std::string*>(feti_info));
  Global.Add("fetiHistory", "(", new OneOperator3_<long, long, std::string*, KN<double>*>(feti_history));
  Global.Add("fetiReport", "(", new OneOperator1s_<std::string*, long>(feti_report));
}

}  // namespace ffeti::binding
