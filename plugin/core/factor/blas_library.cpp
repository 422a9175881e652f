#include "factor/blas_library.h"

#include <dlfcn.h>

namespace ffeti {
namespace {

BlasLibrary detect() {
  // RTLD_NOLOAD: the libblas.so.3 CHOLMOD already loaded (by soname), nothing new loaded.
  void* blas = dlopen("libblas.so.3", RTLD_LAZY | RTLD_NOLOAD);
  using Query = int (*)();
  auto parallel = reinterpret_cast<Query>(dlsym(blas ? blas : RTLD_DEFAULT, "openblas_get_parallel"));
  const int mode = parallel ? parallel() : -1;
  if (blas) dlclose(blas);  // drops the reference NOLOAD added
  switch (mode) {
    case 0: return BlasLibrary::openblas_sequential;
    case 1: return BlasLibrary::openblas_pthreads;
    case 2: return BlasLibrary::openblas_openmp;
    default: return BlasLibrary::other;
  }
}

}  // namespace

BlasLibrary loaded_blas() {
  static const BlasLibrary blas = detect();
  return blas;
}

const char* blas_name(BlasLibrary blas) {
  switch (blas) {
    case BlasLibrary::openblas_sequential: return "openblas-serial";
    case BlasLibrary::openblas_pthreads: return "openblas-pthread";
    case BlasLibrary::openblas_openmp: return "openblas-openmp";
    case BlasLibrary::other: break;
  }
  return "reference";
}

}  // namespace ffeti
