// The binding's state between calls: set-up problems behind integer handles, and how a
// core error becomes a FreeFEM error.
#pragma once

#include "ff++.hpp"

#include "service/convergence_history.h"
#include "feti/feti_problem.h"
#include "parallel/communicator.h"
#include "sens/sensitivity.h"

#include <memory>
#include <optional>
#include <string>

namespace ffeti::binding {

/// A set-up problem, its last solution and the sensitivity problem of that solution (built
/// by the first sensitivity call after fetiSolve). Lives until fetiFree or the end of the
/// process.
struct Handle {
  std::unique_ptr<FetiProblem> problem;
  std::optional<FetiResult> result;
  double tolerance = DualSolveSettings{}.tolerance;  // of the last solve: the sensitivity's default
  std::unique_ptr<SensitivityProblem> sensitivity;
  ConvergenceHistory history;  // of the last fetiSolve
};

/// Keeps `problem` behind a new handle, never one used before in this process: a script
/// holding a freed handle must get an error, not another problem.
long add_handle(std::unique_ptr<FetiProblem> problem);
/// The problem behind handle `id`, given as the argument `name` (for the error message).
Handle& handle(long id, const char* name = "P");
void free_handle(long id);

/// The script's communicator (named parameter comm; nullptr: none given) if given, else the
/// world communicator under FreeFem++-mpi, else one process. Serial FreeFem++ never
/// initializes MPI.
std::shared_ptr<const Communicator> communicator(void* script_comm);

/// Said whatever the verbosity (rank 0): `function`'s solve stopped at round-off (status 2)
/// after `hessian` multiplications, `reached` (its KKT residual) above `tol`.
void say_stagnated(const Handle& h, const char* function, int hessian, double reached, double tol);

/// Runs `body`, turning every core exception into a FreeFEM error the script can catch.
template <class F>
auto guarded(const char* function, F&& body) -> decltype(body()) {
  try {
    return body();
  } catch (const std::exception& error) {
    const std::string message = std::string(function) + ": " + error.what();
    ExecError(message.c_str());
  }
  return decltype(body())();
}

}  // namespace ffeti::binding
