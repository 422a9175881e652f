// What one user call may spend on Hessian multiplications (maxit), like deal.II's
// SolverControl: made and checked once per call (DualSolveSettings::validate), then passed
// by reference down the nesting (friction's fixed point -> each Tresca solve -> SMALBE ->
// its inner MPRGP), each solver charging what it spent. A nested solve so sees what the
// ones before it left, and nothing rebuilds or re-checks the limit on the way down.
#pragma once

namespace ffeti::qp {

class Budget {
 public:
  explicit Budget(int max_hessian);  ///< throws std::invalid_argument unless max_hessian >= 1
  int max_hessian() const { return max_hessian_; }
  int spent() const { return spent_; }
  /// What remains (at least 0): a solver starting now may multiply this often.
  int remaining() const { return spent_ >= max_hessian_ ? 0 : max_hessian_ - spent_; }
  bool exhausted() const { return remaining() == 0; }
  /// Charges `hessian` multiplications (a solver's own, once, when it returns).
  void charge(int hessian) { spent_ += hessian; }

 private:
  int max_hessian_;
  int spent_ = 0;
};

}  // namespace ffeti::qp
