// Spectral norm estimate of a symmetric positive semidefinite operator (Lanczos).
#pragma once

#include "qp/qp_types.h"

namespace ffeti {

struct NormEstimateSettings {
  int iterations = 15;        ///< Lanczos steps at most (multiplications by A)
  /// Stop once the largest Ritz value grows by at most this fraction in a step. On the seed's
  /// model problem 5-6 steps reach what 15 power steps gave (to 1e-4); MPRGP needs the norm
  /// only for its step length abar, which the safety factor keeps below 2/||A||.
  double tolerance = 1e-2;
  double safety_factor = 1.05;///< Ritz values underestimate ||A||; MPRGP needs abar <= 2/||A||
  unsigned seed = 20011;      ///< fixed seed: the same estimate on every run and every rank
};

struct NormEstimate {
  double norm = 0;            ///< safety_factor * the largest Ritz value
  int multiplications = 0;
};

/// Estimates ||A||_2 as the largest eigenvalue of the Lanczos tridiagonal matrix (Krylov
/// space of a pseudo-random start vector, fully reorthogonalized: at most `iterations`
/// vectors are kept). Among estimates from k multiplications it is the best one the Krylov
/// space holds, above the power method's Rayleigh quotient. `start_filter`, if given, is
/// applied to the start vector first (e.g. the coarse projector, so that the iterates live
/// in the subspace where A acts).
NormEstimate estimate_norm(const LinearOperator& A, Eigen::Index size,
                           const NormEstimateSettings& settings = {},
                           const std::function<void(Vec&)>& start_filter = {});

}  // namespace ffeti
