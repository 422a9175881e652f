// A reproducible vector of entries uniform in [-1, 1] for the unit tests.
#pragma once

#include "base/linear_algebra.h"

#include <random>

namespace ffeti {

inline Vec random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Vec v(n);
  for (Eigen::Index i = 0; i < n; ++i) v[i] = value(random);
  return v;
}

}  // namespace ffeti
