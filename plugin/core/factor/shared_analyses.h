// CHOLMOD's symbolic analyses (fill-reducing ordering, elimination tree, supernodes) kept
// by sparsity pattern, so that subdomains of one shape (grids of equal boxes) order and
// analyze once: the analysis depends on the pattern alone, the copy is bitwise the same.
#pragma once

#include <cholmod.h>

#include <cstddef>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace ffeti {

/// Thread-safe. Lives while a set of factors is built (FetiProblem::factorize); the factors
/// keep their own copies, so it may be destroyed before them.
class SharedAnalyses {
 public:
  SharedAnalyses();
  ~SharedAnalyses();
  SharedAnalyses(const SharedAnalyses&) = delete;
  SharedAnalyses& operator=(const SharedAnalyses&) = delete;

  /// The symbolic factor kept for A's pattern (and this supernodal setting), copied into
  /// memory of `common`, with the flop count and nnz(L) of its analysis; null if none kept.
  /// `interface` is a part of the key (CholmodFactor::factorize); `interface_last` tells
  /// whether the kept analysis ordered it last.
  cholmod_factor* copy(const cholmod_sparse& A, int supernodal, const std::vector<int>& interface,
                       cholmod_common* common, double* flops, double* nonzeros, bool* interface_last);
  /// Keeps a copy of `symbolic` (analyzed, not yet factorized) for A's pattern.
  void keep(const cholmod_sparse& A, int supernodal, const std::vector<int>& interface, bool interface_last,
            const cholmod_factor& symbolic, double flops, double nonzeros);

  long analyses() const;  ///< analyses kept (one per pattern, more if threads raced on one)
  long reuses() const;    ///< copies handed out instead of an analysis

 private:
  struct Entry {
    int supernodal;
    std::vector<int> start, index;  // the pattern: compressed columns
    std::vector<int> interface;
    bool interface_last;
    cholmod_factor* symbolic;
    double flops, nonzeros;
  };
  const Entry* find(const cholmod_sparse& A, int supernodal, const std::vector<int>& interface, size_t hash) const;

  mutable std::mutex mutex_;
  cholmod_common common_;  // the kept factors' memory
  std::unordered_multimap<size_t, Entry> entries_;  // by the pattern's hash
  long analyses_ = 0, reuses_ = 0;
};

}  // namespace ffeti
