// Small functions scripts use around the solver: dof selection, the
// ranks, sums and maxima over them, the factorization count and a wall clock.
#include "binding/convert.h"
#include "binding/functions.h"
#include "binding/handles.h"

#include "base/errors.h"
#include "factor/cholmod_factor.h"
#include "factor/dense_rate.h"
#include "service/statistics.h"
#include "mesh/element_quality.h"
#include "parallel/process.h"

#include <mpi.h>

#include <chrono>
#include <string>
#include <vector>

namespace ffeti::binding {
namespace {

/// Fills `indices` with the positions where `mask` exceeds 1/2 and returns their number: the
/// selection loop of ffetiDofsWhere, which FreeFEM's interpreter runs 100 times slower.
long feti_indices(KN<double>* const& mask, KN<long>* const& indices) {
  long count = 0;
  for (long k = 0; k < mask->N(); ++k) count += (*mask)[k] > 0.5;
  indices->resize(count);
  for (long k = 0, next = 0; k < mask->N(); ++k)
    if ((*mask)[k] > 0.5) (*indices)[next++] = k;
  return count;
}

/// Rank and size of MPI's world communicator; 0 and 1 when MPI is not initialized, so that
/// one script runs under FreeFem++ and FreeFem++-mpi (FreeFEM's mpirank exists only there).
long feti_rank() {
  int initialized = 0, rank = 0;
  MPI_Initialized(&initialized);
  if (initialized) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}
long feti_ranks() {
  int initialized = 0, size = 1;
  MPI_Initialized(&initialized);
  if (initialized) MPI_Comm_size(MPI_COMM_WORLD, &size);
  return size;
}

/// Sum of `value` over the ranks of the problem's communicator (itself in one process).
double feti_sum(const long& id, const double& value) {
  return guarded("fetiSum", [&] { return handle(id).problem->communicator().sum(value); });
}

/// Largest `value` over the ranks of the problem's communicator.
double feti_max(const long& id, const double& value) {
  return guarded("fetiMax", [&] { return handle(id).problem->communicator().max(value); });
}

std::string* feti_rank_report(Stack stack, const long& id) {
  const std::string text = guarded("fetiRankReport", [&] { return format_rank_report(*handle(id).problem); });
  return Add2StackOfPtr2Free(stack, new std::string(text));
}

/// Numeric factorizations of subdomain matrices this process has run so far: a design
/// step that factorizes each subdomain once, whatever the number of design variables,
/// raises it by the number of subdomains this rank holds.
long feti_factorizations() { return CholmodFactor::factorizations_in_process(); }

/// Wall-clock seconds since an arbitrary origin: FreeFEM's clock() is CPU time, which
/// overstates the time of threaded phases.
double feti_wall_time() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// This process's resident memory now and its peak so far, MiB (/proc/self/status): a
/// script measures what each of its phases holds, with or without a problem set up.
double feti_resident_mb() { return resident_memory_mb(); }
double feti_peak_mb() { return peak_memory_mb(); }

/// GFlop/s of a dense matrix product on one thread, measured once per process: beside
/// fetiInfo's factor_flops / time_factor, how near the factorizations run to the machine.
double feti_dense_gflops() { return dense_gflops_one_thread(); }

/// The bound below which |volume| / (longest edge)^3 marks a tetrahedron as flat, the
/// core's (ffeti-solve applies the same): ffeti.idp's ffetiFlatTetrahedron starts from it.
double feti_flat_tetrahedron() { return kFlatTetrahedron; }
/// The same for |area| / (longest edge)^2 of a triangle: ffeti.idp's ffetiFlatTriangle.
double feti_flat_triangle() { return kFlatTriangle; }

/// The name of a status code that fetiSolve, fetiSensitivity or fetiAdjoint returned
/// ("converged", "max_iterations", ..., "infeasible"): scripts print it instead of a number.
std::string* feti_status_name(Stack stack, const long& code) {
  const std::string name = guarded("fetiStatusName", [&] {
    for (int k = 0; k <= static_cast<int>(SolveStatus::inaccurate); ++k)
      if (status_code(static_cast<SolveStatus>(k)) == code) return to_string(static_cast<SolveStatus>(k));
    throw InputError("status: " + std::to_string(code) + " is not a status code of ffeti");
  });
  return Add2StackOfPtr2Free(stack, new std::string(name));
}

}  // namespace

void add_utility_functions() {
  Global.Add("fetiStatusName", "(", new OneOperator1s_<std::string*, long>(feti_status_name));
  Global.Add("fetiSum", "(", new OneOperator2_<double, long, double>(feti_sum));
  Global.Add("fetiMax", "(", new OneOperator2_<double, long, double>(feti_max));
  Global.Add("fetiRank", "(", new OneOperator0<long>(feti_rank));
  Global.Add("fetiIndices", "(", new OneOperator2_<long, KN<double>*, KN<long>*>(feti_indices));
  Global.Add("fetiRanks", "(", new OneOperator0<long>(feti_ranks));
  Global.Add("fetiRankReport", "(", new OneOperator1s_<std::string*, long>(feti_rank_report));
  Global.Add("fetiWallTime", "(", new OneOperator0<double>(feti_wall_time));
  Global.Add("fetiResidentMb", "(", new OneOperator0<double>(feti_resident_mb));
  Global.Add("fetiPeakMb", "(", new OneOperator0<double>(feti_peak_mb));
  Global.Add("fetiDenseGflops", "(", new OneOperator0<double>(feti_dense_gflops));
  Global.Add("fetiFlatTetrahedron", "(", new OneOperator0<double>(feti_flat_tetrahedron));
  Global.Add("fetiFlatTriangle", "(", new OneOperator0<double>(feti_flat_triangle));
  Global.Add("fetiFactorizations", "(", new OneOperator0<long>(feti_factorizations));
}

}  // namespace ffeti::binding
