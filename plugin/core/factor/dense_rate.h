// The machine's dense floating-point rate, measured: the yardstick the report puts beside
// each factorization's rate (a supernodal factorization is dense kernels on its fronts, so
// its GFlop/s can approach this rate and never pass it).
#pragma once

namespace ffeti {

/// GFlop/s of Eigen's dense matrix product C = A B on one thread (n = 512, 2 n^3 flops, the
/// best of three runs: the first warms the caches and the allocator). Measured once per
/// process (0.8 GFlop in all), then returned as measured.
double dense_gflops_one_thread();

}  // namespace ffeti
