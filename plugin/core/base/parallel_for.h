// A loop over independent items on OpenMP threads whose errors read as a serial loop's.
#pragma once

#include <exception>
#include <vector>

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
/// rethrown, so a bad input is named the same way whatever the threads' schedule.
template <class Body>
void parallel_for_each(int count, int threads, Body&& body) {
  std::vector<std::exception_ptr> failures(static_cast<size_t>(count > 0 ? count : 0));
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
      failures[static_cast<size_t>(k)] = std::current_exception();
    }
  }
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

}  // namespace ffeti
