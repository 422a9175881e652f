#include "qp/conjugate_gradient.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace ffeti {
namespace {
// Round-off, for a stop test that asks for more than the data allow: once the updated
// gradient lies kRoundOffDepth below the first one, a run that sets no new low in
// kStallSteps steps, or grows kGrowth times above its low, no longer follows A x - b and is
// checked as if it had passed the test (the true gradient, then a restart or stagnated).
// Without it a sensitivity solve at tol 1e-15 (tests/edp/sensitivity-3d-faces.edp's blocks)
// stalled at 4e-15 of its first gradient for 70 steps, then grew by round-off to 1e-9 and
// ran to maxit (10,000 multiplications) with a KKT residual of 4. Such a check counts as a
// replacement even where the true gradient agrees with the updated one: grown by round-off,
// both agree, and a run that let them go on (a check counted only on disagreement) sent the
// same adjoint to maxit again. The depth keeps it off ordinary runs: 1e-10 below the first
// gradient lies at the round-off floor of FETI's operators (condition numbers 1e4 to 1e6).
constexpr double kRoundOffDepth = 1e-10;
constexpr int kStallSteps = 25;
constexpr double kGrowth = 100;
/// One CG run advanced one multiplication at a time: next() is the vector A must multiply,
/// take() receives the product. Lets several runs share each application of A.
class CgRun {
 public:
  CgRun(const Vec& b, Vec& x, const CgSettings& settings, int max_hessian, const StopTest& stop,
        const Monitor& monitor, const LinearOperator& preconditioner)
      : b_(b), x_(x), settings_(settings), max_hessian_(max_hessian), stop_(stop), monitor_(monitor),
        preconditioner_(preconditioner) {
    if (x.size() != b.size()) throw std::invalid_argument("CG: x and b differ in size");
    state_ = State::initial;  // next: A x, for g = A x - b
  }

  bool finished() const { return state_ == State::finished; }
  const Vec& next() const { return state_ == State::step ? p_ : x_; }
  const CgResult& result() const { return result_; }

  void take(const Vec& product) {
    ++result_.counts.hessian;
    if (state_ == State::step) {
      const double pAp = p_.dot(product);
      if (!(pAp > 0)) return finish(SolveStatus::not_positive_definite);
      const double a = gz_ / pAp;
      x_ -= a * p_;        // x_{k+1} = x_k - a p
      g_ -= a * product;   // g = A x - b
      g_sq_ = g_.squaredNorm();
      const double gz_next = precondition();
      p_ = z_ + (gz_next / gz_) * p_;  // next A-conjugate direction
      gz_ = gz_next;
      ++result_.counts.cg;
      ++iteration_;
      return advance();
    }
    g_ = product - b_;  // the true gradient A x - b
    g_sq_ = g_.squaredNorm();
    if (state_ == State::verify) {
      result_.gradient_norm = std::sqrt(g_sq_);
      if (monitor_) monitor_({"cg", iteration_, result_.gradient_norm, 0.0, result_.counts.hessian, 0});
      if (stop_(x_, g_, result_.gradient_norm)) return finish(SolveStatus::converged);
      if (++replacements_ > settings_.residual_replacements) return finish(SolveStatus::stagnated);
      ++iteration_;
      lowest_ = std::numeric_limits<double>::infinity();  // the restart's own low
      since_lowest_ = 0;
    }
    gz_ = precondition();
    p_ = z_;
    advance();
  }

 private:
  enum class State { initial, step, verify, finished };

  void finish(SolveStatus status) {
    result_.status = status;
    state_ = State::finished;
  }

  // z = M g (z = g without a preconditioner); returns g'z.
  double precondition() {
    if (preconditioner_) {
      preconditioner_(g_, z_);
      ++result_.counts.preconditioner;
      return g_.dot(z_);
    }
    z_ = g_;
    return g_sq_;
  }

  // From a gradient g: stop, check the true gradient, or ask for the next A p.
  void advance() {
    result_.gradient_norm = std::sqrt(g_sq_);
    if (monitor_) monitor_({"cg", iteration_, result_.gradient_norm, 0.0, result_.counts.hessian, 0});
    if (stop_(x_, g_, result_.gradient_norm)) {
      // Before any step g is the true gradient. After, the updated g drifts from A x - b by
      // round-off; asked for more than the data's accuracy allows, it keeps falling while
      // x does not improve: check the true one, and restart from it (residual replacement).
      if (result_.counts.cg == 0) return finish(SolveStatus::converged);
      state_ = State::verify;
      return;
    }
    if (result_.counts.hessian >= max_hessian_) return finish(SolveStatus::max_iterations);
    state_ = at_round_off() ? State::verify : State::step;
  }

  // True where the updated gradient stalls or grows deep below the first one (kRoundOffDepth).
  bool at_round_off() {
    const double norm = result_.gradient_norm;
    if (first_ < 0) first_ = norm;
    if (norm < lowest_) {
      lowest_ = norm;
      since_lowest_ = 0;
    } else {
      ++since_lowest_;
    }
    return lowest_ <= kRoundOffDepth * first_ && (since_lowest_ >= kStallSteps || norm >= kGrowth * lowest_);
  }

  const Vec& b_;
  Vec& x_;
  Vec g_;  // A x - b
  const CgSettings& settings_;
  const int max_hessian_;  // this run may multiply
  const StopTest& stop_;
  const Monitor& monitor_;
  const LinearOperator& preconditioner_;
  State state_;
  Vec p_, z_;
  double g_sq_ = 0, gz_ = 0;
  int iteration_ = 0, replacements_ = 0;
  double first_ = -1;                                        // the first gradient's norm
  double lowest_ = std::numeric_limits<double>::infinity();  // since the last restart
  int since_lowest_ = 0;                                     // steps without a new low
  CgResult result_;
};

}  // namespace

void CgSettings::validate() const {
  if (residual_replacements < 0) throw std::invalid_argument("CG residual_replacements must be >= 0");
}

CgResult conjugate_gradient(const qp::Problem& problem, const CgSettings& settings, Vec& x, qp::Budget& budget,
                            const StopTest& stop, const Monitor& monitor) {
  settings.validate();
  if (problem.constraints.bounded() || problem.range_projector)
    throw std::invalid_argument("CG: the problem has constraints (MPRGP's or SMALBE's)");
  const LinearOperator& A = problem.hessian;
  const Vec& b = problem.b;
  CgRun run(b, x, settings, budget.remaining(), stop, monitor, problem.preconditioner);
  Vec product(b.size());
  while (!run.finished()) {
    A(run.next(), product);
    run.take(product);
  }
  budget.charge(run.result().counts.hessian);
  return run.result();
}

std::vector<CgResult> conjugate_gradient_block(const BlockOperator& A, const std::vector<Vec>& b,
                                               std::vector<Vec>& x, const CgSettings& settings,
                                               const qp::Budget& budget, const std::vector<StopTest>& stop,
                                               const LinearOperator& preconditioner) {
  settings.validate();
  if (x.size() != b.size() || stop.size() != b.size())
    throw std::invalid_argument("CG block: b, x and stop differ in count");
  const Monitor no_monitor;
  std::vector<CgRun> runs;
  runs.reserve(b.size());
  for (size_t j = 0; j < b.size(); ++j)
    runs.emplace_back(b[j], x[j], settings, budget.remaining(), stop[j], no_monitor, preconditioner);
  Eigen::MatrixXd block, products;
  for (;;) {
    std::vector<size_t> open;
    for (size_t j = 0; j < runs.size(); ++j)
      if (!runs[j].finished()) open.push_back(j);
    if (open.empty()) break;
    block.resize(b[open.front()].size(), static_cast<Eigen::Index>(open.size()));
    for (size_t c = 0; c < open.size(); ++c) block.col(static_cast<Eigen::Index>(c)) = runs[open[c]].next();
    A(block, products);
    for (size_t c = 0; c < open.size(); ++c) runs[open[c]].take(products.col(static_cast<Eigen::Index>(c)));
  }
  std::vector<CgResult> results;
  for (const CgRun& run : runs) results.push_back(run.result());
  return results;
}

}  // namespace ffeti
