// Facts about this process for reports.
#pragma once

namespace ffeti {

/// Peak resident memory of this process in MiB (VmHWM of /proc/self/status; 0 if unknown).
double peak_memory_mb();

/// Resident memory of this process now in MiB (VmRSS; 0 if unknown): what a script holds
/// between phases (its meshes, matrices, the plugin's problems).
double resident_memory_mb();

/// OpenMP thread count to use: `requested` if > 0, else the runtime default.
int resolve_thread_count(int requested);

/// Threads for this process out of `threads` (the cores by default) when other processes
/// keep cores busy: `threads` less the tasks running now besides this one (/proc/loadavg),
/// at least 1. OpenMP threads spin while they wait, so on a loaded machine a thread beyond
/// the free cores costs far more than it brings (beside two busy neighbours a lesson took
/// 3.98 s on two fixed threads, 0.25 s with this default: docs/results/busy-machine.md).
/// `threads` unchanged when the user set OMP_NUM_THREADS or /proc cannot be read.
int threads_for_load(int threads);

/// While it lives, every OpenMP region the calling thread opens runs on at most `threads`
/// threads: the plugin's own (they name their count anyway) and its libraries', which
/// take the runtime default: Eigen parallelizes a row-major sparse matrix times a vector
/// (the coarse projector's G) over omp_get_max_threads(). Beside a busy process those
/// threads spin for a core the solve needs: with threads = 1 a 3D block's solve took 1.7 s
/// instead of 0.1 s. Restores the previous limit on destruction. `threads` <= 0: the
/// runtime default, nothing changed.
class ThreadLimit {
 public:
  explicit ThreadLimit(int threads);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  int previous_ = 0;  // the limit to restore; 0: none was changed
};

}  // namespace ffeti
