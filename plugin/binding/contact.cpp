// The contact forces of a solve as a script uses them: per row (fetiContact), as a pressure
// (fetiContactPressure), as another problem's start (fetiContactStart), and the constraint
// rows for a solver of the undivided problem (fetiConstraints).
#include "binding/arguments.h"
#include "binding/convert.h"
#include "binding/functions.h"
#include "binding/handles.h"

#include "base/errors.h"
#include "constraints/constraint_triplets.h"
#include "service/contact_pressure.h"
#include "service/contact_transfer.h"

#include <functional>

namespace ffeti::binding {
namespace {

/// Fills xc, yc with the slave positions of the contact rows and lc with their multipliers
/// from the last solve (0 before any: the positions serve to build a start); returns the
/// number of contact rows. With friction, tangential= receives each row's friction force
/// (0 without a friction row; in three dimensions its component along t1, tangential2= along
/// t2 of the row's tangent pair), slip= and slip2= the step's slip along t1 and t2, and
/// state= 0 open, 1 stick, 2 slip; zc= the slave nodes' third coordinate (three dimensions);
/// normal=, tangent1=, tangent2= each row's n, t1, t2, d components per row (d = 2 or 3).
/// Signs: docs/reference.md, "Signs of contact and friction".
class FetiContact : public WithNamedArguments {
 public:
  typedef long Result;
  static NamedParameters name_param;
  Expression id, xc, yc, lc;
  explicit FetiContact(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
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
      // An infeasible solve's multipliers are the last iterate of a QP without a solution:
      // forces and states that look plausible and mean nothing.
      if (h.result && h.result->status == SolveStatus::infeasible)
        throw InputError("P: the last fetiSolve found the contact conditions infeasible (status " +
                         std::to_string(status_code(h.result->status)) +
                         "): there are no contact forces or states to report");
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
      if (auto* tangential = optional_pointer<KN<double>>(nargs[0], stack)) {
        tangential->resize(count);
        for (long k = 0; k < count; ++k) (*tangential)[k] = rows[static_cast<size_t>(k)].tangential;
      }
      if (auto* second = optional_pointer<KN<double>>(nargs[3], stack)) {
        second->resize(count);
        for (long k = 0; k < count; ++k) (*second)[k] = rows[static_cast<size_t>(k)].second_tangential;
      }
      if (auto* z = optional_pointer<KN<double>>(nargs[2], stack)) {
        z->resize(count);
        for (long k = 0; k < count; ++k) (*z)[k] = rows[static_cast<size_t>(k)].z;
      }
      const auto per_row = [&](int argument, const std::function<double(const ContactMultiplier&)>& value) {
        if (auto* out = optional_pointer<KN<double>>(nargs[argument], stack)) {
          out->resize(count);
          for (long k = 0; k < count; ++k) (*out)[k] = value(rows[static_cast<size_t>(k)]);
        }
      };
      per_row(7, [](const ContactMultiplier& r) { return r.slip; });
      per_row(8, [](const ContactMultiplier& r) { return r.second_slip; });
      // A vector per row, its d components one after the other.
      const long d = h.problem->space_dimension();
      const auto vectors = [&](int argument, const std::function<Point3(const ContactMultiplier&)>& value) {
        if (auto* out = optional_pointer<KN<double>>(nargs[argument], stack)) {
          out->resize(d * count);
          for (long k = 0; k < count; ++k)
            for (long i = 0; i < d; ++i) (*out)[d * k + i] = value(rows[static_cast<size_t>(k)])[static_cast<size_t>(i)];
        }
      };
      vectors(4, [](const ContactMultiplier& r) { return r.normal; });
      vectors(5, [](const ContactMultiplier& r) { return r.tangents[0]; });
      vectors(6, [](const ContactMultiplier& r) { return r.tangents[1]; });
      if (auto* state = optional_pointer<KN<long>>(nargs[1], stack)) {
        state->resize(count);
        for (long k = 0; k < count; ++k) (*state)[k] = static_cast<long>(rows[static_cast<size_t>(k)].state);
      }
      return count;
    }));
  }
};

NamedParameters FetiContact::name_param = {
    {"tangential", &typeid(KN<double>*)}, {"state", &typeid(KN<long>*)}, {"zc", &typeid(KN<double>*)},
    {"tangential2", &typeid(KN<double>*)}, {"normal", &typeid(KN<double>*)}, {"tangent1", &typeid(KN<double>*)},
    {"tangent2", &typeid(KN<double>*)}, {"slip", &typeid(KN<double>*)}, {"slip2", &typeid(KN<double>*)}};

// ---- int rows = fetiContactPressure(P, Share, Pr, rows=pc, shares=wc) ----------------------
/// The contact pressure of the last solve per dof into Pr (this rank's subdomains, others
/// empty): each contact row's force over its node's share of the contact curve, Share[s]
/// being each dof's share on subdomain s (int1d of the test functions over the contact
/// boundary: a varf's vector). rows= and shares= receive the pressure and the share per
/// contact row (fetiContact's order). Returns the number of contact rows.
class FetiContactPressure : public WithNamedArguments {
 public:
  typedef long Result;
  static NamedParameters name_param;
  Expression id, share_in, pressure_out;
  explicit FetiContactPressure(const basicAC_F0& args) : WithNamedArguments(args, name_param) {
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
        for (int s : problem.global_ids()) share.push_back(to_vec(shares[s]));
      });
      const ContactPressure p = contact_pressure(problem, h.result->lambda, share);
      auto& out = *GetAny<KN<KN<double>>*>((*pressure_out)(stack));
      out.resize(problem.subdomain_count());
      for (long s = 0; s < out.N(); ++s) out[s].resize(0);
      for (size_t k = 0; k < p.per_dof.size(); ++k) copy_to(p.per_dof[k], out[problem.global_ids()[k]]);
      if (auto* rows = optional_pointer<KN<double>>(nargs[0], stack)) copy_to(p.per_row, *rows);
      if (auto* row_shares = optional_pointer<KN<double>>(nargs[1], stack)) copy_to(p.share_per_row, *row_shares);
      return static_cast<long>(p.per_row.size());
    }));
  }
};

NamedParameters FetiContactPressure::name_param = {{"rows", &typeid(KN<double>*)},
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
      // The forces are paired by position: a plane and a solid problem have no common positions.
      if (from.problem->space_dimension() != h.problem->space_dimension())
        throw InputError("Pfrom: is a " + std::string(from.problem->space_dimension() == 3 ? "solid" : "plane") +
                         " problem and P a " + (h.problem->space_dimension() == 3 ? "solid" : "plane") +
                         " one: a start takes the forces of the same kind of problem");
      const auto forces = contact_multipliers(*from.problem, &*from.result);
      if (forces.empty()) throw InputError("Pfrom: has no contact rows, so no contact forces to start from");
      copy_to(start_from_contact_forces(*h.problem, forces), *GetAny<KN<double>*>((*start_out)(stack)));
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
      const ConstraintTriplets t = constraint_triplets(problem.constraints(), problem.inputs(), problem.variant(),
                                                       problem.communicator().size());
      copy_to(t.rows, *GetAny<KN<long>*>((*rows_out)(stack)));
      copy_to(t.columns, *GetAny<KN<long>*>((*columns_out)(stack)));
      copy_to(t.values, *GetAny<KN<double>*>((*values_out)(stack)));
      copy_to(t.rhs, *GetAny<KN<double>*>((*rhs_out)(stack)));
      copy_to(t.kind, *GetAny<KN<long>*>((*kind_out)(stack)));
      return static_cast<long>(t.rhs.size());
    }));
  }
};

}  // namespace

void add_contact_functions() {
  Global.Add("fetiContact", "(", new OneOperatorCode<FetiContact>());
  Global.Add("fetiContactStart", "(", new OneOperatorCode<FetiContactStart>());
  Global.Add("fetiContactPressure", "(", new OneOperatorCode<FetiContactPressure>());
  Global.Add("fetiConstraints", "(", new OneOperatorCode<FetiConstraints>());
}

}  // namespace ffeti::binding
