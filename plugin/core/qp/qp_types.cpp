#include "qp/qp_types.h"

namespace ffeti {

std::string to_string(SolveStatus status) {
  switch (status) {
    case SolveStatus::converged: return "converged";
    case SolveStatus::max_iterations: return "max_iterations";
    case SolveStatus::stagnated: return "stagnated";
    case SolveStatus::not_positive_definite: return "not_positive_definite";
    case SolveStatus::infeasible: return "infeasible";
    case SolveStatus::invalid_input: return "invalid_input";
    case SolveStatus::weakly_active: return "weakly_active";
    case SolveStatus::overflow: return "overflow";
    case SolveStatus::inaccurate: return "inaccurate";
  }
  return "unknown";
}

IterationCounts& IterationCounts::operator+=(const IterationCounts& other) {
  outer += other.outer;
  hessian += other.hessian;
  hessian_norm_estimate += other.hessian_norm_estimate;
  cg += other.cg;
  expansion += other.expansion;
  proportioning += other.proportioning;
  expansion_fallback += other.expansion_fallback;
  settle += other.settle;
  penalty_increases += other.penalty_increases;
  preconditioner += other.preconditioner;
  return *this;
}

}  // namespace ffeti
