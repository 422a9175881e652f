// Spectral norm estimate of a symmetric positive semidefinite operator (power method).
#pragma once

#include "qp/qp_types.h"

namespace ffeti {

struct NormEstimateSettings {
  int iterations = 15;        ///< power steps; 10-20 suffice for the step length abar
  double safety_factor = 1.05;///< power iterates underestimate ||A||; MPRGP needs abar <= 2/||A||
  unsigned seed = 20011;      ///< fixed seed: the same estimate on every run and every rank
};

struct NormEstimate {
  double norm = 0;            ///< safety_factor * Rayleigh quotient of the last iterate
  int multiplications = 0;
};

/// Estimates ||A||_2 by power iterations from a pseudo-random start vector. `start_filter`,
/// if given, is applied to the start vector first (e.g. the coarse projector, so that the
/// iterates live in the subspace where A acts).
NormEstimate estimate_norm(const LinearOperator& A, Eigen::Index size,
                           const NormEstimateSettings& settings = {},
                           const std::function<void(Vec&)>& start_filter = {});

}  // namespace ffeti
