#include "service/progress_monitor.h"

#include <cstdio>
#include <memory>
#include <string>

namespace ffeti {

Monitor progress_monitor(long verbosity, const Communicator& comm) {
  if (verbosity < 1 || comm.rank() != 0) return {};
  auto last_outer = std::make_shared<int>(-1);
  return [verbosity, last_outer](const ProgressLine& line) {
    const bool outer_solver = std::string(line.solver) == "smalbe";
    if (outer_solver && verbosity < 2 && line.iteration == *last_outer) return;
    *last_outer = line.iteration;
    std::printf("  ffeti %-6s %4d  hessian %5d  ||gP|| %.3e  ||Q mu|| %.3e  contact %d\n", line.solver, line.iteration,
                line.hessian, line.gradient_norm, line.equality_norm, line.active);
  };
}

}  // namespace ffeti
