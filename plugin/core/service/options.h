// The solver options users write (fetiSetup's and fetiSolve's named arguments, the "solver"
// object of ffeti-solve's problem file), each once: its name, kind, accepted range or words,
// default, the reference's sentence, and where it goes in the settings. Both front ends read
// them through this registry, so they accept and refuse the same input with the same words,
// and docs/reference.md's option tables are printed from it (ffeti-solve --options).
#pragma once

#include "feti/dual_system.h"
#include "feti/feti_problem.h"

#include <map>
#include <string>
#include <variant>
#include <vector>

namespace ffeti {

/// Where an option acts: the set-up (factorizations, preconditioner), each solve, or the
/// sensitivity functions' solves (fetiSensitivity, fetiAdjoint).
enum class OptionScope { setup, solve, sensitivity };
enum class OptionKind { real, integer, word };

/// What a front end hands over: a number as the user wrote it (integers as long, before any
/// narrowing) or a word.
using OptionValue = std::variant<double, long, std::string>;

/// All settings the options reach.
struct SolverSettings {
  FetiSetupSettings setup;
  DualSolveSettings solve;
  int verbosity = 0;  ///< progress lines: 0 none, 1 per outer iteration, 2 per inner one
  /// Sensitivity: activeTol, the contact rows' classification threshold (0: not given, the
  /// default follows the state's tol).
  double active_tolerance = 0;
};

struct Option {
  const char* name;
  OptionScope scope;
  OptionKind kind;
  std::vector<const char*> words;  ///< word options: the accepted words
  double lowest = 0, highest = 0;  ///< number options: the accepted range...
  bool open_below = false;         ///< ...open at `lowest` (tol, rho: > 0)
  bool open_above = false;
  const char* default_text;        ///< the default as the reference states it
  const char* meaning;             ///< the reference's sentence
  void (*apply)(SolverSettings&, const OptionValue&);  ///< stores a checked value
};

/// Every option, in the order of the reference's tables.
const std::vector<Option>& options();
/// The set-up or solve option named `name` (fetiSetup's, fetiSolve's, ffeti-solve's "solver"
/// keys), or nullptr.
const Option* find_option(const std::string& name);

/// Options a user gave, each checked when given (kind, range or word; numbers before they
/// are narrowed): InputError "<name>: <what is wrong>".
class GivenOptions {
 public:
  /// A set-up or solve option.
  void set(const std::string& name, OptionValue value) { set(find_option(name), name, std::move(value)); }
  /// An option of the registry (any scope).
  void set(const Option& option, OptionValue value) { set(&option, option.name, std::move(value)); }
  bool has(const std::string& name) const { return given_.count(name) > 0; }

  /// The set-up's settings: given values, else the defaults; the variant's default is
  /// FETI-1 for scalar fields (the seed's), Total FETI for vector fields.
  FetiSetupSettings setup(bool vector_field) const;
  /// A solve's settings for a problem of `variant`: given values, else the defaults (M's
  /// depends on the algorithm, the variant and coarse). Validated.
  SolverSettings solve(FetiVariant variant) const;
  /// The sensitivity functions' settings: the given options of scope sensitivity.
  SolverSettings sensitivity() const;

 private:
  void set(const Option* option, const std::string& name, OptionValue value);
  std::map<std::string, OptionValue> given_;
};

/// The Markdown rows of the reference's table of the options of `scope`:
/// | `name` | type | default | accepted values | meaning |
std::string option_table(OptionScope scope);

/// The word naming a preconditioner (the statistics' and reports' spelling).
std::string preconditioner_name(DualPreconditioner kind);

}  // namespace ffeti
