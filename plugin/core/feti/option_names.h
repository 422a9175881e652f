// The solver options by the names users write (FreeFEM's fetiSetup/fetiSolve arguments and
// ffeti-solve's problem file): one place for the accepted words, the defaults and the error
// messages, so that both front ends accept and refuse the same input.
#pragma once

#include "feti/dual_system.h"
#include "feti/feti_problem.h"

#include <string>

namespace ffeti {

/// The defaults of the named options (the numeric ones are the settings structs' own).
namespace option_defaults {
inline constexpr const char* factor = "simplicial";
inline constexpr const char* preconditioner = "lumped";
inline constexpr const char* algorithm = "smalbe-m";
inline constexpr const char* expansion = "projected-cg";
inline constexpr const char* stop = "kkt";
inline constexpr const char* coarse = "free-rows";
}  // namespace option_defaults

/// Each throws InputError("<option>: \"<word>\" is not one of ...") for an unknown word.
FetiVariant variant_from_name(const std::string& name);          ///< "feti1", "tfeti"
FactorKind factor_from_name(const std::string& name);            ///< "simplicial", "supernodal"
DualPreconditioner preconditioner_from_name(const std::string& name);  ///< "none", "lumped", "dirichlet"
std::string preconditioner_name(DualPreconditioner kind);
SmalbeVariant algorithm_from_name(const std::string& name);      ///< "smalbe-m", "seed"
MprgpExpansion expansion_from_name(const std::string& name);     ///< "projected-cg", "projected-cg-restart", "fixed"
StoppingTest stop_from_name(const std::string& name);            ///< "kkt", "seed"
CoarseConstraints coarse_from_name(const std::string& name);     ///< "free-rows", "penalty"

/// The default variant: FETI-1 for scalar fields (the seed's), Total FETI for vector fields,
/// whose partially constrained subdomains FETI-1 would have to treat as floating.
const char* default_variant_name(bool vector_field);

/// The default M_factor of SMALBE (M_0 = M_factor ||A||). SMALBE-M: 1 where only the
/// floating bodies' modes are left to it (coarse "free-rows"), 100 where it penalizes all of G
/// ("penalty"; docs/algorithms.md has the measurements). The seed's Algorithm 3.1, whose M
/// stays fixed: 10 with FETI-1 and 1 with Total FETI (Hessian multiplications on the model
/// problem with "penalty", n = 128, 256, 512: FETI-1 44, 50, 77 with 10 against 56, 56, 144
/// with 100; Total FETI 43, 46, 64 with 1 against 56, 63, 157).
double default_M_factor(SmalbeVariant algorithm, FetiVariant variant, CoarseConstraints coarse);

/// threads: 0 (OpenMP's default) to 1024.
int checked_threads(long threads);
/// maxit (Hessian multiplications), checked before it is narrowed to int: a value computed
/// in a script beyond int once wrapped to a small valid one.
int checked_maxit(long maxit);

}  // namespace ffeti
