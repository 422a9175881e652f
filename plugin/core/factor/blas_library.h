// Which BLAS this process called through libblas.so.3 (Debian's alternatives, or
// LD_LIBRARY_PATH): supernodal CHOLMOD factors run on it, and whether they pay and may be
// called from several threads at once depends on which it is.
#pragma once

namespace ffeti {

enum class BlasLibrary {
  other,                ///< the reference BLAS (netlib), or one we cannot name
  openblas_sequential,  ///< Debian's libopenblas0-serial: not safe to call from concurrent threads
  openblas_pthreads,    ///< libopenblas0-pthread: its own thread pool
  openblas_openmp,      ///< libopenblas0-openmp: OpenMP threads, one inside a parallel region
};

/// Read once, from OpenBLAS's openblas_get_parallel() if the loaded libblas.so.3 has it.
BlasLibrary loaded_blas();
const char* blas_name(BlasLibrary blas);

}  // namespace ffeti
