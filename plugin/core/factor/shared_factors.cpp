#include "factor/shared_factors.h"

#include <algorithm>
#include <cstring>

namespace ffeti {
namespace {

void mix(size_t& h, size_t v) { h ^= v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); }

void mix_ints(size_t& h, const int* v, size_t n) {
  for (size_t k = 0; k < n; ++k) mix(h, std::hash<int>()(v[k]));
}

size_t matrix_hash(const SparseMatrix& K) {
  size_t h = std::hash<Eigen::Index>()(K.rows());
  mix_ints(h, K.outerIndexPtr(), static_cast<size_t>(K.outerSize()) + 1);
  mix_ints(h, K.innerIndexPtr(), static_cast<size_t>(K.nonZeros()));
  for (Eigen::Index k = 0; k < K.nonZeros(); ++k) {
    uint64_t bits;  // the value's bits: equal matrices are bitwise equal
    std::memcpy(&bits, K.valuePtr() + k, sizeof bits);
    mix(h, std::hash<uint64_t>()(bits));
  }
  return h;
}

bool bitwise_equal(const SparseMatrix& a, const SparseMatrix& b) {
  if (&a == &b) return true;  // one matrix shared by both subdomains (stiffnessOf=)
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
  size_t hash = 0;
  {
    // A matrix several subdomains share (stiffnessOf=) is hashed once: the hash reads every
    // entry serially, ~0.3 s for 1024 3D boxes.
    const std::lock_guard<std::mutex> lock(mutex_);
    if (const auto known = matrix_hashes_.find(&K); known != matrix_hashes_.end()) hash = known->second;
  }
  if (hash == 0) {
    hash = matrix_hash(K) | 1;  // never 0, which stands for "not hashed yet"
    const std::lock_guard<std::mutex> lock(mutex_);
    matrix_hashes_.emplace(&K, hash);
  }
  mix_ints(hash, fixing.data(), fixing.size());
  mix_ints(hash, interface.data(), interface.size());
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
