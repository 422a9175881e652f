// Progress lines of a solve on standard output, shared by the front ends.
#pragma once

#include "parallel/communicator.h"
#include "qp/qp_types.h"

namespace ffeti {

/// Like PETSc's monitors: verbosity 1 prints one line per iteration of the outer solver
/// (SMALBE's multiplier updates, or every MPRGP / CG step), 2 also every inner step. Rank 0
/// prints; verbosity 0 installs no monitor.
Monitor progress_monitor(long verbosity, const Communicator& comm);

}  // namespace ffeti
