#include "factor/shared_analyses.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

namespace ffeti {
namespace {

size_t pattern_hash(const cholmod_sparse& A) {
  const auto* start = static_cast<const int*>(A.p);
  const auto* index = static_cast<const int*>(A.i);
  size_t h = std::hash<size_t>()(A.nrow);
  const auto mix = [&h](int v) { h ^= std::hash<int>()(v) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2); };
  for (size_t j = 0; j <= A.ncol; ++j) mix(start[j]);
  for (int k = 0; k < start[A.ncol]; ++k) mix(index[k]);
  return h;
}

}  // namespace

SharedAnalyses::SharedAnalyses() {
  cholmod_start(&common_);
  common_.print = 0;
  common_.error_handler = nullptr;
}

SharedAnalyses::~SharedAnalyses() {
  for (auto& e : entries_) cholmod_free_factor(&e.second.symbolic, &common_);
  cholmod_finish(&common_);
}

const SharedAnalyses::Entry* SharedAnalyses::find(const cholmod_sparse& A, int supernodal,
                                                  const std::vector<int>& interface, size_t hash) const {
  const auto* start = static_cast<const int*>(A.p);
  const auto* index = static_cast<const int*>(A.i);
  const auto range = entries_.equal_range(hash);
  for (auto it = range.first; it != range.second; ++it) {
    const Entry& e = it->second;
    if (e.supernodal != supernodal || e.start.size() != A.ncol + 1 || e.interface != interface) continue;
    if (std::equal(e.start.begin(), e.start.end(), start) && std::equal(e.index.begin(), e.index.end(), index)) return &e;
  }
  return nullptr;
}

cholmod_factor* SharedAnalyses::copy(const cholmod_sparse& A, int supernodal, const std::vector<int>& interface,
                                     cholmod_common* common, double* flops, double* nonzeros, bool* interface_last) {
  const size_t hash = pattern_hash(A);
  const std::lock_guard<std::mutex> lock(mutex_);
  const Entry* e = find(A, supernodal, interface, hash);
  if (!e) return nullptr;
  cholmod_factor* copy = cholmod_copy_factor(e->symbolic, common);
  if (!copy) throw std::runtime_error("CHOLMOD copy of a symbolic factor failed (out of memory?)");
  *flops = e->flops, *nonzeros = e->nonzeros, *interface_last = e->interface_last;
  ++reuses_;
  return copy;
}

void SharedAnalyses::keep(const cholmod_sparse& A, int supernodal, const std::vector<int>& interface,
                          bool interface_last, const cholmod_factor& symbolic, double flops, double nonzeros) {
  const size_t hash = pattern_hash(A);
  const std::lock_guard<std::mutex> lock(mutex_);
  ++analyses_;
  if (find(A, supernodal, interface, hash)) return;  // another thread analyzed the same pattern meanwhile
  const auto* start = static_cast<const int*>(A.p);
  const auto* index = static_cast<const int*>(A.i);
  cholmod_factor* kept = cholmod_copy_factor(const_cast<cholmod_factor*>(&symbolic), &common_);
  if (!kept) throw std::runtime_error("CHOLMOD copy of a symbolic factor failed (out of memory?)");
  entries_.emplace(hash, Entry{supernodal, std::vector<int>(start, start + A.ncol + 1),
                      std::vector<int>(index, index + start[A.ncol]), interface, interface_last, kept, flops,
                                   nonzeros});
}

long SharedAnalyses::analyses() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return analyses_;
}

long SharedAnalyses::reuses() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return reuses_;
}

}  // namespace ffeti
