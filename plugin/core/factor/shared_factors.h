// One factorization for subdomains whose stiffness matrices are identical. Grids of equal
// boxes (ffetiGrid, ffetiGrid3) whose coordinates are exact in binary (spacings 1/2^k) give
// bitwise equal matrices for every box of one position class (interior, each face, each
// corner): their generalized inverses are the same, so one factor serves them all, read by
// each through a workspace of its own. The matrices, fixing dofs and interfaces are compared
// entry for entry, never only by hash: sharing is exact or does not happen.
#pragma once

#include "base/linear_algebra.h"
#include "factor/cholmod_factor.h"

#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace ffeti {

/// What building a subdomain's factor gave: the factor, CholmodFactor::factorize's result,
/// and the checks the subdomain judges (reciprocal condition, generalized-inverse residual).
struct FactorOutcome {
  std::shared_ptr<const CholmodFactor> factor;
  int failed = -1;
  double reciprocal_condition = 0;
  double residual = 0;
};

/// Thread-safe. Lives while one FetiProblem::factorize builds its subdomains (one factor kind
/// and ordering); the subdomains hold the factors.
class SharedFactors {
 public:
  /// The outcome for (K, fixing, interface): `build`'s, run on this thread, when no equal
  /// triple was registered before; otherwise the registered one, waiting while another thread
  /// builds it (and rethrowing what its build threw). K is kept by reference, not copied (a
  /// copy of every subdomain's matrix would raise the set-up's peak memory where nothing is
  /// shared): it must outlive this object.
  FactorOutcome obtain(const SparseMatrix& K, const std::vector<int>& fixing, const std::vector<int>& interface,
                       const std::function<FactorOutcome()>& build);

  long built() const;   ///< distinct triples, each factorized once
  long reused() const;  ///< outcomes handed out without a factorization

 private:
  struct Entry {
    const SparseMatrix* K;
    std::vector<int> fixing, interface;
    std::shared_future<FactorOutcome> outcome;
  };
  mutable std::mutex mutex_;
  std::unordered_multimap<size_t, Entry> entries_;  // by a hash of the triple
  std::unordered_map<const SparseMatrix*, size_t> matrix_hashes_;  // of the matrices met so far
  long built_ = 0, reused_ = 0;
};

}  // namespace ffeti
