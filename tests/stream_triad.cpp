// Not a test: the machine's sustainable memory bandwidth, STREAM-like, for the bound on the
// dual operator's time (scripts/bandwidth_bound.py). Triad a = b + s c and a read-only sum
// over arrays far larger than the caches, best of several runs (the least disturbed by other
// work on a shared machine), on a given number of OpenMP threads.
//   stream_triad [megabytes per array = 256] [runs = 10] [threads = 1]
// Prints one CSV row: threads, array_mb, runs, triad_gb_s, read_gb_s (GB = 1e9 bytes). Triad
// counts 24 bytes per element as STREAM does (two reads, one write; the write-allocate read
// of a is not counted), the sum 8.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  const double megabytes = argc > 1 ? std::atof(argv[1]) : 256;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 10;
  const int threads = argc > 3 ? std::atoi(argv[3]) : 1;
  if (!(megabytes > 0) || runs < 1 || threads < 1) {
    std::fprintf(stderr, "usage: stream_triad [megabytes per array > 0] [runs >= 1] [threads >= 1]\n");
    return 2;
  }
  omp_set_num_threads(threads);
  const auto n = static_cast<long>(megabytes * 1e6 / sizeof(double));
  std::vector<double> a(static_cast<size_t>(n)), b(static_cast<size_t>(n)), c(static_cast<size_t>(n));
  // First touch by the threads that use them (pages placed where they run).
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) a[i] = 0.0, b[i] = 1.0, c[i] = 2.0;
  const double scalar = 3.0;
  double best_triad = 1e300, best_read = 1e300, checksum = 0;
  for (int run = 0; run < runs; ++run) {
    auto start = std::chrono::steady_clock::now();
#pragma omp parallel for schedule(static)
    for (long i = 0; i < n; ++i) a[i] = b[i] + scalar * c[i];
    best_triad = std::min(best_triad, seconds_since(start));
    start = std::chrono::steady_clock::now();
    double sum = 0;
    // simd: the sum may be reordered into vector lanes; one chain of dependent additions
    // would measure the adder's latency (6.5 GB/s here), not the memory.
#pragma omp parallel for simd schedule(static) reduction(+ : sum)
    for (long i = 0; i < n; ++i) sum += a[i];
    best_read = std::min(best_read, seconds_since(start));
    checksum += sum;
  }
  // The sums must be used, or the read loop may be dropped; a = 7 everywhere.
  if (checksum != 7.0 * static_cast<double>(n) * runs) {
    std::fprintf(stderr, "stream_triad: wrong checksum %.17g\n", checksum);
    return 1;
  }
  const double bytes = static_cast<double>(n) * sizeof(double);
  std::printf("threads,array_mb,runs,triad_gb_s,read_gb_s\n%d,%.17g,%d,%.17g,%.17g\n", threads, bytes / 1e6, runs,
              3 * bytes / best_triad / 1e9, bytes / best_read / 1e9);
  return 0;
}
