// The design sensitivities of a solved state (seed eq. 12): fetiSensitivity (direct, one
// solve per design direction), fetiAdjoint and fetiAdjointGradient (one solve per cost).
#include "binding/arguments.h"
#include "binding/convert.h"
#include "binding/functions.h"
#include "binding/handles.h"

#include "base/errors.h"
#include "service/progress_monitor.h"
#include "service/statistics.h"

#include <algorithm>
#include <cstdio>

namespace ffeti::binding {
namespace {

// ---- sensitivities (seed eq. 12) -------------------------------------------------------

/// The sensitivity problem of the handle's last solution with classification threshold
/// `threshold`, built on first use and kept for every later direction.
SensitivityProblem& sensitivity_problem(Handle& h, double threshold) {
  if (!h.result) throw InputError("P: no solution yet: call fetiSolve first");
  // A state stopped at round-off (stagnated) is as accurate as its data allow: it has a derivative.
  if (h.result->status != SolveStatus::converged && h.result->status != SolveStatus::stagnated)
    throw InputError("P: the last fetiSolve did not converge (" + to_string(h.result->status) +
                     "): its solution has no derivative worth the name; solve it to convergence first");
  if (!h.sensitivity || h.sensitivity->classification().threshold != threshold)
    h.sensitivity = std::make_unique<SensitivityProblem>(*h.problem, *h.result, threshold);
  return *h.sensitivity;
}

/// Said whatever the verbosity (rank 0): `rows` contact rows moved by the design have a
/// one-sided derivative, so `what` holds one of its one-sided values.
void warn_one_sided(const Handle& h, int rows, const char* function, const char* what) {
  if (rows == 0 || h.problem->communicator().rank() != 0) return;
  std::printf("ffeti: WARNING %s: %d node-to-face contact rows the design moves sit on an edge between master "
              "faces that bend against each other: their derivative is one-sided, and %s is one of its one-sided "
              "values (mortar contact, contactSlaveFaces=, has no such kink: use it for shape gradients on "
              "non-matching meshes)\n",
              function, rows, what);
  std::fflush(stdout);
}

/// Default threshold below which a multiplier counts as zero, relative to max lambda.
double default_threshold(const Handle& h) { return default_classification_threshold(h.tolerance); }

/// Design directions from the script: for k directions, entry j * S + s of dK, dF (empty
/// entries: zero), of the node velocities velocityX, velocityY, velocityZ (absent: the contact
/// geometry does not move) and of the gap derivatives dGap (absent: the gaps do not change)
/// belongs to direction j and subdomain s (S subdomains). Only this rank's subdomains are read.
std::vector<DesignDerivative> design_directions(const FetiProblem& problem, KN<Matrice_Creuse<double>>* dK,
                                                KN<KN<double>>* dF, KN<KN<double>>* vx, KN<KN<double>>* vy,
                                                KN<KN<double>>* vz, KN<KN<double>>* dgap) {
  const long count = problem.subdomain_count();
  const long k = dK->N() / count;
  std::vector<DesignDerivative> directions(static_cast<size_t>(std::max(k, 0L)));
  collectively(problem.communicator(), [&] {
    if (k < 1 || dK->N() != k * count)
      throw InputError("dK: has " + std::to_string(dK->N()) + " entries: needs " + std::to_string(count) +
                       " per design direction (one per subdomain)");
    const std::pair<const char*, long> sizes[] = {{"dF", dF->N()},
                                                  {"velocityX", vx ? vx->N() : k * count},
                                                  {"velocityY", vy ? vy->N() : k * count},
                                                  {"velocityZ", vz ? vz->N() : k * count},
                                                  {"dGap", dgap ? dgap->N() : k * count}};
    for (const auto& [name, n] : sizes)
      if (n != k * count)
        throw InputError(std::string(name) + ": has " + std::to_string(n) + " entries, dK has " +
                         std::to_string(k * count) + " (" + std::to_string(k) + " directions of " +
                         std::to_string(count) + " subdomains)");
    for (long j = 0; j < k; ++j) {
      DesignDerivative& d = directions[static_cast<size_t>(j)];
      for (int s : problem.global_ids()) {
        const long e = j * count + s;
        Matrice_Creuse<double>& matrix = (*dK)[e];
        const bool empty = !matrix.pHM() || matrix.pHM()->n == 0;
        d.dK.push_back(empty ? SparseMatrix() : to_sparse(matrix, "dK[" + std::to_string(e) + "]"));
        d.df.push_back(to_vec((*dF)[e]));
        if (vx) d.velocity_x.push_back(to_std((*vx)[e]));
        if (vy) d.velocity_y.push_back(to_std((*vy)[e]));
        if (vz) d.velocity_z.push_back(to_std((*vz)[e]));
        if (dgap) d.dgap.push_back(to_std((*dgap)[e]));
      }
    }
  });
  return directions;
}

/// The sensitivity functions' options (scope sensitivity of the registry, named_parameters'
/// order from `options_nargs`), with the defaults that follow the state's solve.
struct SensitivityCall {
  DualSolveSettings settings;  // the sensitivity's own path and test: only tol, maxit, verbosity from the script
  double threshold = 0;        // activeTol
};

SensitivityCall sensitivity_call(const Handle& h, const Expression* options_nargs, Stack stack) {
  const GivenOptions options = given_options(OptionScope::sensitivity, options_nargs, stack);
  const SolverSettings given = options.sensitivity();
  SensitivityCall call;
  call.settings.tolerance = options.has("tol") ? given.solve.tolerance : h.tolerance;
  call.settings.max_hessian = given.solve.max_hessian;
  call.settings.monitor = progress_monitor(given.verbosity, h.problem->communicator());
  call.threshold = given.active_tolerance > 0 ? given.active_tolerance : default_threshold(h);
  return call;
}

// int status = fetiSensitivity(P, dK, dF, Z, velocityX=, velocityY=, velocityZ=, tol=, maxit=, activeTol=, verbosity=,
//                              dGap=, dLambda=): dLambda[j] receives lambda' of direction j per contact row
// (fetiContact's order; 0 on inactive rows), on every rank.
class FetiSensitivity : public WithNamedArguments {
 public:
  typedef long Result;
  static NamedParameters name_param;
  enum Named { kVelocityX, kVelocityY, kDGap, kDLambda, kVelocityZ, kOptions };
  Expression id, dK, dF, Z;

  explicit FetiSensitivity(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
    id = to<long>(args[0]);
    dK = to<KN<Matrice_Creuse<double>>*>(args[1]);
    dF = to<KN<KN<double>>*>(args[2]);
    Z = to<KN<KN<double>>*>(args[3]);
  }
  static ArrayOfaType typeargs() {
    return ArrayOfaType(atype<long>(), atype<KN<Matrice_Creuse<double>>*>(), atype<KN<KN<double>>*>(),
                        atype<KN<KN<double>>*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FetiSensitivity(args); }

  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiSensitivity", [&] {
      Handle& h = handle(GetAny<long>((*id)(stack)));
      const SensitivityCall call = sensitivity_call(h, &nargs[kOptions], stack);
      SensitivityProblem& sens = sensitivity_problem(h, call.threshold);
      const std::vector<DesignDerivative> directions = design_directions(
          *h.problem, GetAny<KN<Matrice_Creuse<double>>*>((*dK)(stack)), GetAny<KN<KN<double>>*>((*dF)(stack)),
          optional_pointer<KN<KN<double>>>(nargs[kVelocityX], stack),
          optional_pointer<KN<KN<double>>>(nargs[kVelocityY], stack),
          optional_pointer<KN<KN<double>>>(nargs[kVelocityZ], stack), optional_pointer<KN<KN<double>>>(nargs[kDGap], stack));
      const std::vector<SensitivityResult> r = sens.direct(directions, call.settings);
      if (auto* dLambda = optional_pointer<KN<KN<double>>>(nargs[kDLambda], stack)) {
        dLambda->resize(static_cast<long>(r.size()));
        for (size_t j = 0; j < r.size(); ++j) copy_to(r[j].contact_multipliers, (*dLambda)[static_cast<long>(j)]);
      }
      auto& z = *GetAny<KN<KN<double>>*>((*Z)(stack));
      const std::vector<int>& ids = h.problem->global_ids();
      const long count = h.problem->subdomain_count();
      z.resize(count * static_cast<long>(r.size()));
      for (long e = 0; e < z.N(); ++e) z[e].resize(0);  // subdomains of other ranks stay empty
      int one_sided = 0;
      for (const SensitivityResult& result : r) one_sided = std::max(one_sided, result.one_sided_rows);
      warn_one_sided(h, one_sided, "fetiSensitivity", "the derivative returned (status 6)");
      SolveStatus worst = SolveStatus::converged;
      for (size_t j = 0; j < r.size(); ++j) {
        for (size_t k = 0; k < r[j].z.size(); ++k) copy_to(r[j].z[k], z[static_cast<long>(j) * count + ids[k]]);
        // Any failure outranks a stop at round-off, which outranks converged.
        if (worst == SolveStatus::converged || (worst == SolveStatus::stagnated && r[j].status != SolveStatus::converged))
          worst = r[j].status;
        if (r[j].status == SolveStatus::stagnated)
          say_stagnated(h, "fetiSensitivity", r[j].counts.hessian, r[j].kkt.max(), call.settings.tolerance);
      }
      return static_cast<long>(status_code(worst));
    }));
  }
};

NamedParameters FetiSensitivity::name_param = named_parameters(
    {{"velocityX", &typeid(KN<KN<double>>*)}, {"velocityY", &typeid(KN<KN<double>>*)},
     {"dGap", &typeid(KN<KN<double>>*)}, {"dLambda", &typeid(KN<KN<double>>*)},
     {"velocityZ", &typeid(KN<KN<double>>*)}},
    OptionScope::sensitivity);

// int status = fetiAdjoint(P, dJdu, tol=, maxit=, activeTol=, verbosity=, w=, dJdlambda=): 6
// (weakly_active) when some contact row is weakly active: use fetiSensitivity then. w=
// receives the adjoint displacement per subdomain (this rank's; the others empty), as
// fetiSolve's U. dJdlambda: the cost's derivative per contact row (fetiContact's order).
class FetiAdjoint : public WithNamedArguments {
 public:
  typedef long Result;
  static NamedParameters name_param;
  enum Named { kW, kDJdlambda, kOptions };
  Expression id, dJdu;

  explicit FetiAdjoint(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
    id = to<long>(args[0]);
    dJdu = to<KN<KN<double>>*>(args[1]);
  }
  static ArrayOfaType typeargs() { return ArrayOfaType(atype<long>(), atype<KN<KN<double>>*>()); }
  static E_F0* f(const basicAC_F0& args) { return new FetiAdjoint(args); }

  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiAdjoint", [&] {
      Handle& h = handle(GetAny<long>((*id)(stack)));
      const SensitivityCall call = sensitivity_call(h, &nargs[kOptions], stack);
      SensitivityProblem& sens = sensitivity_problem(h, call.threshold);
      const auto& g = *GetAny<KN<KN<double>>*>((*dJdu)(stack));
      std::vector<Vec> gradient;
      collectively(h.problem->communicator(), [&] {
        if (g.N() != h.problem->subdomain_count())
          throw InputError("dJdu: has " + std::to_string(g.N()) + " entries for " +
                           std::to_string(h.problem->subdomain_count()) + " subdomains");
        for (int s : h.problem->global_ids()) gradient.push_back(to_vec(g[s]));
      });
      const Vec dJdlambda = nargs[kDJdlambda] ? to_vec(*GetAny<KN<double>*>((*nargs[kDJdlambda])(stack))) : Vec();
      const AdjointResult r = sens.adjoint(gradient, call.settings, dJdlambda);
      if (r.status == SolveStatus::weakly_active && h.problem->communicator().rank() == 0) {
        // A script that ignores status 6 would lose the contact part of its gradient.
        std::printf("ffeti: WARNING fetiAdjoint: %zu contact rows are weakly active (force and gap both about 0): "
                    "the derivative is only directional there, so no adjoint was solved (status 6); use "
                    "fetiSensitivity (the direct mode) for this design\n",
                    sens.classification().weak.size());
        std::fflush(stdout);
      }
      if (r.status == SolveStatus::stagnated)
        say_stagnated(h, "fetiAdjoint", r.counts.hessian, r.kkt.max(), call.settings.tolerance);
      if (auto* w = optional_pointer<KN<KN<double>>>(nargs[kW], stack)) {
        const std::vector<int>& ids = h.problem->global_ids();
        w->resize(h.problem->subdomain_count());
        for (long s = 0; s < w->N(); ++s) (*w)[s].resize(0);
        if (const std::vector<Vec>* solution = sens.adjoint_displacement())
          for (size_t k = 0; k < solution->size(); ++k) copy_to((*solution)[k], (*w)[ids[k]]);
      }
      return static_cast<long>(status_code(r.status));
    }));
  }
};

NamedParameters FetiAdjoint::name_param = named_parameters(
    {{"w", &typeid(KN<KN<double>>*)}, {"dJdlambda", &typeid(KN<double>*)}}, OptionScope::sensitivity);

// real dJ = fetiAdjointGradient(P, dK, dF, velocityX=, velocityY=, velocityZ=, dGap=): w'fbar + mu'c~ for
// one direction, after fetiAdjoint; no dual solve.
class FetiAdjointGradient : public WithNamedArguments {
 public:
  typedef double Result;
  static NamedParameters name_param;
  Expression id, dK, dF;

  explicit FetiAdjointGradient(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
    id = to<long>(args[0]);
    dK = to<KN<Matrice_Creuse<double>>*>(args[1]);
    dF = to<KN<KN<double>>*>(args[2]);
  }
  static ArrayOfaType typeargs() {
    return ArrayOfaType(atype<long>(), atype<KN<Matrice_Creuse<double>>*>(), atype<KN<KN<double>>*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FetiAdjointGradient(args); }

  AnyType operator()(Stack stack) const {
    return SetAny<double>(guarded("fetiAdjointGradient", [&] {
      Handle& h = handle(GetAny<long>((*id)(stack)));
      if (!h.sensitivity) throw InputError("P: no adjoint solution: call fetiAdjoint first");
      const std::vector<DesignDerivative> d = design_directions(
          *h.problem, GetAny<KN<Matrice_Creuse<double>>*>((*dK)(stack)), GetAny<KN<KN<double>>*>((*dF)(stack)),
          optional_pointer<KN<KN<double>>>(nargs[0], stack), optional_pointer<KN<KN<double>>>(nargs[1], stack),
          optional_pointer<KN<KN<double>>>(nargs[3], stack), optional_pointer<KN<KN<double>>>(nargs[2], stack));
      if (d.size() != 1)  // the same on every rank: the sizes were checked collectively
        throw InputError("dK: " + std::to_string(d.size()) + " design directions: fetiAdjointGradient takes one (" +
                         std::to_string(h.problem->subdomain_count()) + " entries)");
      const double gradient = h.sensitivity->adjoint_gradient(d.front());
      warn_one_sided(h, h.sensitivity->counters().adjoint.one_sided_rows, "fetiAdjointGradient",
                     "the value returned (fetiInfo key adjoint_one_sided counts these rows)");
      return gradient;
    }));
  }
};

NamedParameters FetiAdjointGradient::name_param = {
    {"velocityX", &typeid(KN<KN<double>>*)}, {"velocityY", &typeid(KN<KN<double>>*)},
    {"dGap", &typeid(KN<KN<double>>*)}, {"velocityZ", &typeid(KN<KN<double>>*)}};

}  // namespace

void add_sensitivity_functions() {
  Global.Add("fetiSensitivity", "(", new OneOperatorCode<FetiSensitivity>());
  Global.Add("fetiAdjoint", "(", new OneOperatorCode<FetiAdjoint>());
  Global.Add("fetiAdjointGradient", "(", new OneOperatorCode<FetiAdjointGradient>());
}

}  // namespace ffeti::binding
