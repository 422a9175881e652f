// FreeFEM binding of ffeti: converts script data to core types, keeps problems behind
// integer handles between calls, prints progress on request, turns core errors into
// FreeFEM errors. No numerics here: everything numerical lives in plugin/core.
#include "ff++.hpp"

#include "binding_convert.h"
#include "feti/contact_pressure.h"
#include "feti/contact_transfer.h"
#include "feti/errors.h"
#include "feti/feti_problem.h"
#include "feti/options.h"
#include "feti/statistics.h"
#include "parallel/mpi_communicator.h"
#include "feti/convergence_history.h"
#include "feti/progress_monitor.h"
#include "sens/sensitivity_statistics.h"

#include <mpi.h>

#include <chrono>
#include <algorithm>
#include <limits>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>

namespace {

using namespace ffeti;

/// A set-up problem, its last solution and the sensitivity problem of that solution (built
/// by the first sensitivity call after fetiSolve). Lives until fetiFree or the end of the
/// process.
struct Handle {
  std::unique_ptr<FetiProblem> problem;
  std::optional<FetiResult> result;
  double tolerance = DualSolveSettings{}.tolerance;  // of the last solve: the sensitivity's default
  std::unique_ptr<SensitivityProblem> sensitivity;
  ConvergenceHistory history;  // of the last fetiSolve
};

std::map<long, Handle>& handles() {
  static std::map<long, Handle> registry;
  return registry;
}

/// The problem behind handle `id`, given as the argument `name` (for the error message).
Handle& handle(long id, const char* name = "P") {
  const auto it = handles().find(id);
  if (it == handles().end())
    throw InputError(std::string(name) + ": no ffeti problem with handle " + std::to_string(id) +
                     " (freed, or not returned by fetiSetup)");
  return it->second;
}

/// Runs `body`, turning every core exception into a FreeFEM error the script can catch.
template <class F>
auto guarded(const char* function, F&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const std::exception& error) {
    const std::string message = std::string(function) + ": " + error.what();
    ExecError(message.c_str());
  }
  return decltype(body())();
}

/// The script's communicator (named parameter comm) if given, else the world communicator
/// under FreeFem++-mpi, else one process. Serial FreeFem++ never initializes MPI.
std::shared_ptr<const Communicator> communicator(void* script_comm) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    if (script_comm) throw InputError("comm: MPI is not initialized (run under FreeFem++-mpi)");
    return std::make_shared<SerialCommunicator>();
  }
  return std::make_shared<MpiCommunicator>(script_comm ? *static_cast<MPI_Comm*>(script_comm) : MPI_COMM_WORLD);
}

/// Owner of each subdomain: among the ranks that assembled it (non-empty K[s]), the
/// (s mod count)-th, so that a script assembling everything on every rank is spread
/// round-robin and a script assembling each subdomain once keeps its own split.
std::vector<int> owners(const std::vector<long long>& assembled_here, const Communicator& comm) {
  std::vector<int> counts;
  const std::vector<long long> all = comm.allgather(assembled_here, &counts);
  const size_t S = assembled_here.size();
  for (int r = 0; r < comm.size(); ++r)
    if (static_cast<size_t>(counts[static_cast<size_t>(r)]) != S)
      throw InputError("K: rank " + std::to_string(r) + " has " + std::to_string(counts[static_cast<size_t>(r)]) +
                       " subdomains, rank " + std::to_string(comm.rank()) + " has " + std::to_string(S));
  std::vector<int> owner(S, -1);
  for (size_t s = 0; s < S; ++s) {
    std::vector<int> providers;
    for (int r = 0; r < comm.size(); ++r)
      if (all[static_cast<size_t>(r) * S + s]) providers.push_back(r);
    if (providers.empty())
      throw InputError("K[" + std::to_string(s) + "]: empty on every rank (no rank assembled subdomain " +
                       std::to_string(s) + ")");
    owner[s] = providers[s % providers.size()];
  }
  return owner;
}

template <class T>
T* optional_pointer(Expression e, Stack stack) {
  return e ? GetAny<T*>((*e)(stack)) : nullptr;
}
double optional_real(Expression e, Stack stack, double fallback) {
  return e ? GetAny<double>((*e)(stack)) : fallback;
}
long optional_int(Expression e, Stack stack, long fallback) {
  return e ? GetAny<long>((*e)(stack)) : fallback;
}
std::string optional_string(Expression e, Stack stack, const std::string& fallback) {
  return e ? *GetAny<std::string*>((*e)(stack)) : fallback;
}

/// A function's named parameters: its own (`extras`), then the registry's options of `scope`
/// (feti/options.h), whose values the script gives as FreeFEM reals, integers or strings.
std::vector<basicAC_F0::name_and_type> named_parameters(std::vector<basicAC_F0::name_and_type> extras,
                                                        OptionScope scope) {
  for (const Option& o : options())
    if (o.scope == scope)
      extras.push_back({o.name, o.kind == OptionKind::word      ? &typeid(std::string*)
                                : o.kind == OptionKind::integer ? &typeid(long)
                                                                : &typeid(double)});
  return extras;
}

/// The options of `scope` the script gave: `options` points at the first of them in nargs
/// (named_parameters' order). Each is checked as it is read, before any narrowing.
GivenOptions given_options(OptionScope scope, const Expression* options_nargs, Stack stack) {
  GivenOptions given;
  size_t k = 0;
  for (const Option& o : options()) {
    if (o.scope != scope) continue;
    const Expression e = options_nargs[k++];
    if (!e) continue;
    if (o.kind == OptionKind::word) given.set(o.name, *GetAny<std::string*>((*e)(stack)));
    else if (o.kind == OptionKind::integer) given.set(o.name, GetAny<long>((*e)(stack)));
    else given.set(o.name, GetAny<double>((*e)(stack)));
  }
  return given;
}

// ---- int P = fetiSetup(K, F, X, Y, body, dirichlet=..., contactSlave=..., ...) ----------
class FetiSetup : public E_F0mps {
 public:
  typedef long Result;
  static std::vector<basicAC_F0::name_and_type> name_param;
  std::vector<Expression> nargs;
  Expression K, F, X, Y, body;

  explicit FetiSetup(const basicAC_F0& args) : nargs(name_param.size()) {
    args.SetNameParam(static_cast<int>(name_param.size()), name_param.data(), nargs.data());
    K = to<KN<Matrice_Creuse<double>>*>(args[0]);
    F = to<KN<KN<double>>*>(args[1]);
    X = to<KN<KN<double>>*>(args[2]);
    Y = to<KN<KN<double>>*>(args[3]);
    body = to<KN<long>*>(args[4]);
  }
  static ArrayOfaType typeargs() {
    return ArrayOfaType(atype<KN<Matrice_Creuse<double>>*>(), atype<KN<KN<double>>*>(),
                        atype<KN<KN<double>>*>(), atype<KN<KN<double>>*>(), atype<KN<long>*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FetiSetup(args); }

  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiSetup", [&] { return setup(stack); }));
  }

 private:
  // Named parameters by position in name_param: these, then the set-up options.
  enum Named { kDirichlet, kDirichletValues, kSlave, kMaster, kGap, kComponent, kComm, kSegments, kObstacle,
               kRadius, kContactGap, kOptions };

  long setup(Stack stack) const {
    auto& Ks = *GetAny<KN<Matrice_Creuse<double>>*>((*K)(stack));
    const std::shared_ptr<const Communicator> comm =
        communicator(nargs[kComm] ? GetAny<pcommworld>((*nargs[kComm])(stack)) : nullptr);
    const long count = Ks.N();
    std::vector<long long> assembled(static_cast<size_t>(count), 0);
    for (long s = 0; s < count; ++s) assembled[static_cast<size_t>(s)] = Ks[s].pHM() && Ks[s].pHM()->n > 0;
    // Conversion errors are raised on every rank together, or the others would wait.
    collectively(*comm, [&] { check_array_sizes(stack, count); });
    const std::vector<int> owner = owners(assembled, *comm);
    std::vector<int> ids;
    for (long s = 0; s < count; ++s)
      if (owner[static_cast<size_t>(s)] == comm->rank()) ids.push_back(static_cast<int>(s));
    std::vector<SubdomainInput> subdomains;
    ContactInput contact;
    FetiSetupSettings settings;
    collectively(*comm, [&] {
      subdomains = subdomain_inputs(stack, ids);
      std::vector<long> dofs;
      for (const SubdomainInput& sub : subdomains) dofs.push_back(sub.K.rows());
      add_dirichlet_and_components(stack, count, ids, dofs, subdomains);
      contact = contact_input(stack, count, ids, dofs);
      settings = setup_settings(stack);
    });
    if (settings.threads == 0) settings.threads = default_threads_per_rank(*comm);
    // Never reused: a script holding a freed handle must get an error, not another problem.
    static long next_id = 1;
    const long id = next_id++;
    auto problem = std::make_unique<FetiProblem>(std::move(subdomains), ids, static_cast<int>(count), contact,
                                                 settings, comm);
    handles()[id].problem = std::move(problem);
    return id;
  }

  /// F, X, Y and body need one entry per subdomain, as K has.
  void check_array_sizes(Stack stack, long count) const {
    const std::pair<const char*, long> sizes[] = {{"F", GetAny<KN<KN<double>>*>((*F)(stack))->N()},
                                                  {"X", GetAny<KN<KN<double>>*>((*X)(stack))->N()},
                                                  {"Y", GetAny<KN<KN<double>>*>((*Y)(stack))->N()},
                                                  {"body", GetAny<KN<long>*>((*body)(stack))->N()}};
    for (const auto& [name, n] : sizes)
      if (n != count)
        throw InputError(std::string(name) + ": has " + std::to_string(n) + " entries, K has " +
                         std::to_string(count) + " subdomains");
  }

  /// K, F, coordinates and body of the subdomains `ids` this rank holds.
  std::vector<SubdomainInput> subdomain_inputs(Stack stack, const std::vector<int>& ids) const {
    auto& Ks = *GetAny<KN<Matrice_Creuse<double>>*>((*K)(stack));
    auto& Fs = *GetAny<KN<KN<double>>*>((*F)(stack));
    auto& Xs = *GetAny<KN<KN<double>>*>((*X)(stack));
    auto& Ys = *GetAny<KN<KN<double>>*>((*Y)(stack));
    auto& bodies = *GetAny<KN<long>*>((*body)(stack));
    std::vector<SubdomainInput> subdomains;
    for (int s : ids) {
      SubdomainInput sub;
      sub.K = binding::to_sparse(Ks[s], "K[" + std::to_string(s) + "]");
      sub.f = binding::to_vec(Fs[s]);
      sub.x = binding::to_std(Xs[s]);
      sub.y = binding::to_std(Ys[s]);
      sub.body = static_cast<int>(bodies[s]);
      subdomains.push_back(std::move(sub));
    }
    return subdomains;
  }

  /// dirichlet=, dirichletValues= and component= into the subdomains.
  void add_dirichlet_and_components(Stack stack, long count, const std::vector<int>& ids, const std::vector<long>& dofs,
                                    std::vector<SubdomainInput>& subdomains) const {
    const auto dirichlet = binding::per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kDirichlet], stack), count, ids,
                                                  dofs, "dirichlet");
    const auto components = binding::per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kComponent], stack), count,
                                                   ids, dofs, "component");
    const auto* values = optional_pointer<KN<KN<double>>>(nargs[kDirichletValues], stack);
    if (values && values->N() != count)
      throw InputError("dirichletValues: has " + std::to_string(values->N()) + " entries for " +
                       std::to_string(count) + " subdomains");
    for (size_t k = 0; k < ids.size(); ++k) {
      SubdomainInput& sub = subdomains[k];
      if (!dirichlet.empty()) sub.dirichlet_dofs = dirichlet[k];
      if (values) sub.dirichlet_values = binding::to_std((*values)[ids[k]]);
      if (!components.empty()) sub.component = components[k];
    }
  }

  /// contactSlave=, contactMaster=, gap=, contactSegments=, obstacle=, contactRadius=, contactGap=.
  ContactInput contact_input(Stack stack, long count, const std::vector<int>& ids, const std::vector<long>& dofs) const {
    ContactInput contact;
    contact.slave_dofs = binding::per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kSlave], stack), count, ids,
                                                dofs, "contactSlave");
    contact.master_dofs = binding::per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kMaster], stack), count, ids,
                                                 dofs, "contactMaster");
    contact.gap = optional_real(nargs[kGap], stack, 0.0);
    const auto segment_dofs = binding::per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kSegments], stack), count,
                                                     ids, dofs, "contactSegments");
    for (size_t k = 0; k < segment_dofs.size(); ++k) {
      if (segment_dofs[k].size() % 4 != 0)
        throw InputError("contactSegments[" + std::to_string(ids[k]) + "]: needs 4 dofs per segment (a_x, a_y, b_x, b_y)");
      contact.master_segments.emplace_back();
      for (size_t i = 0; i < segment_dofs[k].size(); i += 4)
        contact.master_segments.back().push_back({segment_dofs[k][i], segment_dofs[k][i + 1],
                                                  segment_dofs[k][i + 2], segment_dofs[k][i + 3]});
    }
    if (const auto* obstacle = optional_pointer<KN<double>>(nargs[kObstacle], stack)) {
      if (obstacle->N() != 4)
        throw InputError("obstacle: needs [point x, point y, normal x, normal y], got " +
                         std::to_string(obstacle->N()) + " entries");
      contact.obstacle = true;
      contact.obstacle_point = {(*obstacle)[0], (*obstacle)[1]};
      contact.obstacle_normal = {(*obstacle)[2], (*obstacle)[3]};
    }
    contact.search_distance = optional_real(nargs[kRadius], stack, contact.search_distance);
    if (const auto* gaps = optional_pointer<KN<KN<double>>>(nargs[kContactGap], stack)) {
      if (gaps->N() != count)
        throw InputError("contactGap: has " + std::to_string(gaps->N()) + " entries for " + std::to_string(count) +
                         " subdomains");
      for (int s : ids) contact.gap_field.push_back(binding::to_std((*gaps)[s]));
    }
    return contact;
  }

  /// The set-up options (variant=, factor=, threads=, preconditioner=); a vector field is
  /// one with component= given.
  FetiSetupSettings setup_settings(Stack stack) const {
    return given_options(OptionScope::setup, &nargs[kOptions], stack).setup(nargs[kComponent] != nullptr);
  }
};

std::vector<basicAC_F0::name_and_type> FetiSetup::name_param = named_parameters(
    {{"dirichlet", &typeid(KN<KN<long>>*)},       {"dirichletValues", &typeid(KN<KN<double>>*)},
     {"contactSlave", &typeid(KN<KN<long>>*)},    {"contactMaster", &typeid(KN<KN<long>>*)},
     {"gap", &typeid(double)},                    {"component", &typeid(KN<KN<long>>*)},
     {"comm", &typeid(pcommworld)},               {"contactSegments", &typeid(KN<KN<long>>*)},
     {"obstacle", &typeid(KN<double>*)},          {"contactRadius", &typeid(double)},
     {"contactGap", &typeid(KN<KN<double>>*)}},
    OptionScope::setup);

// ---- int status = fetiSolve(P, U, lambda=..., tol=..., maxit=..., algorithm=..., verbosity=...)
class FetiSolve : public E_F0mps {
 public:
  typedef long Result;
  static std::vector<basicAC_F0::name_and_type> name_param;
  std::vector<Expression> nargs;
  Expression id, U;

  explicit FetiSolve(const basicAC_F0& args) : nargs(name_param.size()) {
    args.SetNameParam(static_cast<int>(name_param.size()), name_param.data(), nargs.data());
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
    if (auto* start = optional_pointer<KN<double>>(nargs[kStart], stack)) settings.start = binding::to_vec(*start);
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
    for (size_t k = 0; k < r.u.size(); ++k) binding::copy_to(r.u[k], u[ids[k]]);
    if (auto* lambda = optional_pointer<KN<double>>(nargs[kLambda], stack)) binding::copy_to(r.lambda, *lambda);
    if (verbosity >= 1 && h.problem->communicator().rank() == 0)
      std::printf("ffeti: %s after %d Hessian multiplications (%d outer), path %s, ||gP||/||b|| %.2e, "
                  "KKT check %.2e\n",
                  to_string(r.status).c_str(), r.counts.hessian, r.counts.outer, r.path.c_str(),
                  r.gradient_norm / r.gradient_reference, r.violation);
    std::fflush(stdout);
    return status_code(r.status);
  }
};

std::vector<basicAC_F0::name_and_type> FetiSolve::name_param = named_parameters(
    {{"lambda", &typeid(KN<double>*)}, {"history", &typeid(std::string*)}, {"start", &typeid(KN<double>*)}},
    OptionScope::solve);

// ---- sensitivities (seed eq. 12) -------------------------------------------------------

/// The sensitivity problem of the handle's last solution with classification threshold
/// `threshold`, built on first use and kept for every later direction.
SensitivityProblem& sensitivity_problem(Handle& h, double threshold) {
  if (!h.result) throw InputError("P: no solution yet: call fetiSolve first");
  if (h.result->status != SolveStatus::converged)
    throw InputError("P: the last fetiSolve did not converge (" + to_string(h.result->status) +
                     "): its solution has no derivative worth the name; solve it to convergence first");
  if (!h.sensitivity || h.sensitivity->classification().threshold != threshold)
    h.sensitivity = std::make_unique<SensitivityProblem>(*h.problem, *h.result, threshold);
  return *h.sensitivity;
}

/// Default threshold below which a multiplier counts as zero, relative to max lambda: ten
/// times the state's tolerance, the accuracy to which its multipliers are known.
double default_threshold(const Handle& h) { return std::min(1e-2, 10 * h.tolerance); }

/// Design directions from the script: for k directions, entry j * S + s of dK, dF (empty
/// entries: zero), of the node velocities velocityX, velocityY (absent: the contact
/// geometry does not move) and of the gap derivatives dGap (absent: the gaps do not change)
/// belongs to direction j and subdomain s (S subdomains). Only this rank's subdomains are read.
std::vector<DesignDerivative> design_directions(const FetiProblem& problem, KN<Matrice_Creuse<double>>* dK,
                                                KN<KN<double>>* dF, KN<KN<double>>* vx, KN<KN<double>>* vy,
                                                KN<KN<double>>* dgap) {
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
        d.dK.push_back(empty ? SparseMatrix() : binding::to_sparse(matrix, "dK[" + std::to_string(e) + "]"));
        d.df.push_back(binding::to_vec((*dF)[e]));
        if (vx) d.velocity_x.push_back(binding::to_std((*vx)[e]));
        if (vy) d.velocity_y.push_back(binding::to_std((*vy)[e]));
        if (dgap) d.dgap.push_back(binding::to_std((*dgap)[e]));
      }
    }
  });
  return directions;
}

DualSolveSettings sensitivity_settings(const Handle& h, Expression tol, Expression maxit, Expression verbosity,
                                       Stack stack) {
  GivenOptions given;  // checked as fetiSolve's; the default tol is the state's
  given.set("tol", optional_real(tol, stack, h.tolerance));
  if (maxit) given.set("maxit", GetAny<long>((*maxit)(stack)));
  if (verbosity) given.set("verbosity", GetAny<long>((*verbosity)(stack)));
  const SolverSettings solver = given.solve(h.problem->variant());
  DualSolveSettings settings;  // the sensitivity's own path and test: only these three from the script
  settings.tolerance = solver.solve.tolerance;
  settings.max_hessian = solver.solve.max_hessian;
  settings.monitor = progress_monitor(solver.verbosity, h.problem->communicator());
  return settings;
}

// int status = fetiSensitivity(P, dK, dF, Z, velocityX=, velocityY=, tol=, maxit=, activeTol=, verbosity=,
//                              dGap=, dLambda=): dLambda[j] receives lambda' of direction j per contact row
// (fetiContact's order; 0 on inactive rows), on every rank.
class FetiSensitivity : public E_F0mps {
 public:
  typedef long Result;
  static const int n_name_param = 8;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression id, dK, dF, Z;

  explicit FetiSensitivity(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
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
      SensitivityProblem& sens = sensitivity_problem(h, optional_real(nargs[4], stack, default_threshold(h)));
      const std::vector<DesignDerivative> directions = design_directions(
          *h.problem, GetAny<KN<Matrice_Creuse<double>>*>((*dK)(stack)), GetAny<KN<KN<double>>*>((*dF)(stack)),
          optional_pointer<KN<KN<double>>>(nargs[0], stack), optional_pointer<KN<KN<double>>>(nargs[1], stack),
          optional_pointer<KN<KN<double>>>(nargs[6], stack));
      const std::vector<SensitivityResult> r =
          sens.direct(directions, sensitivity_settings(h, nargs[2], nargs[3], nargs[5], stack));
      if (auto* dLambda = optional_pointer<KN<KN<double>>>(nargs[7], stack)) {
        dLambda->resize(static_cast<long>(r.size()));
        for (size_t j = 0; j < r.size(); ++j) binding::copy_to(r[j].contact_multipliers, (*dLambda)[static_cast<long>(j)]);
      }
      auto& z = *GetAny<KN<KN<double>>*>((*Z)(stack));
      const std::vector<int>& ids = h.problem->global_ids();
      const long count = h.problem->subdomain_count();
      z.resize(count * static_cast<long>(r.size()));
      for (long e = 0; e < z.N(); ++e) z[e].resize(0);  // subdomains of other ranks stay empty
      SolveStatus worst = SolveStatus::converged;
      for (size_t j = 0; j < r.size(); ++j) {
        for (size_t k = 0; k < r[j].z.size(); ++k) binding::copy_to(r[j].z[k], z[static_cast<long>(j) * count + ids[k]]);
        if (worst == SolveStatus::converged) worst = r[j].status;
      }
      return static_cast<long>(status_code(worst));
    }));
  }
};

basicAC_F0::name_and_type FetiSensitivity::name_param[] = {
    {"velocityX", &typeid(KN<KN<double>>*)}, {"velocityY", &typeid(KN<KN<double>>*)}, {"tol", &typeid(double)},
    {"maxit", &typeid(long)}, {"activeTol", &typeid(double)}, {"verbosity", &typeid(long)},
    {"dGap", &typeid(KN<KN<double>>*)}, {"dLambda", &typeid(KN<KN<double>>*)}};

// int status = fetiAdjoint(P, dJdu, tol=, maxit=, activeTol=, verbosity=, w=, dJdlambda=): 6
// (weakly_active) when some contact row is weakly active: use fetiSensitivity then. w=
// receives the adjoint displacement per subdomain (this rank's; the others empty), as
// fetiSolve's U. dJdlambda: the cost's derivative per contact row (fetiContact's order).
class FetiAdjoint : public E_F0mps {
 public:
  typedef long Result;
  static const int n_name_param = 6;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression id, dJdu;

  explicit FetiAdjoint(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
    id = to<long>(args[0]);
    dJdu = to<KN<KN<double>>*>(args[1]);
  }
  static ArrayOfaType typeargs() { return ArrayOfaType(atype<long>(), atype<KN<KN<double>>*>()); }
  static E_F0* f(const basicAC_F0& args) { return new FetiAdjoint(args); }

  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiAdjoint", [&] {
      Handle& h = handle(GetAny<long>((*id)(stack)));
      SensitivityProblem& sens = sensitivity_problem(h, optional_real(nargs[2], stack, default_threshold(h)));
      const auto& g = *GetAny<KN<KN<double>>*>((*dJdu)(stack));
      std::vector<Vec> gradient;
      collectively(h.problem->communicator(), [&] {
        if (g.N() != h.problem->subdomain_count())
          throw InputError("dJdu: has " + std::to_string(g.N()) + " entries for " +
                           std::to_string(h.problem->subdomain_count()) + " subdomains");
        for (int s : h.problem->global_ids()) gradient.push_back(binding::to_vec(g[s]));
      });
      const Vec dJdlambda =
          nargs[5] ? binding::to_vec(*GetAny<KN<double>*>((*nargs[5])(stack))) : Vec();
      const AdjointResult r =
          sens.adjoint(gradient, sensitivity_settings(h, nargs[0], nargs[1], nargs[3], stack), dJdlambda);
      if (r.status == SolveStatus::weakly_active && h.problem->communicator().rank() == 0) {
        // A script that ignores status 6 would lose the contact part of its gradient.
        std::printf("ffeti: WARNING fetiAdjoint: %zu contact rows are weakly active (force and gap both about 0): "
                    "the derivative is only directional there, so no adjoint was solved (status 6); use "
                    "fetiSensitivity (the direct mode) for this design\n",
                    sens.classification().weak.size());
        std::fflush(stdout);
      }
      if (auto* w = optional_pointer<KN<KN<double>>>(nargs[4], stack)) {
        const std::vector<int>& ids = h.problem->global_ids();
        w->resize(h.problem->subdomain_count());
        for (long s = 0; s < w->N(); ++s) (*w)[s].resize(0);
        if (const std::vector<Vec>* solution = sens.adjoint_displacement())
          for (size_t k = 0; k < solution->size(); ++k) binding::copy_to((*solution)[k], (*w)[ids[k]]);
      }
      return static_cast<long>(status_code(r.status));
    }));
  }
};

basicAC_F0::name_and_type FetiAdjoint::name_param[] = {
    {"tol", &typeid(double)}, {"maxit", &typeid(long)}, {"activeTol", &typeid(double)}, {"verbosity", &typeid(long)},
    {"w", &typeid(KN<KN<double>>*)}, {"dJdlambda", &typeid(KN<double>*)}};

// real dJ = fetiAdjointGradient(P, dK, dF, velocityX=, velocityY=, dGap=): w'fbar + mu'c~ for
// one direction, after fetiAdjoint; no dual solve.
class FetiAdjointGradient : public E_F0mps {
 public:
  typedef double Result;
  static const int n_name_param = 3;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression id, dK, dF;

  explicit FetiAdjointGradient(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
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
          optional_pointer<KN<KN<double>>>(nargs[2], stack));
      if (d.size() != 1)  // the same on every rank: the sizes were checked collectively
        throw InputError("dK: " + std::to_string(d.size()) + " design directions: fetiAdjointGradient takes one (" +
                         std::to_string(h.problem->subdomain_count()) + " entries)");
      return h.sensitivity->adjoint_gradient(d.front());
    }));
  }
};

basicAC_F0::name_and_type FetiAdjointGradient::name_param[] = {
    {"velocityX", &typeid(KN<KN<double>>*)}, {"velocityY", &typeid(KN<KN<double>>*)},
    {"dGap", &typeid(KN<KN<double>>*)}};

// ---- small functions -------------------------------------------------------------------
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

double feti_info(const long& id, std::string* const& key) {
  return guarded("fetiInfo", [&] {
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

long feti_set_loads(const long& id, KN<KN<double>>* const& loads) {
  return guarded("fetiSetLoads", [&] {
    Handle& h = handle(id);
    std::vector<Vec> f;
    for (long s = 0; s < loads->N(); ++s) f.push_back(binding::to_vec((*loads)[s]));
    h.problem->set_loads(f);
    h.sensitivity.reset();
    h.result.reset();
    return 0L;
  });
}

/// Fills xc, yc with the slave positions of the contact rows and lc with their multipliers
/// from the last solve (0 before any: the positions serve to build a start); returns the
/// number of contact rows.
class FetiContact : public E_F0mps {
 public:
  typedef long Result;
  Expression id, xc, yc, lc;
  explicit FetiContact(const basicAC_F0& args) {
    args.SetNameParam(0, nullptr, nullptr);
    id = to<long>(args[0]);
    xc = to<KN<double>*>(args[1]);
    yc = to<KN<double>*>(args[2]);
    lc = to<KN<double>*>(args[3]);
  }
  static ArrayOfaType typeargs() {
    return ArrayOfaType(atype<long>(), atype<KN<double>*>(), atype<KN<double>*>(), atype<KN<double>*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FetiContact(args); }
  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiContact", [&] {
      const Handle& h = handle(GetAny<long>((*id)(stack)));
      const auto rows = contact_multipliers(*h.problem, h.result ? &*h.result : nullptr);
      auto& x = *GetAny<KN<double>*>((*xc)(stack));
      auto& y = *GetAny<KN<double>*>((*yc)(stack));
      auto& l = *GetAny<KN<double>*>((*lc)(stack));
      const long count = static_cast<long>(rows.size());
      x.resize(count), y.resize(count), l.resize(count);
      for (long k = 0; k < count; ++k) {
        x[k] = rows[static_cast<size_t>(k)].x;
        y[k] = rows[static_cast<size_t>(k)].y;
        l[k] = rows[static_cast<size_t>(k)].lambda;
      }
      return count;
    }));
  }
};

// ---- int rows = fetiContactPressure(P, Share, Pr, rows=pc, shares=wc) ----------------------
/// The contact pressure of the last solve per dof into Pr (this rank's subdomains, others
/// empty): each contact row's force over its node's share of the contact curve, Share[s]
/// being each dof's share on subdomain s (int1d of the test functions over the contact
/// boundary: a varf's vector). rows= and shares= receive the pressure and the share per
/// contact row (fetiContact's order). Returns the number of contact rows.
class FetiContactPressure : public E_F0mps {
 public:
  typedef long Result;
  static const int n_name_param = 2;
  static basicAC_F0::name_and_type name_param[];
  Expression nargs[n_name_param];
  Expression id, share_in, pressure_out;
  explicit FetiContactPressure(const basicAC_F0& args) {
    args.SetNameParam(n_name_param, name_param, nargs);
    id = to<long>(args[0]);
    share_in = to<KN<KN<double>>*>(args[1]);
    pressure_out = to<KN<KN<double>>*>(args[2]);
  }
  static ArrayOfaType typeargs() {
    return ArrayOfaType(atype<long>(), atype<KN<KN<double>>*>(), atype<KN<KN<double>>*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FetiContactPressure(args); }
  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiContactPressure", [&] {
      const Handle& h = handle(GetAny<long>((*id)(stack)));
      if (!h.result) throw InputError("P: no solution yet: call fetiSolve first");
      const FetiProblem& problem = *h.problem;
      const auto& shares = *GetAny<KN<KN<double>>*>((*share_in)(stack));
      std::vector<Vec> share;
      collectively(problem.communicator(), [&] {
        if (shares.N() != problem.subdomain_count())
          throw InputError("Share: has " + std::to_string(shares.N()) + " entries for " +
                           std::to_string(problem.subdomain_count()) + " subdomains");
        for (int s : problem.global_ids()) share.push_back(binding::to_vec(shares[s]));
      });
      const ContactPressure p = contact_pressure(problem, h.result->lambda, share);
      auto& out = *GetAny<KN<KN<double>>*>((*pressure_out)(stack));
      out.resize(problem.subdomain_count());
      for (long s = 0; s < out.N(); ++s) out[s].resize(0);
      for (size_t k = 0; k < p.per_dof.size(); ++k) binding::copy_to(p.per_dof[k], out[problem.global_ids()[k]]);
      if (auto* rows = optional_pointer<KN<double>>(nargs[0], stack)) binding::copy_to(p.per_row, *rows);
      if (auto* row_shares = optional_pointer<KN<double>>(nargs[1], stack)) binding::copy_to(p.share_per_row, *row_shares);
      return static_cast<long>(p.per_row.size());
    }));
  }
};

basicAC_F0::name_and_type FetiContactPressure::name_param[] = {{"rows", &typeid(KN<double>*)},
                                                               {"shares", &typeid(KN<double>*)}};

// ---- int rows = fetiContactStart(P, Pfrom, start): a start from another problem's forces --
/// Fills `start` with multipliers for P (fetiSolve's start): on P's contact rows the contact
/// forces of Pfrom's last solve, each row taking the force of Pfrom's nearest contact row
/// shared among the rows nearest to it; 0 on the equality rows. Pfrom is the same scene on a
/// coarser mesh (nested iteration), another split or the previous design. Returns P's number
/// of contact rows.
class FetiContactStart : public E_F0mps {
 public:
  typedef long Result;
  Expression id, from_id, start_out;
  explicit FetiContactStart(const basicAC_F0& args) {
    args.SetNameParam(0, nullptr, nullptr);
    id = to<long>(args[0]);
    from_id = to<long>(args[1]);
    start_out = to<KN<double>*>(args[2]);
  }
  static ArrayOfaType typeargs() { return ArrayOfaType(atype<long>(), atype<long>(), atype<KN<double>*>()); }
  static E_F0* f(const basicAC_F0& args) { return new FetiContactStart(args); }
  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiContactStart", [&] {
      const Handle& h = handle(GetAny<long>((*id)(stack)));
      const Handle& from = handle(GetAny<long>((*from_id)(stack)), "Pfrom");
      if (!from.result) throw InputError("Pfrom: no solution yet: call fetiSolve on it first");
      const auto forces = contact_multipliers(*from.problem, &*from.result);
      if (forces.empty()) throw InputError("Pfrom: has no contact rows, so no contact forces to start from");
      binding::copy_to(start_from_contact_forces(*h.problem, forces), *GetAny<KN<double>*>((*start_out)(stack)));
      return static_cast<long>(h.problem->contact_positions().size());
    }));
  }
};

// ---- int rows = fetiConstraints(P, I, J, V, c, kind): the constraint rows as triplets ---
/// B u = c (equality rows) and B u <= c (contact rows) over the dofs of all subdomains
/// numbered one after the other in subdomain order: triplets (I, J, V), right-hand side c
/// and kind per row (0 gluing, 1 Dirichlet, 2 contact). With Total FETI every condition is
/// a row: what a solver of the undivided problem needs (the peers of the benchmarks). One
/// process only.
class FetiConstraints : public E_F0mps {
 public:
  typedef long Result;
  Expression id, rows_out, columns_out, values_out, rhs_out, kind_out;
  explicit FetiConstraints(const basicAC_F0& args) {
    args.SetNameParam(0, nullptr, nullptr);
    id = to<long>(args[0]);
    rows_out = to<KN<long>*>(args[1]);
    columns_out = to<KN<long>*>(args[2]);
    values_out = to<KN<double>*>(args[3]);
    rhs_out = to<KN<double>*>(args[4]);
    kind_out = to<KN<long>*>(args[5]);
  }
  static ArrayOfaType typeargs() {
    return ArrayOfaType(atype<long>(), atype<KN<long>*>(), atype<KN<long>*>(), atype<KN<double>*>(),
                        atype<KN<double>*>(), atype<KN<long>*>());
  }
  static E_F0* f(const basicAC_F0& args) { return new FetiConstraints(args); }
  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiConstraints", [&] {
      const FetiProblem& problem = *handle(GetAny<long>((*id)(stack))).problem;
      if (problem.communicator().size() > 1) throw InputError("P: fetiConstraints runs in one process only");
      if (problem.variant() == FetiVariant::feti1)
        throw InputError("P: fetiConstraints needs variant=\"tfeti\" (FETI-1 eliminates the Dirichlet dofs, "
                         "so their conditions are no rows)");
      std::vector<long> offset(1, 0);
      for (const SubdomainInput& in : problem.inputs()) offset.push_back(offset.back() + in.K.rows());
      const Constraints& c = problem.constraints();
      auto& I = *GetAny<KN<long>*>((*rows_out)(stack));
      auto& J = *GetAny<KN<long>*>((*columns_out)(stack));
      auto& V = *GetAny<KN<double>*>((*values_out)(stack));
      auto& rhs = *GetAny<KN<double>*>((*rhs_out)(stack));
      auto& kind = *GetAny<KN<long>*>((*kind_out)(stack));
      const long count = static_cast<long>(c.entries.size());
      I.resize(count), J.resize(count), V.resize(count), rhs.resize(c.rows()), kind.resize(c.rows());
      for (int row = 0; row < c.rows(); ++row) {
        rhs[row] = c.rhs[static_cast<size_t>(row)];
        kind[row] = static_cast<long>(c.kind[static_cast<size_t>(row)]);
        for (int e = c.row_start[static_cast<size_t>(row)]; e < c.row_start[static_cast<size_t>(row) + 1]; ++e) {
          const ConstraintEntry& entry = c.entries[static_cast<size_t>(e)];
          I[e] = row;
          J[e] = offset[static_cast<size_t>(entry.subdomain)] + entry.dof;
          V[e] = entry.coefficient;
        }
      }
      return static_cast<long>(c.rows());
    }));
  }
};

/// Fills `indices` with the positions where `mask` exceeds 1/2 and returns their number: the
/// selection loop of ffetiDofsWhere, which FreeFEM's interpreter runs 100 times slower.
long feti_indices(KN<double>* const& mask, KN<long>* const& indices) {
  long count = 0;
  for (long k = 0; k < mask->N(); ++k) count += (*mask)[k] > 0.5;
  indices->resize(count);
  for (long k = 0, next = 0; k < mask->N(); ++k)
    if ((*mask)[k] > 0.5) (*indices)[next++] = k;
  return count;
}

/// Makes every part of a mesh partition (`part`: one entry per triangle of Th) connected
/// through element edges: each edge-connected piece of a part other than its largest goes
/// to the neighbouring part it shares most edges with, until no piece is left (METIS may
/// give a part two pieces, e.g. both jaws of a spanner, and a disconnected subdomain has
/// rigid modes no kernel candidate covers). Returns the number of triangles moved.
long feti_connect_parts(pmesh const& mesh, KN<long>* const& part) {
  return guarded("fetiConnectParts", [&] {
    const Mesh& Th = *mesh;
    const int nt = Th.nt;
    if (part->N() != nt)
      throw InputError("part: has " + std::to_string(part->N()) + " entries for " + std::to_string(nt) + " triangles");
    long moved = 0;
    for (int round = 0; round < 100; ++round) {
      std::vector<int> piece(static_cast<size_t>(nt), -1), size, stack;
      for (int start = 0; start < nt; ++start) {  // edge-connected pieces of each part
        if (piece[static_cast<size_t>(start)] >= 0) continue;
        const int id = static_cast<int>(size.size());
        size.push_back(0);
        stack.assign(1, start);
        piece[static_cast<size_t>(start)] = id;
        while (!stack.empty()) {
          const int k = stack.back();
          stack.pop_back();
          ++size[static_cast<size_t>(id)];
          for (int e = 0; e < 3; ++e) {
            int edge = e;
            const int other = Th.ElementAdj(k, edge);
            if (other >= 0 && other != k && piece[static_cast<size_t>(other)] < 0 && (*part)[other] == (*part)[k]) {
              piece[static_cast<size_t>(other)] = id;
              stack.push_back(other);
            }
          }
        }
      }
      std::map<long, int> largest;  // part -> its largest piece
      for (int k = 0; k < nt; ++k) {
        const int id = piece[static_cast<size_t>(k)];
        auto [it, inserted] = largest.emplace((*part)[k], id);
        if (!inserted && size[static_cast<size_t>(id)] > size[static_cast<size_t>(it->second)]) it->second = id;
      }
      std::map<int, std::map<long, int>> shared;  // stray piece -> neighbouring part -> shared edges
      for (int k = 0; k < nt; ++k) {
        const int id = piece[static_cast<size_t>(k)];
        if (largest[(*part)[k]] == id) continue;
        for (int e = 0; e < 3; ++e) {
          int edge = e;
          const int other = Th.ElementAdj(k, edge);
          if (other >= 0 && other != k && (*part)[other] != (*part)[k]) ++shared[id][(*part)[other]];
        }
      }
      if (shared.empty()) break;
      std::map<int, long> target;
      for (const auto& [id, counts] : shared)
        target[id] = std::max_element(counts.begin(), counts.end(),
                                      [](const auto& a, const auto& b) { return a.second < b.second; })->first;
      for (int k = 0; k < nt; ++k)
        if (const auto it = target.find(piece[static_cast<size_t>(k)]); it != target.end()) {
          (*part)[k] = it->second;
          ++moved;
        }
    }
    return moved;
  });
}

/// Rank and size of MPI's world communicator; 0 and 1 when MPI is not initialized, so that
/// one script runs under FreeFem++ and FreeFem++-mpi (FreeFEM's mpirank exists only there).
long feti_rank() {
  int initialized = 0, rank = 0;
  MPI_Initialized(&initialized);
  if (initialized) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}
long feti_ranks() {
  int initialized = 0, size = 1;
  MPI_Initialized(&initialized);
  if (initialized) MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

/// Sum of `value` over the ranks of the problem's communicator (itself in one process).
double feti_sum(const long& id, const double& value) {
  return guarded("fetiSum", [&] { return handle(id).problem->communicator().sum(value); });
}

/// Largest `value` over the ranks of the problem's communicator.
double feti_max(const long& id, const double& value) {
  return guarded("fetiMax", [&] { return handle(id).problem->communicator().max(value); });
}

std::string* feti_rank_report(Stack stack, const long& id) {
  const std::string text = guarded("fetiRankReport", [&] { return format_rank_report(*handle(id).problem); });
  return Add2StackOfPtr2Free(stack, new std::string(text));
}

/// Numeric factorizations of subdomain matrices this process has run so far: a design
/// step that factorizes each subdomain once, whatever the number of design variables,
/// raises it by the number of subdomains this rank holds.
long feti_factorizations() { return CholmodFactor::factorizations_in_process(); }

/// Wall-clock seconds since an arbitrary origin: FreeFEM's clock() is CPU time, which
/// overstates the time of threaded phases.
double feti_wall_time() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

long feti_free(const long& id) {
  return guarded("fetiFree", [&] {
    handle(id);
    handles().erase(id);
    return 0L;
  });
}

}  // namespace

static void Load_Init() {
  Global.Add("fetiSetup", "(", new OneOperatorCode<FetiSetup>());
  Global.Add("fetiSolve", "(", new OneOperatorCode<FetiSolve>());
  Global.Add("fetiInfo", "(", new OneOperator2_<double, long, std::string*>(feti_info));
  Global.Add("fetiHistory", "(", new OneOperator3_<long, long, std::string*, KN<double>*>(feti_history));
  Global.Add("fetiReport", "(", new OneOperator1s_<std::string*, long>(feti_report));
  Global.Add("fetiSetLoads", "(", new OneOperator2_<long, long, KN<KN<double>>*>(feti_set_loads));
  Global.Add("fetiFree", "(", new OneOperator1_<long, long>(feti_free));
  Global.Add("fetiSensitivity", "(", new OneOperatorCode<FetiSensitivity>());
  Global.Add("fetiAdjoint", "(", new OneOperatorCode<FetiAdjoint>());
  Global.Add("fetiAdjointGradient", "(", new OneOperatorCode<FetiAdjointGradient>());
  Global.Add("fetiContact", "(", new OneOperatorCode<FetiContact>());
  Global.Add("fetiContactStart", "(", new OneOperatorCode<FetiContactStart>());
  Global.Add("fetiContactPressure", "(", new OneOperatorCode<FetiContactPressure>());
  Global.Add("fetiConstraints", "(", new OneOperatorCode<FetiConstraints>());
  Global.Add("fetiSum", "(", new OneOperator2_<double, long, double>(feti_sum));
  Global.Add("fetiMax", "(", new OneOperator2_<double, long, double>(feti_max));
  Global.Add("fetiRank", "(", new OneOperator0<long>(feti_rank));
  Global.Add("fetiIndices", "(", new OneOperator2_<long, KN<double>*, KN<long>*>(feti_indices));
  Global.Add("fetiRanks", "(", new OneOperator0<long>(feti_ranks));
  Global.Add("fetiRankReport", "(", new OneOperator1s_<std::string*, long>(feti_rank_report));
  Global.Add("fetiWallTime", "(", new OneOperator0<double>(feti_wall_time));
  Global.Add("fetiFactorizations", "(", new OneOperator0<long>(feti_factorizations));
  Global.Add("fetiConnectParts", "(", new OneOperator2_<long, pmesh, KN<long>*>(feti_connect_parts));
}

LOADFUNC(Load_Init)
