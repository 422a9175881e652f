// Facts about this process for reports.
#pragma once

namespace ffeti {

/// Peak resident memory of this process in MiB (VmHWM of /proc/self/status; 0 if unknown).
double peak_memory_mb();

/// OpenMP thread count to use: `requested` if > 0, else the runtime default.
int resolve_thread_count(int requested);

/// Threads for this process out of `threads` (the cores by default) when other processes
/// keep cores busy: `threads` less the tasks running now besides this one (/proc/loadavg),
/// at least 1. OpenMP threads spin while they wait, so on a loaded machine a thread beyond
/// the free cores costs far more than it brings (beside two busy neighbours a lesson took
/// 3.98 s on two fixed threads, 0.25 s with this default: docs/results/busy-machine.md).
/// `threads` unchanged when the user set OMP_NUM_THREADS or /proc cannot be read.
int threads_for_load(int threads);

}  // namespace ffeti
