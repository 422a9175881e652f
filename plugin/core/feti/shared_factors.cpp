#include "feti/shared_factors.h"

#include <algorithm>
#include <cstring>

namespace ffeti {
namespace {

size_t triple_hash(const SparseMatrix& K, const std::vector<int>& fixing, const std::vector<int>& interface) {
  size_t h = std::hash<Eigen::Index>()(K.rows());
  const auto mix = [&h](size_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); };
  const auto mix_ints = [&mix](const int* v, size_t n) {
    for (size_t k = 0; k < n; ++k) mix(std::hash<int>()(v[k]));
  };
  mix_ints(K.outerIndexPtr(), static_cast<size_t>(K.outerSize()) + 1);
  mix_ints(K.innerIndexPtr(), static_cast<size_t>(K.nonZeros()));
  for (Eigen::Index k = 0; k < K.nonZeros(); ++k) {
    uint64_t bits;  // the value's bits: equal matrices are bitwise equal
    std::memcpy(&bits, K.valuePtr() + k, sizeof bits);
    mix(std::hash<uint64_t>()(bits));
  }
  mix_ints(fixing.data(), fixing.size());
  mix_ints(interface.data(), interface.size());
  return h;
}

bool bitwise_equal(const SparseMatrix& a, const SparseMatrix& b) {
  const auto n = static_cast<size_t>(a.nonZeros());
  return a.rows() == b.rows() && a.cols() == b.cols() && a.nonZeros() == b.nonZeros() &&
         std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + n, b.innerIndexPtr()) &&
         std::memcmp(a.valuePtr(), b.valuePtr(), n * sizeof(double)) == 0;
}

}  // namespace

FactorOutcome SharedFactors::obtain(const SparseMatrix& K, const std::vector<int>& fixing,
                                    const std::vector<int>& interface, const std::function<FactorOutcome()>& build) {
  if (!K.isCompressed()) return build();  // compared through its compressed arrays
  const size_t hash = triple_hash(K, fixing, interface);
  std::shared_future<FactorOutcome> registered;
  std::promise<FactorOutcome> promise;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    const auto range = entries_.equal_range(hash);
    for (auto it = range.first; it != range.second && !registered.valid(); ++it)
      if (it->second.fixing == fixing && it->second.interface == interface && bitwise_equal(*it->second.K, K))
        registered = it->second.outcome;
    if (registered.valid()) {
      ++reused_;
    } else {
      entries_.emplace(hash, Entry{&K, fixing, interface, promise.get_future().share()});
      ++built_;
    }
  }
  if (registered.valid()) return registered.get();  // waits, outside the lock, while another thread builds it
  try {
    FactorOutcome outcome = build();
    promise.set_value(outcome);
    return outcome;
  } catch (...) {
    promise.set_exception(std::current_exception());
    throw;
  }
}

long SharedFactors::built() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return built_;
}

long SharedFactors::reused() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return reused_;
}

}  // namespace ffeti
