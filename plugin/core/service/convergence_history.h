// The convergence history of one solve: a row per progress line of the dual solver (every
// inner iteration of SMALBE-M, every MPRGP or CG iteration) with the wall time since the
// solve began, so that a script can draw accuracy against time or against Hessian
// multiplications from a single solve.
#pragma once

#include "base/stopwatch.h"
#include "qp/qp_types.h"

#include <string>
#include <vector>

namespace ffeti {

class ConvergenceHistory {
 public:
  /// Starts a new history (the clock starts now) and returns the monitor that records into
  /// it and then passes each line on to `forward` (if any). The history must outlive it.
  Monitor start(Monitor forward);

  size_t rows() const { return time_.size(); }
  /// One column by name: time, hessian, gradient, equality, active (contact rows with a
  /// positive multiplier), iteration (SMALBE-M: the outer one). InputError naming `key` for
  /// any other.
  std::vector<double> column(const std::string& key) const;
  /// CSV with a header line, one row per progress line. InputError naming `path` if the file
  /// cannot be written.
  void write_csv(const std::string& path) const;

 private:
  Stopwatch clock_;
  std::vector<double> time_, gradient_, equality_, hessian_, active_, iteration_;
  std::vector<std::string> solver_;
};

}  // namespace ffeti
