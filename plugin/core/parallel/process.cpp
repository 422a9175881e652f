#include "parallel/process.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <string>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace ffeti {

int resolve_thread_count(int requested) {
#ifdef _OPENMP
  return requested > 0 ? requested : omp_get_max_threads();
#else
  (void)requested;
  return 1;
#endif
}

ThreadLimit::ThreadLimit(int threads) {
#ifdef _OPENMP
  if (threads <= 0) return;
  previous_ = omp_get_max_threads();
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
}

ThreadLimit::~ThreadLimit() {
#ifdef _OPENMP
  if (previous_ > 0) omp_set_num_threads(previous_);
#endif
}

namespace {

/// One "Vm...:" line of /proc/self/status in MiB (0 where there is none).
double status_mb(const std::string& wanted) {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == wanted) {
      double kilobytes = 0;
      status >> kilobytes;
      return kilobytes / 1024.0;
    }
    status.ignore(4096, '\n');
  }
  return 0.0;
}

}  // namespace

double peak_memory_mb() { return status_mb("VmHWM:"); }

double resident_memory_mb() { return status_mb("VmRSS:"); }

int threads_for_load(int threads) {
  if (std::getenv("OMP_NUM_THREADS")) return threads;
  std::ifstream loadavg("/proc/loadavg");
  double one, five, fifteen;
  int running = 0, total = 0;
  char slash = 0;
  if (!(loadavg >> one >> five >> fifteen >> running >> slash >> total) || slash != '/') return threads;
  const int others = std::max(0, running - 1);  // the task reading is this process's own
  return std::max(1, std::min(threads, threads - others));
}

}  // namespace ffeti
