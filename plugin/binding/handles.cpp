#include "binding/handles.h"

#include "base/errors.h"
#include "parallel/mpi_communicator.h"

#include <cstdio>
#include <mpi.h>

#include <map>

namespace ffeti::binding {
namespace {

std::map<long, Handle>& handles() {
  static std::map<long, Handle> registry;
  return registry;
}

}  // namespace

long add_handle(std::unique_ptr<FetiProblem> problem) {
  static long next_id = 1;
  const long id = next_id++;
  handles()[id].problem = std::move(problem);
  return id;
}

Handle& handle(long id, const char* name) {
  const auto it = handles().find(id);
  if (it == handles().end())
    throw InputError(std::string(name) + ": no ffeti problem with handle " + std::to_string(id) +
                     " (freed, or not returned by fetiSetup)");
  return it->second;
}

void free_handle(long id) {
  handle(id);
  handles().erase(id);
}

std::shared_ptr<const Communicator> communicator(void* script_comm) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    if (script_comm) throw InputError("comm: MPI is not initialized (run under FreeFem++-mpi)");
    return std::make_shared<SerialCommunicator>();
  }
  return std::make_shared<MpiCommunicator>(script_comm ? *static_cast<MPI_Comm*>(script_comm) : MPI_COMM_WORLD);
}

void say_stagnated(const Handle& h, const char* function, int hessian, double reached, double tol) {
  if (h.problem->communicator().rank() != 0) return;
  std::printf("ffeti: %s: stagnated at round-off after %d Hessian multiplications: KKT residual %.2e, above tol "
              "%.1e, is the best accuracy this problem's data allow (status 2, the answer returned)\n",
              function, hessian, reached, tol);
  std::fflush(stdout);
}

}  // namespace ffeti::binding
