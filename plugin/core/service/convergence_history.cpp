#include "service/convergence_history.h"

#include "base/errors.h"

#include <fstream>

namespace ffeti {

Monitor ConvergenceHistory::start(Monitor forward) {
  *this = ConvergenceHistory();
  return [this, forward = std::move(forward)](const ProgressLine& line) {
    time_.push_back(clock_.seconds());
    gradient_.push_back(line.gradient_norm);
    equality_.push_back(line.equality_norm);
    hessian_.push_back(line.hessian);
    active_.push_back(line.active);
    iteration_.push_back(line.iteration);
    solver_.push_back(line.solver);
    if (forward) forward(line);
  };
}

std::vector<double> ConvergenceHistory::column(const std::string& key) const {
  if (key == "time") return time_;
  if (key == "hessian") return hessian_;
  if (key == "gradient") return gradient_;
  if (key == "equality") return equality_;
  if (key == "active") return active_;
  if (key == "iteration") return iteration_;
  throw InputError("key: \"" + key + "\" is not one of \"time\", \"hessian\", \"gradient\", \"equality\", "
                   "\"active\", \"iteration\"");
}

void ConvergenceHistory::write_csv(const std::string& path) const {
  std::ofstream out(path);
  if (!out) throw InputError("history: cannot write \"" + path + "\"");
  out.precision(10);
  out << "time,hessian,gradient,equality,active,iteration,solver\n";
  for (size_t i = 0; i < rows(); ++i)
    out << time_[i] << ',' << hessian_[i] << ',' << gradient_[i] << ',' << equality_[i] << ',' << active_[i] << ','
        << iteration_[i] << ',' << solver_[i] << '\n';
  if (!out) throw InputError("history: writing \"" + path + "\" failed");
}

}  // namespace ffeti
