// One row of docs/results/hard-cases.md from a unit test (scripts/hard_cases_table.py reads
// the rows from the tests' XML output).
#pragma once

#include "feti/feti_problem.h"

#include <string>

namespace ffeti::test {

/// One row of the hard-case table: what was solved, how it went and how far it is from the
/// independent answer (`error`, described by `check`). A positive `kkt_bound` also checks
/// the primal KKT residuals, recomputed outside the solver (fetiInfo's).
void record(const std::string& scene, const FetiResult& r, double error, const std::string& check,
            double kkt_bound);

}  // namespace ffeti::test
