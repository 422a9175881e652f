// A loop over independent items on OpenMP threads whose errors read as a serial loop's.
#pragma once

#include <exception>
#include <mutex>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace ffeti {

/// The threads a loop of parallel_for_each with threads <= 0 runs on: the runtime's current
/// limit (the set-up's ThreadLimit).
inline int available_threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

/// Runs body(k) for k = 0..count-1 on `threads` OpenMP threads (<= 0: the runtime's
/// current limit). Every item runs; then the exception of the lowest failing k, if any, is
/// rethrown, so a bad input is named the same way whatever the threads' schedule. Nothing
/// is allocated: the dual operator runs its applications through it.
template <class Body>
void parallel_for_each(int count, int threads, Body&& body) {
  std::mutex guard;
  int first_failing = count;
  std::exception_ptr failure;
#ifdef _OPENMP
  const int team = threads > 0 ? threads : available_threads();
#pragma omp parallel for schedule(dynamic) num_threads(team)
#else
  (void)threads;
#endif
  for (int k = 0; k < count; ++k) {
    try {
      body(k);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(guard);
      if (k < first_failing) first_failing = k, failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace ffeti
