#include "feti/option_names.h"

#include "feti/errors.h"

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace ffeti {
namespace {

/// The value named `name` among `choices`, or InputError listing them under `option`.
template <class T>
T choose(const std::string& option, const std::string& name, const std::vector<std::pair<const char*, T>>& choices) {
  std::string list;
  for (const auto& [word, value] : choices) {
    if (name == word) return value;
    list += (list.empty() ? "\"" : ", \"") + std::string(word) + "\"";
  }
  throw InputError(option + ": \"" + name + "\" is not one of " + list);
}

}  // namespace

FetiVariant variant_from_name(const std::string& name) {
  return choose<FetiVariant>("variant", name, {{"feti1", FetiVariant::feti1}, {"tfeti", FetiVariant::tfeti}});
}

FactorKind factor_from_name(const std::string& name) {
  return choose<FactorKind>("factor", name,
                            {{"simplicial", FactorKind::simplicial}, {"supernodal", FactorKind::supernodal}});
}

DualPreconditioner preconditioner_from_name(const std::string& name) {
  return choose<DualPreconditioner>("preconditioner", name,
                                    {{"none", DualPreconditioner::none},
                                     {"lumped", DualPreconditioner::lumped},
                                     {"dirichlet", DualPreconditioner::dirichlet}});
}

std::string preconditioner_name(DualPreconditioner kind) {
  switch (kind) {
    case DualPreconditioner::lumped: return "lumped";
    case DualPreconditioner::dirichlet: return "dirichlet";
    case DualPreconditioner::none: break;
  }
  return "none";
}

SmalbeVariant algorithm_from_name(const std::string& name) {
  return choose<SmalbeVariant>("algorithm", name,
                               {{"smalbe-m", SmalbeVariant::smalbe_m}, {"seed", SmalbeVariant::seed_alg31}});
}

MprgpExpansion expansion_from_name(const std::string& name) {
  return choose<MprgpExpansion>("expansion", name,
                                {{"projected-cg", MprgpExpansion::projected_cg},
                                 {"projected-cg-restart", MprgpExpansion::projected_cg_restart},
                                 {"fixed", MprgpExpansion::fixed_step}});
}

StoppingTest stop_from_name(const std::string& name) {
  return choose<StoppingTest>("stop", name, {{"kkt", StoppingTest::relative_kkt}, {"seed", StoppingTest::seed}});
}

CoarseConstraints coarse_from_name(const std::string& name) {
  return choose<CoarseConstraints>("coarse", name,
                                   {{"free-rows", CoarseConstraints::free_rows}, {"penalty", CoarseConstraints::penalty}});
}

const char* default_variant_name(bool vector_field) { return vector_field ? "tfeti" : "feti1"; }

double default_M_factor(SmalbeVariant algorithm, FetiVariant variant, CoarseConstraints coarse) {
  if (algorithm == SmalbeVariant::smalbe_m) return coarse == CoarseConstraints::free_rows ? 1.0 : 100.0;
  return variant == FetiVariant::feti1 ? 10.0 : 1.0;
}

int checked_threads(long threads) {
  // More threads than any node has cores only oversubscribe, and OpenMP fails to create
  // tens of thousands (a segfault, or the process killed with exit status 1).
  constexpr long kMaxThreads = 1024;
  if (threads < 0) throw InputError("threads: must be >= 0 (0: the default)");
  if (threads > kMaxThreads)
    throw InputError("threads: " + std::to_string(threads) + " is more than " + std::to_string(kMaxThreads) +
                     " (give at most the cores of a node, or 0 for the default)");
  return static_cast<int>(threads);
}

int checked_maxit(long maxit) {
  if (maxit < 1 || maxit > std::numeric_limits<int>::max())
    throw InputError("maxit: must lie in 1.." + std::to_string(std::numeric_limits<int>::max()) + ", got " +
                     std::to_string(maxit));
  return static_cast<int>(maxit);
}

}  // namespace ffeti
