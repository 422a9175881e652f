// fetiSetup (the problem's data into the core, which checks it, builds the constraints and
// factorizes), fetiSetLoads (new loads, prescribed values or contact gaps on the same
// factorizations) and fetiFree.
#include "binding/arguments.h"
#include "binding/convert.h"
#include "binding/functions.h"
#include "binding/handles.h"

#include "base/errors.h"
#include "base/parallel_for.h"
#include "constraints/contact/contact_discretization.h"
#include "parallel/mpi_communicator.h"
#include "parallel/ownership.h"

#include <algorithm>
#include <limits>
#include <cmath>
#include <tuple>

namespace ffeti::binding {
namespace {

// ---- int P = fetiSetup(K, F, X, Y, body, dirichlet=..., contactSlave=..., ...) ----------
class FetiSetup : public WithNamedArguments {
 public:
  typedef long Result;
  static NamedParameters name_param;
  Expression K, F, X, Y, body;

  explicit FetiSetup(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
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
  // Named parameters by position in name_param: these, then the per-subdomain lists of the
  // contact kinds that own one (contactMaster=, contactSegments=, ...: kinds_with_lists()) and
  // their scalar arguments (gap=, contactNormal=: list_options()), the arguments of the kinds
  // that own their input (obstacle=, obstacleBall=, ...: kinds_with_input()), each in the
  // registry's order (constraints/contact/registry.cpp), then the set-up options.
  enum Named { kDirichlet, kDirichletValues, kSlave, kComponent, kComm, kRadius, kContactGap, kFriction,
               kSlipBound, kFrictionField, kZ, kSlipBoundField, kStiffnessOf, kReleaseK, kKindLists };
  static size_t list_options_start() { return kKindLists + kinds_with_lists().size(); }
  static size_t kind_arguments_start() { return list_options_start() + list_options().size(); }
  static size_t options_start() { return kind_arguments_start() + kinds_with_input().size(); }

  long setup(Stack stack) const {
    auto& Ks = *GetAny<KN<Matrice_Creuse<double>>*>((*K)(stack));
    const std::shared_ptr<const Communicator> comm =
        communicator(nargs[kComm] ? GetAny<pcommworld>((*nargs[kComm])(stack)) : nullptr);
    // Input errors are raised on every rank together, or the others would wait.
    std::vector<long> stiffness_of;
    collectively(*comm, [&] { stiffness_of = matrix_of_subdomain(stack); });
    const auto count = static_cast<long>(stiffness_of.size());
    collectively(*comm, [&] { check_array_sizes(stack, count); });
    // A subdomain is assembled on a rank where its matrix is (and, for a shared matrix,
    // its load too: every rank may hold the few shared matrices).
    auto& Fs = *GetAny<KN<KN<double>>*>((*F)(stack));
    std::vector<long long> assembled(static_cast<size_t>(count), 0);
    long unshared = -1;  // a subdomain whose load this rank assembled without the matrix it shares
    for (long s = 0; s < count; ++s) {
      const long m = stiffness_of[static_cast<size_t>(s)];
      const bool matrix_here = Ks[m].pHM() && Ks[m].pHM()->n > 0;
      const bool load_here = Fs[s].N() > 0;
      if (nargs[kStiffnessOf] && load_here && !matrix_here && unshared < 0) unshared = s;
      assembled[static_cast<size_t>(s)] = matrix_here && (!nargs[kStiffnessOf] || load_here);
    }
    collectively(*comm, [&] {
      if (unshared < 0) return;
      const std::string m = std::to_string(stiffness_of[static_cast<size_t>(unshared)]);
      throw InputError("K[" + m + "]: empty where F[" + std::to_string(unshared) + "] is assembled (stiffnessOf[" +
                       std::to_string(unshared) + "] = " + m + "): assemble every shared matrix on every rank");
    });
    const std::vector<int> owner = subdomain_owners(assembled, *comm, nargs[kStiffnessOf] ? "F" : "K");
    std::vector<int> ids;
    for (long s = 0; s < count; ++s)
      if (owner[static_cast<size_t>(s)] == comm->rank()) ids.push_back(static_cast<int>(s));
    std::vector<SubdomainInput> subdomains;
    ContactInput contact;
    FetiSetupSettings settings;
    collectively(*comm, [&] {
      settings = setup_settings(stack);
      if (settings.threads == 0) settings.threads = default_threads_per_rank(*comm);
      subdomains = subdomain_inputs(stack, ids, stiffness_of, settings.threads);
      std::vector<long> dofs;
      for (const SubdomainInput& sub : subdomains) dofs.push_back(sub.K.rows());
      add_dirichlet_and_components(stack, count, ids, dofs, subdomains);
      contact = contact_input(stack, count, ids, dofs);
    });
    return add_handle(std::make_unique<FetiProblem>(std::move(subdomains), ids, static_cast<int>(count), contact,
                                                    settings, comm));
  }

  /// The entry of K each subdomain's stiffness is: stiffnessOf= where given (checked against
  /// K's size; the same on every rank, as the script's other arrays), else subdomain s has K[s].
  std::vector<long> matrix_of_subdomain(Stack stack) const {
    const long matrices = GetAny<KN<Matrice_Creuse<double>>*>((*K)(stack))->N();
    std::vector<long> of;
    if (const auto* given = optional_pointer<KN<long>>(nargs[kStiffnessOf], stack)) {
      for (long s = 0; s < given->N(); ++s) {
        const long m = (*given)[s];
        if (m < 0 || m >= matrices)
          throw InputError("stiffnessOf[" + std::to_string(s) + "]: is " + std::to_string(m) + ", K has " +
                           std::to_string(matrices) + " matrices (0 to " + std::to_string(matrices - 1) + ")");
        of.push_back(m);
      }
    } else {
      for (long s = 0; s < matrices; ++s) of.push_back(s);
    }
    return of;
  }

  /// F, X, Y, body and Z need one entry per subdomain, as K (or stiffnessOf=) has.
  void check_array_sizes(Stack stack, long count) const {
    const std::string counted_by = nargs[kStiffnessOf] ? "stiffnessOf has " : "K has ";
    const std::pair<const char*, long> sizes[] = {{"F", GetAny<KN<KN<double>>*>((*F)(stack))->N()},
                                                  {"X", GetAny<KN<KN<double>>*>((*X)(stack))->N()},
                                                  {"Y", GetAny<KN<KN<double>>*>((*Y)(stack))->N()},
                                                  {"body", GetAny<KN<long>*>((*body)(stack))->N()},
                                                  {"Z", nargs[kZ] ? GetAny<KN<KN<double>>*>((*nargs[kZ])(stack))->N()
                                                                  : count}};
    for (const auto& [name, n] : sizes)
      if (n != count)
        throw InputError(std::string(name) + ": has " + std::to_string(n) + " entries, " + counted_by +
                         std::to_string(count) + (nargs[kStiffnessOf] ? " (one per subdomain)" : " subdomains"));
  }

  /// K, F, coordinates and body of the subdomains `ids` this rank holds, converted on
  /// `threads` threads (FreeFEM's arrays are only read). Each matrix of K is converted once
  /// and held once, whatever the number of subdomains that share it (`stiffness_of`).
  std::vector<SubdomainInput> subdomain_inputs(Stack stack, const std::vector<int>& ids,
                                               const std::vector<long>& stiffness_of, int threads) const {
    auto& Ks = *GetAny<KN<Matrice_Creuse<double>>*>((*K)(stack));
    auto& Fs = *GetAny<KN<KN<double>>*>((*F)(stack));
    auto& Xs = *GetAny<KN<KN<double>>*>((*X)(stack));
    auto& Ys = *GetAny<KN<KN<double>>*>((*Y)(stack));
    auto& bodies = *GetAny<KN<long>*>((*body)(stack));
    const auto* Zs = optional_pointer<KN<KN<double>>>(nargs[kZ], stack);
    std::vector<long> matrices;  // the entries of K these subdomains use, each once
    for (int s : ids) matrices.push_back(stiffness_of[static_cast<size_t>(s)]);
    std::sort(matrices.begin(), matrices.end());
    matrices.erase(std::unique(matrices.begin(), matrices.end()), matrices.end());
    std::vector<SharedMatrix> converted(matrices.size());
    // releaseK=true: each script matrix goes as soon as the plugin holds its copy, so that
    // the script's K is gone before the factors come (the set-up's peak memory).
    const bool release = nargs[kReleaseK] && GetAny<bool>((*nargs[kReleaseK])(stack));
    parallel_for_each(static_cast<int>(matrices.size()), threads, [&](int k) {
      const long m = matrices[static_cast<size_t>(k)];
      const std::string name = "K[" + std::to_string(m) + "]";
      converted[static_cast<size_t>(k)] = SharedMatrix(to_sparse(Ks[m], name), name);
      if (release) Ks[m].A.destroy();  // distinct matrices per thread; the Matrice_Creuse stays, empty
    });
    std::vector<SubdomainInput> subdomains(ids.size());
    parallel_for_each(static_cast<int>(ids.size()), threads, [&](int k) {
      const int s = ids[static_cast<size_t>(k)];
      SubdomainInput& sub = subdomains[static_cast<size_t>(k)];
      const auto m = std::lower_bound(matrices.begin(), matrices.end(), stiffness_of[static_cast<size_t>(s)]);
      sub.K = converted[static_cast<size_t>(m - matrices.begin())];
      sub.f = to_vec(Fs[s]);
      sub.x = to_std(Xs[s]);
      sub.y = to_std(Ys[s]);
      if (Zs) sub.z = to_std((*Zs)[s]);
      // Checked here, before the narrowing to int: 2^32 would become body 0, 2^31 a negative one.
      if (bodies[s] < 0 || bodies[s] > std::numeric_limits<int>::max())
        throw InputError("body[" + std::to_string(s) + "]: is " + std::to_string(bodies[s]) +
                         ", body numbers must lie in 0 .. 2^31 - 1");
      sub.body = static_cast<int>(bodies[s]);
    });
    return subdomains;
  }

  /// dirichlet=, dirichletValues= and component= into the subdomains.
  void add_dirichlet_and_components(Stack stack, long count, const std::vector<int>& ids, const std::vector<long>& dofs,
                                    std::vector<SubdomainInput>& subdomains) const {
    const auto dirichlet = per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kDirichlet], stack), count, ids,
                                                  dofs, "dirichlet");
    const auto components = per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kComponent], stack), count,
                                                   ids, dofs, "component");
    const auto* values = optional_pointer<KN<KN<double>>>(nargs[kDirichletValues], stack);
    if (values && values->N() != count)
      throw InputError("dirichletValues: has " + std::to_string(values->N()) + " entries for " +
                       std::to_string(count) + " subdomains");
    for (size_t k = 0; k < ids.size(); ++k) {
      SubdomainInput& sub = subdomains[k];
      if (!dirichlet.empty()) sub.dirichlet_dofs = dirichlet[k];
      if (values) sub.dirichlet_values = to_std((*values)[ids[k]]);
      if (!components.empty()) sub.component = components[k];
    }
  }

  /// contactSlave=, the lists of the kinds that own one (kinds_with_lists()), the arguments of
  /// the kinds that own their input (kinds_with_input()), the list kinds' scalar arguments
  /// (gap=, contactNormal=: list_options()), contactRadius=, contactGap=, friction=,
  /// slipBound=, frictionField=, slipBoundField=.
  ContactInput contact_input(Stack stack, long count, const std::vector<int>& ids, const std::vector<long>& dofs) const {
    ContactInput contact;
    contact.slave_dofs = per_subdomain(optional_pointer<KN<KN<long>>>(nargs[kSlave], stack), count, ids,
                                                dofs, "contactSlave");
    // Each kind that owns a per-subdomain list cuts it into its entries and stores them.
    const auto lists = kinds_with_lists();
    for (size_t i = 0; i < lists.size(); ++i) {
      const char* name = lists[i]->list_input()->argument;
      const auto* given = optional_pointer<KN<KN<long>>>(nargs[kKindLists + i], stack);
      lists[i]->read_list(per_subdomain(given, count, ids, dofs, name), ids, contact);
    }
    // Each kind that owns its input reads and checks its own argument.
    const auto kinds = kinds_with_input();
    for (size_t i = 0; i < kinds.size(); ++i)
      if (const auto* values = optional_pointer<KN<double>>(nargs[kind_arguments_start() + i], stack))
        kinds[i]->read_input(to_std(*values), nargs[kZ] ? 3 : 2, contact);
    // Each list kind's scalar arguments, a word read as its position among the option's words.
    const auto options = list_options();
    for (size_t i = 0; i < options.size(); ++i) {
      const Expression given = nargs[list_options_start() + i];
      if (!given) continue;
      const ListOption& option = *options[i].option;
      double value = 0;
      if (option.words.empty()) {
        value = optional_real(given, stack, 0.0);
      } else {
        const std::string word = optional_string(given, stack, "");
        value = word_position(option, word);
        if (value < 0) throw InputError(std::string(option.argument) + ": " + word_refusal(option, word));
      }
      options[i].kind->read_option(options[i].index, value, contact);
    }
    contact.search_distance = optional_real(nargs[kRadius], stack, contact.search_distance);
    // Not given: -1, no friction rows (a given negative value is refused by the core).
    contact.friction = optional_real(nargs[kFriction], stack, -1.0);
    contact.slip_bound = optional_real(nargs[kSlipBound], stack, -1.0);
    if ((nargs[kFriction] && contact.friction == -1.0) || (nargs[kSlipBound] && contact.slip_bound == -1.0))
      throw InputError(std::string(nargs[kFriction] ? "friction" : "slipBound") + ": must be >= 0, got -1");
    // A value per dof of each law: its scalar (0 if not given) where the field has no entry.
    for (const auto& [argument, name, field, scalar] :
         {std::tuple{kFrictionField, "frictionField", &contact.friction_field, &contact.friction},
          std::tuple{kSlipBoundField, "slipBoundField", &contact.slip_bound_field, &contact.slip_bound}}) {
      const auto* values = optional_pointer<KN<KN<double>>>(nargs[argument], stack);
      if (!values) continue;
      if (values->N() != count)
        throw InputError(std::string(name) + ": has " + std::to_string(values->N()) + " entries for " +
                         std::to_string(count) + " subdomains");
      for (int s : ids) field->push_back(to_std((*values)[s]));
      if (*scalar == -1.0) *scalar = 0.0;
    }
    if (const auto* gaps = optional_pointer<KN<KN<double>>>(nargs[kContactGap], stack)) {
      if (gaps->N() != count)
        throw InputError("contactGap: has " + std::to_string(gaps->N()) + " entries for " + std::to_string(count) +
                         " subdomains");
      for (int s : ids) contact.gap_field.push_back(to_std((*gaps)[s]));
    }
    return contact;
  }

  /// The set-up options (variant=, factor=, threads=, preconditioner=); a vector field is
  /// one with component= given.
  FetiSetupSettings setup_settings(Stack stack) const {
    return given_options(OptionScope::setup, &nargs[options_start()], stack).setup(nargs[kComponent] != nullptr);
  }
};

NamedParameters FetiSetup::name_param = named_parameters(
    [] {
      NamedParameters names{
          {"dirichlet", &typeid(KN<KN<long>>*)},         {"dirichletValues", &typeid(KN<KN<double>>*)},
          {"contactSlave", &typeid(KN<KN<long>>*)},      {"component", &typeid(KN<KN<long>>*)},
          {"comm", &typeid(pcommworld)},                 {"contactRadius", &typeid(double)},
          {"contactGap", &typeid(KN<KN<double>>*)},      {"friction", &typeid(double)},
          {"slipBound", &typeid(double)},                {"frictionField", &typeid(KN<KN<double>>*)},
          {"Z", &typeid(KN<KN<double>>*)},               {"slipBoundField", &typeid(KN<KN<double>>*)},
          {"stiffnessOf", &typeid(KN<long>*)},           {"releaseK", &typeid(bool)}};
      for (const ContactDiscretization* kind : kinds_with_lists())
        names.push_back({kind->list_input()->argument, &typeid(KN<KN<long>>*)});
      for (const KindOption& kind : list_options())
        names.push_back({kind.option->argument, kind.option->words.empty() ? &typeid(double) : &typeid(std::string*)});
      for (const ContactDiscretization* kind : kinds_with_input())
        names.push_back({kind->input()->argument, &typeid(KN<double>*)});
      return names;
    }(),
    OptionScope::setup);

// ---- fetiSetLoads(P, F, dirichletValues=D, contactGap=G): the next load case, load step
// or gap design -------------------------------------------------------------------------
class FetiSetLoads : public WithNamedArguments {
 public:
  typedef long Result;
  static NamedParameters name_param;
  Expression id, loads_in;
  explicit FetiSetLoads(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
    id = to<long>(args[0]);
    loads_in = to<KN<KN<double>>*>(args[1]);
  }
  static ArrayOfaType typeargs() { return ArrayOfaType(atype<long>(), atype<KN<KN<double>>*>()); }
  static E_F0* f(const basicAC_F0& args) { return new FetiSetLoads(args); }
  AnyType operator()(Stack stack) const {
    return SetAny<long>(guarded("fetiSetLoads", [&] {
      Handle& h = handle(GetAny<long>((*id)(stack)));
      const auto& loads = *GetAny<KN<KN<double>>*>((*loads_in)(stack));
      const auto* values = optional_pointer<KN<KN<double>>>(nargs[kDirichletValues], stack);
      const auto* gaps = optional_pointer<KN<KN<double>>>(nargs[kContactGap], stack);
      const int count = h.problem->subdomain_count();
      // One entry per subdomain, as fetiSetup's F; each rank takes its own subdomains' (with
      // all of them handed to the core, a second rank refused the array).
      collectively(h.problem->communicator(), [&] {
        const std::pair<const char*, long> sizes[] = {{"F", loads.N()},
                                                      {"dirichletValues", values ? values->N() : count},
                                                      {"contactGap", gaps ? gaps->N() : count}};
        for (const auto& [name, n] : sizes)
          if (n != count)
            throw InputError(std::string(name) + ": has " + std::to_string(n) + " entries for " +
                             std::to_string(count) + " subdomains");
      });
      std::vector<Vec> f;
      std::vector<std::vector<double>> prescribed, gap_field;
      for (int s : h.problem->global_ids()) {
        f.push_back(to_vec(loads[s]));
        if (values) prescribed.push_back(to_std((*values)[s]));
        if (gaps) gap_field.push_back(to_std((*gaps)[s]));
      }
      // With friction new loads are the next load step: the last solve's state is where its
      // slip is measured from (before any solve, the unloaded state still is).
      if (h.problem->has_friction() && h.result) h.problem->start_load_step(*h.result);
      if (values) h.problem->set_dirichlet_values(prescribed);
      if (gaps) h.problem->set_contact_gaps(gap_field);
      h.problem->set_loads(f);
      h.sensitivity.reset();
      h.result.reset();
      return 0L;
    }));
  }

 private:
  enum Named { kDirichletValues, kContactGap };
};

NamedParameters FetiSetLoads::name_param = {{"dirichletValues", &typeid(KN<KN<double>>*)},
                                            {"contactGap", &typeid(KN<KN<double>>*)}};

/// Frees the problem behind `id`; the handle stays invalid for the life of the process.
long feti_free(const long& id) {
  return guarded("fetiFree", [&] {
    free_handle(id);
    return 0L;
  });
}

}  // namespace

void add_setup_functions() {
  Global.Add("fetiSetup", "(", new OneOperatorCode<FetiSetup>());
  Global.Add("fetiSetLoads", "(", new OneOperatorCode<FetiSetLoads>());
  Global.Add("fetiFree", "(", new OneOperator1_<long, long>(feti_free));
}

}  // namespace ffeti::binding
