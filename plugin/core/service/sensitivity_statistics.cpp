#include "service/sensitivity_statistics.h"

#include <sstream>

namespace ffeti {

Statistics statistics(const SensitivityProblem& sensitivity) {
  const ContactClassification& c = sensitivity.classification();
  const SensitivityCounters& n = sensitivity.counters();
  return {
      {"sens_strong", static_cast<double>(c.strong.size())},
      {"sens_weak", static_cast<double>(c.weak.size())},
      {"sens_inactive", static_cast<double>(c.inactive.size())},
      {"sens_threshold", c.threshold},
      {"sens_dual", sensitivity.dual_dimension()},
      {"sens_time_setup", n.setup_seconds},
      {"sensitivity_solves", n.directions},
      {"sens_hessian_total", static_cast<double>(n.hessian)},
      {"sens_time_total", n.seconds},
      {"sens_status", status_code(n.last.status)},
      {"sens_hessian", n.last.counts.hessian + n.last.counts.hessian_norm_estimate},
      {"sens_time", n.last.seconds},
      {"sens_kkt", n.last.kkt.max()},
      {"sens_one_sided", n.last.one_sided_rows},
      {"adjoint_solves", n.adjoint_solves},
      {"adjoint_status", status_code(n.adjoint.status)},
      {"adjoint_hessian", n.adjoint.counts.hessian},
      {"adjoint_time", n.adjoint.seconds},
      {"adjoint_kkt", n.adjoint.kkt.max()},
      {"adjoint_gradients", n.adjoint_gradients},
      {"adjoint_gradient_time_total", n.adjoint_gradient_seconds},
      {"adjoint_one_sided", n.adjoint.one_sided_rows},
  };
}

std::string format_report(const SensitivityProblem& sensitivity) {
  std::ostringstream out;
  out.precision(10);
  // The path the last solve took (a system whose data call for SMALBE-M may be solved by
  // MPRGP or CG, e.g. without weakly active rows): the system's own before any solve.
  const SensitivityCounters& n = sensitivity.counters();
  out << "sens_path="
      << path_name(n.directions > 0 ? n.last.path : n.adjoint_solves > 0 ? n.adjoint.path : sensitivity.path());
  if (sensitivity.counters().directions > 0) out << " sens_status_name=" << to_string(sensitivity.counters().last.status);
  for (const auto& [key, value] : statistics(sensitivity)) out << ' ' << key << '=' << value;
  return out.str();
}

}  // namespace ffeti
