// ffeti-solve: the FETI contact solver of the FreeFEM plugin, driven by files instead of a
// FreeFEM script: a gmsh mesh, subdomain systems assembled by GetDP (or any code writing
// Matrix Market) and a JSON problem file. Serial, or under mpirun (subdomain s on rank
// s mod ranks). Usage and file format: docs/reference.md ("ffeti-solve"), docs/getdp.md.
//
// Exit status: 0 converged, 1 not converged (the RESULT line names the status), 2 bad
// input (the message names the file and what is wrong).
#include "feti/convergence_history.h"
#include "feti/errors.h"
#include "feti/feti_problem.h"
#include "feti/progress_monitor.h"
#include "feti/statistics.h"
#include "native/gmsh_mesh.h"
#include "native/native_problem.h"
#include "native/problem_file.h"
#include "native/result_files.h"
#include "parallel/mpi_communicator.h"

#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <iostream>
#include <memory>
#include <string>

namespace ffeti::native {
namespace {

constexpr int kConverged = 0, kNotConverged = 1, kBadInput = 2;

const char* const kUsage =
    "usage: ffeti-solve PROBLEM.json\n"
    "  Solves the contact problem described by PROBLEM.json (docs/reference.md, \"ffeti-solve\").\n"
    "  Under mpirun -np P, subdomain s is solved on rank s mod P.\n";

int run(const std::string& problem_path, const std::shared_ptr<const Communicator>& comm) {
  ProblemFile problem;
  std::unique_ptr<GmshMesh> mesh;
  NativeInput input;
  collectively(*comm, [&] {
    problem = read_problem_file(problem_path);
    mesh = std::make_unique<GmshMesh>(resolve(problem, problem.mesh));
    std::vector<int> ids;
    for (int s = comm->rank(); s < static_cast<int>(problem.subdomains.size()); s += comm->size()) ids.push_back(s);
    input = build_input(problem, *mesh, ids);
  });
  const long missing = input.master_segments_total - static_cast<long>(comm->sum(input.master_segments_here));
  if (missing != 0)
    throw InputError(problem.path + ": contact: " + std::to_string(missing) +
                     " master segments lie on no subdomain's triangles (the master curve is not on the boundary "
                     "of the subdomains listed)");
  if (input.setup.threads == 0) input.setup.threads = default_threads_per_rank(*comm);

  std::vector<int> ids;
  for (const SubdomainLayout& layout : input.layouts) ids.push_back(layout.id);
  const int count = static_cast<int>(problem.subdomains.size());
  const FetiProblem feti(std::move(input.subdomains), ids, count, input.contact, input.setup, comm);
  ConvergenceHistory history;
  input.solve.monitor = history.start(progress_monitor(problem.solver.verbosity, *comm));
  const FetiResult result = feti.solve(input.solve);

  const GatheredSolution solution = gather_solution(result, input.layouts, count, *comm);
  const std::vector<ContactMultiplier> contact = contact_multipliers(feti, result);
  collectively(*comm, [&] {
    if (comm->rank() != 0) return;
    const OutputSpec& out = problem.output;
    const NodalResults nodal = nodal_results(problem, *mesh, solution, contact);
    if (!out.views.empty()) write_views(resolve(problem, out.views), problem, *mesh, nodal);
    if (!out.table.empty()) write_table(resolve(problem, out.table), *mesh, nodal);
    if (!out.stress_table.empty()) write_stress_table(resolve(problem, out.stress_table), problem, *mesh, nodal);
    if (!out.getdp_solution.empty()) write_getdp_solution(resolve(problem, out.getdp_solution), problem, solution);
    if (!out.history.empty()) history.write_csv(resolve(problem, out.history));
  });
  const std::string rank_report = format_rank_report(feti);
  if (comm->rank() == 0) {
    std::cout << rank_report << "RESULT " << format_report(feti, &result) << std::endl;
    if (result.status != SolveStatus::converged)
      std::cerr << "ffeti-solve: not converged: " << to_string(result.status) << std::endl;
  }
  return result.status == SolveStatus::converged ? kConverged : kNotConverged;
}

}  // namespace
}  // namespace ffeti::native

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int status = ffeti::native::kBadInput;
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (argc != 2 || std::strcmp(argv[1], "-h") == 0 || std::strcmp(argv[1], "--help") == 0) {
    if (rank == 0) std::fputs(ffeti::native::kUsage, argc == 2 ? stdout : stderr);
    status = argc == 2 ? 0 : ffeti::native::kBadInput;
  } else {
    try {
      status = ffeti::native::run(argv[1], std::make_shared<ffeti::MpiCommunicator>(MPI_COMM_WORLD));
    } catch (const ffeti::InputError& error) {
      if (rank == 0) std::cerr << "ffeti-solve: " << error.what() << std::endl;
      status = ffeti::native::kBadInput;
    }
  }
  MPI_Finalize();
  return status;
}
