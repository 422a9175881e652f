// The sensitivity figures of a handle as named numbers, appended to the problem's
// statistics by fetiInfo and fetiReport.
#pragma once

#include "service/statistics.h"
#include "sens/sensitivity.h"

namespace ffeti {

/// sens_* keys: the classification (strong, weak, inactive, threshold), the counters of
/// direct solves (directions, Hessian multiplications and seconds in all and of the last
/// direction, its status, path and KKT residual) and of the adjoint mode.
Statistics statistics(const SensitivityProblem& sensitivity);

/// "sens_path=... sens_status_name=... " followed by the statistics as key=value pairs.
std::string format_report(const SensitivityProblem& sensitivity);

}  // namespace ffeti
