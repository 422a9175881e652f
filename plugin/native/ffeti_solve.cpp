// ffeti-solve: the FETI contact solver of the FreeFEM plugin, driven by files instead of a
// FreeFEM script: a gmsh mesh, subdomain systems assembled by GetDP (or any code writing
// Matrix Market) and a JSON problem file. Serial, or under mpirun (subdomain s on rank
// s mod ranks). Usage and file format: docs/reference.md ("ffeti-solve"), docs/getdp.md.
//
// Exit status: 0 converged, 1 not converged (the RESULT line names the status), 2 bad
// input (the message names the file and what is wrong), 3 another failure (out of memory).
#include "service/convergence_history.h"
#include "base/errors.h"
#include "constraints/capabilities.h"
#include "service/options.h"
#include "feti/feti_problem.h"
#include "service/progress_monitor.h"
#include "service/statistics.h"
#include "native/gmsh_mesh.h"
#include "native/native_problem.h"
#include "native/problem_file.h"
#include "native/result_files.h"
#include "parallel/mpi_communicator.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace ffeti::native {
namespace {

constexpr int kConverged = 0, kNotConverged = 1, kBadInput = 2, kFailure = 3;

const char* const kUsage =
    "usage: ffeti-solve PROBLEM.json\n"
    "       ffeti-solve --options setup|solve|sensitivity\n"
    "       ffeti-solve --capabilities\n"
    "  Solves the contact problem described by PROBLEM.json (docs/reference.md, \"ffeti-solve\").\n"
    "  Under mpirun -np P, the subdomains are spread over the ranks by size.\n"
    "  --options: prints the reference's table of the solver options (the \"solver\" object; sensitivity:\n"
    "  fetiSensitivity's and fetiAdjoint's).\n"
    "  --capabilities: prints the reference's table of what each contact kind supports.\n";

/// Every output file can be written: found out before the solve, not after. A file the
/// check creates is removed again, so that a solve that writes nothing leaves nothing.
void check_outputs_writable(const ProblemFile& problem) {
  const OutputSpec& out = problem.output;
  for (const auto& [key, path] : {std::pair{"views", out.views}, {"table", out.table}, {"stress_table", out.stress_table},
                                  {"getdp_solution", out.getdp_solution}, {"history", out.history}}) {
    if (path.empty()) continue;
    const std::string file = resolve(problem, path);
    const bool existed = std::filesystem::exists(file);
    if (!std::ofstream(file, std::ios::app)) throw InputError(problem.path + ": output." + key + ": cannot write " + file);
    if (!existed) std::filesystem::remove(file);
  }
}

/// The likeliest cause here of an inaccurate answer (a stiffness singular beyond the rigid
/// modes its kernel check found): the rows' components taken in another order (a .pro
/// whose FunctionSpaces declare the y displacement first), which leaves the rotations no
/// rigid modes of the matrix. Empty for scalar problems.
std::string component_order_hint(const ProblemFile& problem) {
  if (problem.components == 3)
    return "; ffeti-solve takes components 0, 1, 2 (x, y, z) from a node's first, second and third basis functions: "
           "a .pro declaring them in another order swaps them";
  return problem.components == 2 ? "; ffeti-solve takes component 0 (x) from a node's first basis function and 1 (y) "
                                   "from its second: a .pro declaring y before x swaps them"
                                 : "";
}

int run(const std::string& problem_path, const std::shared_ptr<const Communicator>& comm) {
  ProblemFile problem;
  std::unique_ptr<GmshMesh> mesh;
  NativeInput input;
  collectively(*comm, [&] {
    problem = read_problem_file(problem_path);
    mesh = std::make_unique<GmshMesh>(resolve(problem, problem.mesh));
    input = build_input(problem, *mesh, comm->rank(), comm->size());
    if (comm->rank() == 0) check_outputs_writable(problem);
  });
  const long missing = input.master_segments_total - static_cast<long>(comm->sum(input.master_segments_here));
  if (missing != 0)
    throw InputError(problem.path + ": contact: " + std::to_string(missing) +
                     " master segments lie on no subdomain's triangles (the master curve is not on the boundary "
                     "of the subdomains listed)");
  if (input.setup.threads == 0) input.setup.threads = default_threads_per_rank(*comm);

  const int count = static_cast<int>(problem.subdomains.size());
  std::unique_ptr<FetiProblem> built;
  try {  // the core's checks name K[s], F[s]: the system of subdomains[s]
    built = std::make_unique<FetiProblem>(std::move(input.subdomains), input.ids, count, input.contact, input.setup, comm);
  } catch (const InputError& error) {
    throw InputError(problem.path + ": " + error.what() + " (K[s], F[s]: the system of subdomains[s])");
  }
  const FetiProblem& feti = *built;
  ConvergenceHistory history;
  input.solve.monitor = history.start(progress_monitor(input.verbosity, *comm));
  const FetiResult result = feti.solve(input.solve);

  const GatheredSolution solution = gather_solution(result, input.layouts, count, *comm);
  const std::vector<ContactMultiplier> contact = contact_multipliers(feti, &result);
  // An answer that did not converge (infeasible: pulling contact forces; overflow: not
  // numbers) is not written as a result a post-processor would show as one; the history,
  // which tells why, is.
  const bool converged = result.status == SolveStatus::converged;
  collectively(*comm, [&] {
    if (comm->rank() != 0) return;
    const OutputSpec& out = problem.output;
    if (!out.history.empty()) history.write_csv(resolve(problem, out.history));
    if (!converged) return;
    const NodalResults nodal = nodal_results(problem, *mesh, solution, contact);
    if (!out.views.empty()) write_views(resolve(problem, out.views), problem, *mesh, nodal);
    if (!out.table.empty()) write_table(resolve(problem, out.table), problem, *mesh, nodal);
    if (!out.stress_table.empty()) write_stress_table(resolve(problem, out.stress_table), problem, nodal);
    if (!out.getdp_solution.empty()) write_getdp_solution(resolve(problem, out.getdp_solution), problem, solution);
  });
  // The applied load per component, summed over every subdomain's right-hand side: a load
  // term assembled over a whole curve in each subdomain that touches it shows up here as
  // a multiple of the intended total (GetDP cannot tell, and neither can the solver).
  std::vector<double> load(static_cast<size_t>(problem.components), 0.0);
  for (const SubdomainInput& in : feti.inputs())
    for (Eigen::Index i = 0; i < in.f.size(); ++i)
      load[in.component.empty() ? 0 : static_cast<size_t>(in.component[static_cast<size_t>(i)])] += in.f[i];
  std::ostringstream load_report;
  load_report.precision(10);
  for (size_t c = 0; c < load.size(); ++c) load_report << " load_" << "xyz"[c] << "=" << comm->sum(load[c]);
  const std::string rank_report = format_rank_report(feti);
  if (comm->rank() == 0) {
    std::cout << rank_report << "RESULT " << format_report(feti, &result) << load_report.str() << std::endl;
    if (result.beyond_reach.penetrating > 0)
      std::cerr << "ffeti-solve: WARNING: " << result.beyond_reach.warning() << std::endl;
    if (!converged)
      std::cerr << "ffeti-solve: not converged: " << to_string(result.status)
                << " (no views, tables or GetDP solution written; the history, if asked for, is)"
                << (result.status == SolveStatus::inaccurate ? component_order_hint(problem) : std::string())
                << std::endl;
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
  const std::pair<const char*, ffeti::OptionScope> scopes[] = {
      {"setup", ffeti::OptionScope::setup}, {"solve", ffeti::OptionScope::solve},
      {"sensitivity", ffeti::OptionScope::sensitivity}};
  const auto* scope = argc == 3 && std::strcmp(argv[1], "--options") == 0
                          ? std::find_if(std::begin(scopes), std::end(scopes),
                                         [&](const auto& s) { return std::strcmp(argv[2], s.first) == 0; })
                          : std::end(scopes);
  if (scope != std::end(scopes)) {
    if (rank == 0) std::fputs(ffeti::option_table(scope->second).c_str(), stdout);
    status = 0;
  } else if (argc == 2 && std::strcmp(argv[1], "--capabilities") == 0) {
    if (rank == 0) std::fputs(ffeti::capability_table_markdown().c_str(), stdout);
    status = 0;
  } else if (argc != 2 || std::strcmp(argv[1], "-h") == 0 || std::strcmp(argv[1], "--help") == 0) {
    if (rank == 0) std::fputs(ffeti::native::kUsage, argc == 2 ? stdout : stderr);
    status = argc == 2 ? 0 : ffeti::native::kBadInput;
  } else {
    try {
      status = ffeti::native::run(argv[1], std::make_shared<ffeti::MpiCommunicator>(MPI_COMM_WORLD));
    } catch (const ffeti::InputError& error) {
      if (rank == 0) std::cerr << "ffeti-solve: " << error.what() << std::endl;
      status = ffeti::native::kBadInput;
    } catch (const std::exception& error) {  // not the input: out of memory, a library failure
      std::cerr << "ffeti-solve: rank " << rank << ": failed: " << error.what() << std::endl;
      MPI_Abort(MPI_COMM_WORLD, ffeti::native::kFailure);
    }
  }
  MPI_Finalize();
  return status;
}
