#include "service/options.h"

#include "base/errors.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace ffeti {
namespace {

constexpr double kIntMax = std::numeric_limits<int>::max();
// More threads than any node has cores only oversubscribe, and OpenMP fails to create tens
// of thousands (a segfault, or the process killed with exit status 1).
constexpr double kMaxThreads = 1024;

double number(const OptionValue& v) {
  return std::holds_alternative<long>(v) ? static_cast<double>(std::get<long>(v)) : std::get<double>(v);
}
int integer(const OptionValue& v) { return static_cast<int>(std::get<long>(v)); }  // range checked before
const std::string& word(const OptionValue& v) { return std::get<std::string>(v); }

/// The value of enum type T the word `w` names, by the option's list of words in `choices` order.
template <class T>
T pick(const OptionValue& v, std::initializer_list<T> choices, const char* const* words) {
  size_t i = 0;
  for (T choice : choices) {
    if (word(v) == words[i]) return choice;
    ++i;
  }
  throw InputError("internal: unmapped word " + word(v));  // the registry checked the word
}

// The settings' defaults (DualSolveSettings, SmalbeSettings, MprgpSettings, FetiSetupSettings)
// are the user defaults; default_text repeats them for the reference, and a unit test
// checks that each default_text parses to the settings' value.
const char* const kVariants[] = {"feti1", "tfeti"};
const char* const kFactors[] = {"auto", "simplicial", "supernodal"};
const char* const kOrderings[] = {"auto", "fill", "interface"};
const char* const kSharing[] = {"on", "off"};
const char* const kDualOperators[] = {"auto", "implicit", "explicit"};
const char* const kCoulombMethods[] = {"auto", "fixed-point", "newton"};
const char* const kPreconditioners[] = {"lumped", "dirichlet", "none"};
const char* const kScalings[] = {"multiplicity", "stiffness"};
const char* const kProjectors[] = {"none", "conjugate"};
const char* const kCoarseGrams[] = {"auto", "contact-last", "separate"};
const char* const kAlgorithms[] = {"smalbe-m", "seed"};
const char* const kExpansions[] = {"projected-cg", "projected-cg-restart", "fixed"};
const char* const kStops[] = {"kkt", "seed"};
const char* const kCoarse[] = {"free-rows", "penalty"};

std::vector<Option> make_options() {
  using S = OptionScope;
  using K = OptionKind;
  return {
      {"variant", S::setup, K::word, {kVariants[0], kVariants[1]}, 0, 0, false, false,
       "`\"feti1\"` for scalar fields, `\"tfeti\"` for vector fields (`component` given)",
       "`\"feti1\"`: Dirichlet dofs eliminated inside K_s (the seed); `\"tfeti\"`: Total FETI, Dirichlet conditions as "
       "constraint rows, every subdomain floats",
       [](SolverSettings& s, const OptionValue& v) {
         s.setup.variant = pick(v, {FetiVariant::feti1, FetiVariant::tfeti}, kVariants);
       }},
      {"factor", S::setup, K::word, {kFactors[0], kFactors[1], kFactors[2]}, 0, 0, false, false, "`\"auto\"`",
       "CHOLMOD factor kind per subdomain; `\"auto\"`: after CHOLMOD's analysis, supernodal (dense blocks through "
       "the BLAS) where the factorization's flops per factor nonzero reach 120 (measured: 3D elasticity subdomains), "
       "simplicial below (small and scalar 2D subdomains); fetiInfo's `supernodal_factors` counts the supernodal ones "
       "([algorithms](algorithms.md)). Under Debian's serial OpenBLAS `\"supernodal\"` runs on one thread and "
       "`\"auto\"` is simplicial when more threads run",
       [](SolverSettings& s, const OptionValue& v) {
         s.setup.factor = pick(v, {FactorKind::automatic, FactorKind::simplicial, FactorKind::supernodal}, kFactors);
       }},
      {"ordering", S::setup, K::word, {kOrderings[0], kOrderings[1], kOrderings[2]}, 0, 0, false, false, "`\"auto\"`",
       "where each subdomain's interface (the dofs its constraint rows touch) goes in its factor's elimination order: "
       "`\"interface\"` last (CHOLMOD's constrained minimum degree), so that a multiplication by the dual operator "
       "solves on the interface alone and reads only its block of the factor, for a factorization of 2-5 times the "
       "flops and a larger factor; `\"fill\"`: CHOLMOD's fill-reducing ordering alone (every solve reads the whole "
       "factor); `\"auto\"`: interface last where the factor is simplicial, a multiplication then skips at least a "
       "third of the factor, and the extra factorization pays for itself within about 90 multiplications (at most "
       "300 extra flops per factor entry skipped): 2D subdomains with a thin interface; 3D ones, whose interfaces are "
       "large against their volume, and subdomains that are nearly all interface keep the fill-reducing ordering. "
       "fetiInfo's `interface_factors` counts them ([algorithms](algorithms.md))",
       [](SolverSettings& s, const OptionValue& v) {
         s.setup.ordering =
             pick(v, {InterfaceOrdering::automatic, InterfaceOrdering::fill_reducing, InterfaceOrdering::interface_last},
                  kOrderings);
       }},
      {"shareFactors", S::setup, K::word, {kSharing[0], kSharing[1]}, 0, 0, false, false, "`\"on\"`",
       "`\"on\"`: subdomains whose stiffness matrices, fixing dofs and interfaces are bitwise equal (boxes of "
       "`ffetiGrid`/`ffetiGrid3` at spacings exact in binary, such as 1/2^k: interior boxes, each face's, each "
       "corner's) share one factorization, each solving through a workspace of its own (and with "
       "`preconditioner = \"dirichlet\"` those whose interior blocks K_ii are bitwise equal share that factor too): "
       "the same answer, bit for bit, from fewer factorizations and less memory; `\"off\"`: one factorization per subdomain (to measure what "
       "sharing saves). fetiInfo's `shared_factors` counts the subdomains that shared",
       [](SolverSettings& s, const OptionValue& v) { s.setup.share_factors = pick(v, {true, false}, kSharing); }},
      {"dualOperator", S::setup, K::word, {kDualOperators[0], kDualOperators[1], kDualOperators[2]}, 0, 0, false,
       false, "`\"auto\"`",
       "how a multiplication by the dual operator applies each subdomain's K_s⁺ on its interface: `\"implicit\"` by "
       "the factor's triangular solves (the interface block's where `ordering` put it last); `\"explicit\"` by a "
       "dense symmetric block of K_s⁺ on the interface (the same generalized inverse, zero on the fixing dofs), "
       "formed once after the factorization (from the factor's interface block where the interface is last, else by "
       "block solves with the identity's columns: several factorizations' time in 3D), shared by subdomains that "
       "share a factor, held as its packed lower triangle: one dense product per multiplication that streams "
       "t(t+1)/2 values for t interface dofs; `\"auto\"`: explicit where the block forms from the interface block "
       "and holds at most the bytes one triangular pass of the factor's solve reads (the 2D subdomains). The "
       "factors stay (loads, primal recovery and sensitivities solve with them). For speed only: the same answers "
       "to round-off. fetiInfo's `explicit_operators` counts the explicit subdomains, `explicit_bytes` their "
       "blocks' memory, `time_explicit` the seconds forming them "
       "([dual operator](results/dual-operator.md))",
       [](SolverSettings& s, const OptionValue& v) {
         s.setup.dual_operator =
             pick(v, {DualOperatorForm::automatic, DualOperatorForm::implicit, DualOperatorForm::explicit_block},
                  kDualOperators);
       }},
      {"preconditioner", S::setup, K::word, {kPreconditioners[0], kPreconditioners[1], kPreconditioners[2]}, 0, 0,
       false, false, "`\"lumped\"`",
       "the preconditioner of the dual problem on every path (CG and projected CG directly; MPRGP in face, also inside "
       "SMALBE-M): `\"lumped\"` M = A (Σ_s B_s K_s B_s') A, A = (BB')⁻¹, no factorization, a sparse product per "
       "application; `\"dirichlet\"`: K_s replaced by its Schur complement on the constrained dofs, one more "
       "factorization per subdomain, shared as `shareFactors` says (without contact: iterations bounded in h); `\"none\"`. Measured in "
       "[scalability](results/scalability.md), [large contact](results/large-contact.md) and on [every "
       "scene](results/accuracy-and-time.md); [algorithms](algorithms.md). Sensitivity and adjoint solves take the "
       "lumped one unless `\"none\"` (no factorization: half the multiplications per direction, "
       "`tests/edp/sensitivity-many-directions.edp`)",
       [](SolverSettings& s, const OptionValue& v) {
         s.setup.preconditioner =
             pick(v, {DualPreconditioner::lumped, DualPreconditioner::dirichlet, DualPreconditioner::none},
                  kPreconditioners);
       }},
      {"scaling", S::setup, K::word, {kScalings[0], kScalings[1]}, 0, 0, false, false, "`\"multiplicity\"`",
       "how the lumped and Dirichlet preconditioners weigh the two sides of each row: `\"multiplicity\"` A = (BB')⁻¹ "
       "(at a node on m subdomains 1/m); `\"stiffness\"` by the stiffness of the other sides there, A = "
       "(B D⁻¹ B')⁻¹ with D the diagonal of each K_s, and D⁻¹ on both sides of K_s (Rixen and Farhat's "
       "k-scaling): the same where the sides are equally stiff (regular grids); with the lumped one 0.78 to "
       "1.05 times the multiplications on unstructured METIS parts (the crowned punch up to 6.5 million "
       "unknowns, [real meshes](results/real-meshes.md#the-preconditioners-weights)); stiffness weights with "
       "the Dirichlet one not measured there "
       "(more on membranes graded 1:1000, `tests/unit/feti_problem_test.cpp`). "
       "For speed only: the same answers to tol. Ignored with `preconditioner = \"none\"`",
       [](SolverSettings& s, const OptionValue& v) {
         s.setup.scaling = pick(v, {InterfaceScaling::multiplicity, InterfaceScaling::stiffness}, kScalings);
       }},
      {"projector", S::setup, K::word, {kProjectors[0], kProjectors[1]}, 0, 0, false, false, "`\"none\"`",
       "where nothing floats (a time step's K + c M, `edp/dynamics.idp`): `\"conjugate\"` solves the dual problem "
       "with the conjugate projector onto the subdomains' rigid modes on the gluing and Dirichlet rows (F applied "
       "once to each mode at set-up; the contact rows untouched): fewer multiplications per step where the step is "
       "long and K + c M nearly floats ([dynamics](results/dynamics.md)); a problem with a coarse space refuses it",
       [](SolverSettings& s, const OptionValue& v) { s.setup.conjugate_projector = pick(v, {false, true}, kProjectors); }},
      {"coarseGram", S::setup, K::word, {kCoarseGrams[0], kCoarseGrams[1], kCoarseGrams[2]}, 0, 0, false, false,
       "`\"auto\"`",
       "how the coarse problem's Gram matrices over fewer multipliers are factorized, the free rows' G_F G_F' and "
       "each primal check's G_S G_S' (they differ from GG' in contact columns only): `\"contact-last\"` from GG''s "
       "factor with the rigid modes of the subdomains on a contact surface eliminated last and a dense Cholesky "
       "factor of their Schur complement; `\"separate\"` a sparse factor of each; `\"auto\"` contact-last from "
       "3000 rigid modes on with at most 6000 of them on a contact surface. For speed only: the same answers to "
       "round-off ([algorithms](algorithms.md), measured in [three dimensions](results/three-dimensions.md))",
       [](SolverSettings& s, const OptionValue& v) {
         s.setup.coarse_gram =
             pick(v, {GramLayout::automatic, GramLayout::contact_last, GramLayout::separate}, kCoarseGrams);
       }},
      {"threads", S::setup, K::integer, {}, 0, kMaxThreads, false, false, "0",
       "OpenMP threads over subdomains (more than 1024 is refused: no node has the cores, and OpenMP fails to create "
       "tens of thousands); 0: in one process `OMP_NUM_THREADS` if set, else all cores less those other processes "
       "keep busy at set-up (OpenMP threads spin while they wait: [busy machine](results/busy-machine.md)); under "
       "MPI the node's cores divided by its ranks",
       [](SolverSettings& s, const OptionValue& v) { s.setup.threads = integer(v); }},
      {"tol", S::solve, K::real, {}, 0, 1, true, true, "1e-4",
       "relative accuracy, the same on every scene: the solve stops when the returned solution violates no "
       "constraint (gluing jump, Dirichlet misfit, penetration) and no complementarity condition (a contact force on "
       "an open gap) by more than `tol ‖u‖∞` and its equilibrium residual `‖Ku − f + B'λ‖` is at most `tol max(‖f‖, "
       "‖B'λ‖)`, both checked on the recovered solution: the relative KKT residuals `fetiInfo` reports are then at "
       "most `tol` ([algorithms](algorithms.md#stopping-test-stopping_testcpp), [every "
       "scene](results/accuracy-and-time.md)); the seed's value. With Coulomb friction also: the last Tresca solve of "
       "the fixed point meets this test and the friction bounds μλ_n of its answer differ from the bounds it was "
       "solved with by at most `tol ‖μλ_n‖∞` (earlier solves stop looser, [algorithms](algorithms.md#friction))",
       [](SolverSettings& s, const OptionValue& v) { s.solve.tolerance = number(v); }},
      {"stop", S::solve, K::word, {kStops[0], kStops[1]}, 0, 0, false, false, "`\"kkt\"`",
       "`\"kkt\"`: the test of `tol`; `\"seed\"`: the seed's `‖gP‖₂ ≤ tol ‖b‖₂` (b the dual right-hand side), whose "
       "accuracy for a given tol depends on the scene (looser with many contact couples) — for comparisons with the "
       "seed",
       [](SolverSettings& s, const OptionValue& v) {
         s.solve.stopping = pick(v, {StoppingTest::relative_kkt, StoppingTest::seed}, kStops);
       }},
      {"maxit", S::solve, K::integer, {}, 1, kIntMax, false, false, "10000",
       "limit on Hessian multiplications (dual operator applications) over the whole solve, all Tresca solves of "
       "Coulomb friction's fixed point together; checked before narrowing: a larger value is an error, not wrapped",
       [](SolverSettings& s, const OptionValue& v) { s.solve.max_hessian = integer(v); }},
      {"algorithm", S::solve, K::word, {kAlgorithms[0], kAlgorithms[1]}, 0, 0, false, false, "`\"smalbe-m\"`",
       "`\"smalbe-m\"` (fixed penalty, adaptive M) or `\"seed\"` (the seed's Algorithm 3.1, growing penalty)",
       [](SolverSettings& s, const OptionValue& v) {
         s.solve.smalbe.variant = pick(v, {SmalbeVariant::smalbe_m, SmalbeVariant::seed_alg31}, kAlgorithms);
       }},
      {"coarse", S::solve, K::word, {kCoarse[0], kCoarse[1]}, 0, 0, false, false, "`\"free-rows\"`",
       "how the balance of floating subdomains (Gλ = e) is kept where there is contact: `\"free-rows\"` moves gluing "
       "and Dirichlet multipliers so that every subdomain stays balanced and leaves to SMALBE-M only the balance of "
       "whole floating bodies (none: MPRGP alone); `\"penalty\"`: all of Gλ = e by SMALBE-M's augmented Lagrangian, "
       "the seed's formulation ([algorithms](algorithms.md#dual-problem-and-coarse-space-dual_operatorcpp-coarse_"
       "spacecpp), [scalability](results/scalability.md))",
       [](SolverSettings& s, const OptionValue& v) {
         s.solve.coarse_constraints = pick(v, {CoarseConstraints::free_rows, CoarseConstraints::penalty}, kCoarse);
       }},
      {"expansion", S::solve, K::word, {kExpansions[0], kExpansions[1], kExpansions[2]}, 0, 0, false, false,
       "`\"projected-cg\"`",
       "MPRGP's expansion step: `\"projected-cg\"` takes the whole CG step projected onto the bounds when it "
       "decreases the cost at least as much as the fixed step is guaranteed to, else the fixed step, and then goes "
       "on with the CG recurrence in the new face (each such step checked against the same guaranteed decrease); "
       "`\"projected-cg-restart\"`: the same step, CG restarted from the free gradient after it; `\"fixed\"`: the "
       "fixed step ᾱ = 1.9/‖A‖ along the free gradient (ALGORITHMS.md). Measured in [large "
       "contact](results/large-contact.md) and [scalability](results/scalability.md)",
       [](SolverSettings& s, const OptionValue& v) {
         s.solve.mprgp.expansion = pick(
             v, {MprgpExpansion::projected_cg, MprgpExpansion::projected_cg_restart, MprgpExpansion::fixed_step},
             kExpansions);
       }},
      {"settle", S::solve, K::integer, {}, 0, kIntMax, false, false, "2",
       "with a start (fetiSolve's `start`): face solves that settle it before MPRGP (conjugate gradients on the "
       "start's contact set with the bounds ignored, then projected onto them, each kept if it lowers the cost; "
       "[algorithms](algorithms.md), measured in [large contact](results/large-contact.md)); 0: MPRGP from the "
       "start as given. Ignored without a start, and by the second and later Tresca solves of Coulomb friction's "
       "fixed point (each starts from the last one's multipliers as they are); its first solve takes at most one",
       [](SolverSettings& s, const OptionValue& v) { s.solve.settle = integer(v); }},
      {"frictionit", S::solve, K::integer, {}, 1, kIntMax, false, false, "50",
       "with Coulomb friction: Tresca solves the fixed point may take; beyond them, or once they have spent `maxit` "
       "multiplications together, the status is `max_iterations` (1), the last iterate returned ([algorithms](algorithms.md#friction)). Without friction: ignored",
       [](SolverSettings& s, const OptionValue& v) { s.solve.friction_iterations = integer(v); }},
      {"coulomb", S::solve, K::word, {kCoulombMethods[0], kCoulombMethods[1], kCoulombMethods[2]}, 0, 0, false, false,
       "`\"auto\"`",
       "with Coulomb friction, how its law is solved: `\"fixed-point\"` by Tresca solves, each with the bounds "
       "μλ_n of the last; `\"newton\"` by semismooth Newton steps after the first Tresca solve (closed rows, "
       "sticking and slipping pairs fixed per step, the linear system by GMRES), whose answer the next Tresca solve "
       "at `tol` must give back (else the fixed point goes on: the same answers and checks either way); `\"auto\"`: "
       "Newton in plane problems (fewer multiplications on static scenes; `\"fixed-point\"` is faster where each "
       "load step starts next to its answer, as time steps of a sliding body do, and at tol 1e-2 or looser), the "
       "fixed point in 3D, where Newton's steps near full slip cost more ([algorithms](algorithms.md#friction), "
       "[hard cases](results/hard-cases.md)). For speed only. Without friction: ignored",
       [](SolverSettings& s, const OptionValue& v) {
         s.solve.coulomb = pick(v, {CoulombMethod::automatic, CoulombMethod::fixed_point, CoulombMethod::newton},
                                kCoulombMethods);
       }},
      {"verbosity", S::solve, K::integer, {}, 0, kIntMax, false, false, "0",
       "1: a line per outer iteration (Hessian multiplications so far, `‖gP‖`, `‖Qμ‖` — the part of the iterate "
       "outside the kernel of the constraints left to SMALBE-M, zero iff Gλ = e — and the contact rows with a "
       "positive multiplier) and a summary; 2: also every inner step",
       [](SolverSettings& s, const OptionValue& v) { s.verbosity = integer(v); }},
      {"rho", S::solve, K::real, {}, 0, HUGE_VAL, true, true, "1.1",
       "penalty as a multiple of the estimated norm of the Hessian (`‖T'PFPT‖`, with `coarse=\"penalty\"` `‖PFP‖`)",
       [](SolverSettings& s, const OptionValue& v) { s.solve.smalbe.rho_factor = number(v); }},
      {"M", S::solve, K::real, {}, 0, HUGE_VAL, true, true,
       "1 (`coarse=\"penalty\"`: 100; `algorithm=\"seed\"`: 10 with FETI-1, 1 with Total FETI)",
       "initial M as a multiple of the inner Hessian's norm `‖H + ρQ‖` (fixed in the seed's algorithm)",
       [](SolverSettings& s, const OptionValue& v) { s.solve.smalbe.M_factor = number(v); }},
      {"eta", S::solve, K::real, {}, 0, HUGE_VAL, true, true, "0.1", "η as a multiple of `‖b‖`",
       [](SolverSettings& s, const OptionValue& v) { s.solve.smalbe.eta_factor = number(v); }},
      {"gamma", S::solve, K::real, {}, 0, HUGE_VAL, true, true, "1", "MPRGP proportioning threshold Γ",
       [](SolverSettings& s, const OptionValue& v) { s.solve.mprgp.gamma = number(v); }},
      {"tol", S::sensitivity, K::real, {}, 0, 1, true, true, "the last `fetiSolve`'s",
       "relative stopping tolerance of the sensitivity problem: the seed's test of `fetiSolve` (`stop=\"seed\"`) "
       "with ‖b‖ replaced by max(‖b‖, ‖B K⁺ fbar‖) (see [algorithms](algorithms.md)); not the KKT test of the "
       "state's solve, so the same value means a different thing here",
       [](SolverSettings& s, const OptionValue& v) { s.solve.tolerance = number(v); }},
      {"maxit", S::sensitivity, K::integer, {}, 1, kIntMax, false, false, "10000",
       "limit on Hessian multiplications of each sensitivity or adjoint solve",
       [](SolverSettings& s, const OptionValue& v) { s.solve.max_hessian = integer(v); }},
      {"activeTol", S::sensitivity, K::real, {}, 0, 1, true, true, "10 × the last solve's `tol`, within [1e-8, 1e-2]",
       "the classification threshold t, relative to the multipliers' and displacements' scales: a multiplier "
       "known to `tol` is zero below about 10 `tol` max λ; not below 1e-8, the round-off of gaps recovered from u "
       "(a tighter tol would otherwise class zero-gap rows as open)",
       [](SolverSettings& s, const OptionValue& v) { s.active_tolerance = number(v); }},
      {"verbosity", S::sensitivity, K::integer, {}, 0, kIntMax, false, false, "0", "as for `fetiSolve`",
       [](SolverSettings& s, const OptionValue& v) { s.verbosity = integer(v); }},
  };
}

std::string format_number(double x) {
  if (x == kIntMax) return "2^31 − 1";
  std::ostringstream out;
  out << x;
  return out.str();
}

/// The accepted values of a number option: "1 .. 2^31 − 1", "> 0", "(0, 1)".
std::string accepted_range(const Option& o) {
  if (o.kind == OptionKind::integer) return format_number(o.lowest) + " .. " + format_number(o.highest);
  if (std::isinf(o.highest)) return std::string(o.open_below ? "> " : ">= ") + format_number(o.lowest);
  return std::string(o.open_below ? "(" : "[") + format_number(o.lowest) + ", " + format_number(o.highest) +
         (o.open_above ? ")" : "]");
}

/// "must lie in 1 .. 2^31 − 1", "must be > 0", "must lie in (0, 1)".
std::string range_text(const Option& o) {
  const bool bound = o.kind == OptionKind::real && std::isinf(o.highest);
  return (bound ? "must be " : "must lie in ") + accepted_range(o);
}

/// `value` checked against option `o`: InputError naming the option otherwise.
void check(const Option& o, const OptionValue& value) {
  const std::string name = o.name;
  if (o.kind == OptionKind::word) {
    if (!std::holds_alternative<std::string>(value)) throw InputError(name + ": must be a word");
    std::string list;
    for (const char* w : o.words) {
      if (word(value) == w) return;
      list += (list.empty() ? "\"" : ", \"") + std::string(w) + "\"";
    }
    throw InputError(name + ": \"" + word(value) + "\" is not one of " + list);
  }
  if (std::holds_alternative<std::string>(value)) throw InputError(name + ": must be a number");
  if (o.kind == OptionKind::integer && !std::holds_alternative<long>(value))
    throw InputError(name + ": must be an integer");
  const double x = number(value);
  const bool below = o.open_below ? !(x > o.lowest) : !(x >= o.lowest);
  const bool above = o.open_above ? !(x < o.highest) : !(x <= o.highest);
  if (below || above) {
    std::ostringstream got;
    got << (std::holds_alternative<long>(value) ? std::to_string(std::get<long>(value)) : format_number(x));
    throw InputError(name + ": " + range_text(o) + ", got " + got.str());
  }
}

}  // namespace

const std::vector<Option>& options() {
  static const std::vector<Option> registry = make_options();
  return registry;
}

const Option* find_option(const std::string& name) {
  for (const Option& o : options())
    if (name == o.name && o.scope != OptionScope::sensitivity) return &o;
  return nullptr;
}

void GivenOptions::set(const Option* o, const std::string& name, OptionValue value) {
  if (!o) throw InputError(name + ": not a solver option");
  check(*o, value);
  given_[name] = std::move(value);
}

FetiSetupSettings GivenOptions::setup(bool vector_field) const {
  SolverSettings s;
  s.setup.variant = vector_field ? FetiVariant::tfeti : FetiVariant::feti1;
  for (const Option& o : options())
    if (o.scope == OptionScope::setup && has(o.name)) o.apply(s, given_.at(o.name));
  return s.setup;
}

SolverSettings GivenOptions::solve(FetiVariant variant) const {
  SolverSettings s;
  for (const Option& o : options())
    if (o.scope == OptionScope::solve && has(o.name)) o.apply(s, given_.at(o.name));
  if (!has("M")) {
    // SMALBE-M: 1 where only the floating bodies' modes are left to it (coarse "free-rows"),
    // 100 where it penalizes all of G ("penalty"; docs/algorithms.md has the measurements).
    // The seed's Algorithm 3.1, whose M stays fixed: 10 with FETI-1 and 1 with Total FETI
    // (Hessian multiplications on the model problem with "penalty", n = 128, 256, 512:
    // FETI-1 44, 50, 77 with 10 against 56, 56, 144 with 100; Total FETI 43, 46, 64 with 1
    // against 56, 63, 157).
    const bool seed = s.solve.smalbe.variant == SmalbeVariant::seed_alg31;
    const bool penalty = s.solve.coarse_constraints == CoarseConstraints::penalty;
    s.solve.smalbe.M_factor = seed ? (variant == FetiVariant::feti1 ? 10.0 : 1.0) : (penalty ? 100.0 : 1.0);
  }
  s.solve.validate();
  return s;
}

SolverSettings GivenOptions::sensitivity() const {
  SolverSettings s;
  for (const Option& o : options())
    if (o.scope == OptionScope::sensitivity && has(o.name)) o.apply(s, given_.at(o.name));
  return s;
}

std::string option_table(OptionScope scope) {
  std::string rows;
  for (const Option& o : options()) {
    if (o.scope != scope) continue;
    const char* type = o.kind == OptionKind::word ? "string" : o.kind == OptionKind::integer ? "int" : "real";
    // | `name` | type | default | accepted | meaning |
    std::string accepted;
    if (o.kind == OptionKind::word) {
      for (const char* w : o.words) accepted += (accepted.empty() ? "one of `\"" : "`, `\"") + std::string(w) + "\"";
      accepted += "`";
    } else {
      accepted = accepted_range(o);
    }
    rows += "| `" + std::string(o.name) + "` | `" + type + "` | " + o.default_text + " | " + accepted + " | " +
            o.meaning + " |\n";
  }
  return rows;
}

std::string preconditioner_name(DualPreconditioner kind) {
  switch (kind) {
    case DualPreconditioner::lumped: return "lumped";
    case DualPreconditioner::dirichlet: return "dirichlet";
    case DualPreconditioner::none: break;
  }
  return "none";
}

}  // namespace ffeti
