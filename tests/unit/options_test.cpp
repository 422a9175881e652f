// The option registry (service/options.h): what both front ends accept and refuse, and that
// the defaults the reference states are the settings' own.
#include "base/errors.h"
#include "service/options.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace ffeti {
namespace {

std::string refusal(const std::string& name, const OptionValue& value) {
  try {
    GivenOptions given;
    given.set(name, value);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Options, RefusesOutOfRangeBeforeNarrowing) {
  EXPECT_EQ(refusal("maxit", 4294967297L), "maxit: must lie in 1 .. 2^31 − 1, got 4294967297");  // once wrapped to 1
  EXPECT_EQ(refusal("maxit", 0L), "maxit: must lie in 1 .. 2^31 − 1, got 0");
  EXPECT_EQ(refusal("threads", 100000L), "threads: must lie in 0 .. 1024, got 100000");
  EXPECT_EQ(refusal("settle", -1L), "settle: must lie in 0 .. 2^31 − 1, got -1");
  EXPECT_EQ(refusal("tol", 1.0), "tol: must lie in (0, 1), got 1");
  EXPECT_EQ(refusal("rho", -1.0), "rho: must be > 0, got -1");
  EXPECT_NE(refusal("rho", std::nan("")), "");
  EXPECT_NE(refusal("gamma", HUGE_VAL), "");
  EXPECT_EQ(refusal("variant", std::string("feti2")), "variant: \"feti2\" is not one of \"feti1\", \"tfeti\"");
  EXPECT_EQ(refusal("maxit", 2.5), "maxit: must be an integer");
  EXPECT_EQ(refusal("tol", std::string("small")), "tol: must be a number");
  EXPECT_EQ(refusal("tolerance", 1e-3), "tolerance: not a solver option");
  EXPECT_EQ(refusal("tol", 3L), "tol: must lie in (0, 1), got 3");
}

TEST(Options, EveryWordIsAccepted) {
  for (const Option& o : options())
    for (const char* word : o.words) EXPECT_EQ(refusal(o.name, std::string(word)), "") << o.name << " " << word;
}

TEST(Options, GivenValuesReachTheSettings) {
  GivenOptions given;
  given.set("tol", 1e-6);
  given.set("maxit", 77L);
  given.set("coarse", std::string("penalty"));
  given.set("preconditioner", std::string("dirichlet"));
  given.set("verbosity", 2L);
  const SolverSettings s = given.solve(FetiVariant::tfeti);
  EXPECT_EQ(s.solve.tolerance, 1e-6);
  EXPECT_EQ(s.solve.max_hessian, 77);
  EXPECT_EQ(s.solve.coarse_constraints, CoarseConstraints::penalty);
  EXPECT_EQ(s.solve.smalbe.M_factor, 100.0);  // the default M of "penalty"
  EXPECT_EQ(s.verbosity, 2);
  EXPECT_EQ(given.setup(true).preconditioner, DualPreconditioner::dirichlet);
}

/// The number a default_text begins with ("1e-4", "1 (`coarse=...`)").
double leading_number(const char* text) { return std::strtod(text, nullptr); }

// The reference is printed from default_text: it must state the settings' own defaults.
TEST(Options, StatedDefaultsAreTheSettingsDefaults) {
  const SolverSettings defaults = GivenOptions().solve(FetiVariant::feti1);
  const FetiSetupSettings setup = GivenOptions().setup(false);
  const std::pair<const char*, double> numbers[] = {
      {"tol", defaults.solve.tolerance},         {"maxit", defaults.solve.max_hessian},
      {"settle", defaults.solve.settle},         {"verbosity", defaults.verbosity},
      {"frictionit", defaults.solve.friction_iterations},
      {"rho", defaults.solve.smalbe.rho_factor}, {"M", defaults.solve.smalbe.M_factor},
      {"eta", defaults.solve.smalbe.eta_factor}, {"gamma", defaults.solve.mprgp.gamma},
      {"threads", setup.threads}};
  for (const auto& [name, value] : numbers) EXPECT_EQ(leading_number(find_option(name)->default_text), value) << name;
  const std::pair<const char*, std::string> words[] = {
      {"preconditioner", preconditioner_name(setup.preconditioner)},
      {"factor", setup.factor == FactorKind::automatic    ? "auto"
                 : setup.factor == FactorKind::simplicial ? "simplicial"
                                                          : "supernodal"},
      {"variant", "feti1"},  // scalar field; "tfeti" for a vector field (below)
      {"algorithm", defaults.solve.smalbe.variant == SmalbeVariant::smalbe_m ? "smalbe-m" : "seed"},
      {"coarse", defaults.solve.coarse_constraints == CoarseConstraints::free_rows ? "free-rows" : "penalty"},
      {"stop", defaults.solve.stopping == StoppingTest::relative_kkt ? "kkt" : "seed"},
      {"expansion", defaults.solve.mprgp.expansion == MprgpExpansion::projected_cg ? "projected-cg" : "other"}};
  for (const auto& [name, word] : words)
    EXPECT_EQ(std::string(find_option(name)->default_text).rfind("`\"" + word + "\"`", 0), 0u) << name;
  EXPECT_EQ(GivenOptions().setup(true).variant, FetiVariant::tfeti);
  // The core's structs default to what a user who passes nothing gets.
  EXPECT_EQ(FetiSetupSettings{}.preconditioner, setup.preconditioner);
  EXPECT_EQ(SmalbeSettings{}.M_factor, defaults.solve.smalbe.M_factor);
  // The sensitivity functions' maxit and verbosity default as fetiSolve's.
  EXPECT_EQ(GivenOptions().sensitivity().solve.max_hessian, defaults.solve.max_hessian);
  EXPECT_EQ(GivenOptions().sensitivity().verbosity, defaults.verbosity);
}

TEST(Options, SensitivityOptionsAreTheirOwnScope) {
  // activeTol is the sensitivity functions', not a "solver" key of ffeti-solve.
  EXPECT_EQ(find_option("activeTol"), nullptr);
  GivenOptions given;
  for (const Option& o : options())
    if (o.scope == OptionScope::sensitivity && std::string(o.name) == "activeTol") given.set(o, 0.05);
  EXPECT_EQ(given.sensitivity().active_tolerance, 0.05);
}

TEST(Options, TablesListEveryOptionOnce) {
  for (const Option& o : options()) {
    // The sensitivity functions' table is apart: it repeats tol, maxit and verbosity.
    const std::string table = o.scope == OptionScope::sensitivity
                                  ? option_table(OptionScope::sensitivity)
                                  : option_table(OptionScope::setup) + option_table(OptionScope::solve);
    const std::string cell = "| `" + std::string(o.name) + "` |";
    ASSERT_NE(table.find(cell), std::string::npos) << o.name;
    EXPECT_EQ(table.find(cell, table.find(cell) + 1), std::string::npos) << o.name;
  }
}

}  // namespace
}  // namespace ffeti
