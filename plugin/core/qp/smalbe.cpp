#include "qp/smalbe.h"

#include "qp/held_modes.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace ffeti {
namespace {

/// SMALBE's crawl on the held modes: their imbalance U'x kept within this cosine of its
/// direction over an outer round ...
constexpr double kCrawlCosine = 0.9;
/// ... and above this share of its size.
constexpr double kCrawlShrink = 0.5;

/// The held modes' balance (qp/held_modes.h) as a multiplier step of SMALBE-M, safeguarded.
/// Taken only where the plain updates crawl (above), and only where it moves the multiplier
/// further than the plain update did. A step whose next round ends with a Lagrangian below
/// what the plain update promised (L + rho/2 ||Qx||^2, which a gradient step on the dual
/// function of step rho guarantees) is undone: x, g and nu back to the plain update's, and
/// no step for as many rounds as steps were undone. (Every round a step: q = 0.5 on the 3D
/// block of the onset table lost a round to an undone step in most Tresca solves; without
/// the wait after one undone, SMALBE's plain crawl resumed for the rest of the solve.)
class HeldModeSteps {
 public:
  /// Nothing to balance unless `wanted`, C given and some mode held by boxes and discs alone.
  HeldModeSteps(bool wanted, const qp::Problem& problem, const qp::ConstraintSet& bounds) {
    if (!wanted || !problem.equality_rows) return;
    held_ = std::make_unique<qp::HeldModes>(*problem.equality_rows, bounds);
    if (held_->empty()) held_.reset();
  }

  /// After an inner solve, before the multiplier update: true when the last step is undone
  /// (x, g and nu restored; the round is then over).
  bool undo(double lagrangian, Vec& x, Vec& g, Vec& nu) {
    if (!pending_) return false;
    pending_ = false;
    if (lagrangian >= required_) return false;
    x = x_, g = g_, nu = nu_;
    quiet_rounds_ = ++undone_;
    return true;
  }

  /// After the plain update (`promised`: the Lagrangian it guarantees; g the gradient of
  /// L(x, nu, rho), g0 of L(x, nu, 0)): moves nu and g by the balance where SMALBE crawls.
  void step(const Vec& x, const Vec& g0, double plain_step, double promised, Vec& g, Vec& nu) {
    if (!held_) return;
    const Vec imbalance = held_->basis().transpose() * x;
    const bool crawling = last_imbalance_.size() == imbalance.size() &&
                          imbalance.norm() > kCrawlShrink * last_imbalance_.norm() &&
                          imbalance.dot(last_imbalance_) > kCrawlCosine * imbalance.norm() * last_imbalance_.norm();
    last_imbalance_ = imbalance;
    if (quiet_rounds_ > 0) {
      --quiet_rounds_;
      return;
    }
    Vec d;
    if (!crawling || !held_->balance(g0, d) || !(d.norm() > plain_step)) return;
    pending_ = true;
    x_ = x, g_ = g, nu_ = nu;
    required_ = promised;
    nu += d;
    g += d;
  }

 private:
  std::unique_ptr<qp::HeldModes> held_;
  Vec last_imbalance_;
  int undone_ = 0, quiet_rounds_ = 0;
  bool pending_ = false;
  Vec x_, g_, nu_;  // the plain update's state, to go back to
  double required_ = 0;
};

}  // namespace

void SmalbeSettings::validate() const {
  if (!(rho_factor > 0)) throw std::invalid_argument("SMALBE rho_factor must be > 0");
  if (!(M_factor > 0)) throw std::invalid_argument("SMALBE M_factor must be > 0");
  if (!(eta_factor > 0)) throw std::invalid_argument("SMALBE eta_factor must be > 0");
  if (!(alpha > 0 && alpha < 1)) throw std::invalid_argument("SMALBE alpha must lie in (0, 1)");
  if (!(beta > 1)) throw std::invalid_argument("SMALBE beta must be > 1");
  if (stall_rounds < 1) throw std::invalid_argument("SMALBE stall_rounds must be >= 1");
  inner.validate();
}

SmalbeResult smalbe(const qp::Problem& problem, const SmalbeSettings& settings, Vec& x, qp::Budget& budget,
                    const StopTest& stop, const Monitor& monitor) {
  settings.validate();
  if (!problem.hessian || !problem.range_projector) throw std::invalid_argument("SMALBE: incomplete problem");
  const Vec& b = problem.b;
  const qp::ConstraintSet& bounds = problem.constraints;
  const Eigen::Index n = b.size();
  if (x.size() != n || bounds.size() != n)
    throw std::invalid_argument("SMALBE: x, b and the bounds differ in size");
  if (!(problem.hessian_norm > 0)) throw std::invalid_argument("SMALBE: ||H|| must be > 0");

  SmalbeResult result;
  double rho = settings.rho_factor * problem.hessian_norm;
  double M = settings.M_factor * std::max(problem.hessian_norm, rho);
  // eta bounds ||gP|| in SMALBE-M (units of b) but ||Qx|| in the seed's Algorithm 3.1
  // (units of x): scale it by 1/||A|| there.
  double eta = settings.eta_factor * b.norm() /
               (settings.variant == SmalbeVariant::smalbe_m ? 1.0 : std::max(problem.hessian_norm, rho));
  Vec& nu = result.multiplier;  // multiplier term C'mu, kept in Im C'
  nu = problem.equality_multiplier.size() == n ? problem.equality_multiplier : Vec::Zero(n);
  Vec shifted_b = b - nu;          // linear term of the inner problem
  Vec Qx(n), Qv(n), g(n);  // Qx: Q at the iterate; Qv: scratch of the operator A
  bool gradient_is_current = false;
  double gradient_error = 0;  // of g, left by MPGP's sliding steps (discs): carried, not recomputed
  double previous_lagrangian = std::numeric_limits<double>::infinity();
  double best_q_norm = std::numeric_limits<double>::infinity();
  int stalled_rounds = 0;

  // A = H + rho Q: on Ker C it acts as H, on Im C' as rho, so ||A|| <= max(||H||, rho).
  int applications = 0;  // of A, for the progress lines
  const LinearOperator A = [&](const Vec& v, Vec& Av) {
    ++applications;
    problem.hessian(v, Av);
    problem.range_projector(v, Qv);
    Av += rho * Qv;
  };

  LinearOperator inner_preconditioner;
  Vec Pv(n), Mv(n), QMv(n), Qp(n);  // the preconditioner's buffers
  if (problem.preconditioner)
    inner_preconditioner = [&](const Vec& v, Vec& y) {
      problem.range_projector(v, Qp);
      Pv = v - Qp;
      problem.preconditioner(Pv, Mv);
      problem.range_projector(Mv, QMv);
      y = Mv - QMv + Qp / rho;  // P M P v + Q v / rho
    };

  // The bound-constrained subproblem min L(x, nu, rho): A, b - nu and the bounds.
  qp::Problem inner_problem;
  inner_problem.hessian = A;
  inner_problem.preconditioner = inner_preconditioner;
  inner_problem.constraints = bounds;

  // The modes friction alone holds, balanced where SMALBE crawls (smalbe_m).
  HeldModeSteps held(settings.balance_held_modes && settings.variant == SmalbeVariant::smalbe_m, problem, bounds);

  for (int outer = 0;; ++outer) {
    bool globally_done = false;
    bool first_call = true;
    const StopTest inner_stop = [&](const Vec& xi, const Vec& gi, double gp_norm) {
      problem.range_projector(xi, Qx);
      const double q_norm = Qx.norm();
      // Projected gradient of L(x, nu, 0): the gradient without its penalty part rho Q x.
      const Vec gp0 = bounds.projected_gradient(xi, gi - rho * Qx);
      result.gradient_norm = gp0.norm();
      result.equality_norm = q_norm;
      if (monitor)
        monitor({"smalbe", outer, result.gradient_norm, q_norm, applications, bounds.off_bound_count(xi)});
      if (stop(xi, gp0, result.gradient_norm)) return globally_done = true;
      // At least one inner step per outer iteration: a multiplier update that the inner
      // solver does not answer only grows nu, and can stall the outer loop for many rounds.
      if (first_call) return first_call = false;
      const double bound = settings.variant == SmalbeVariant::smalbe_m ? std::min(M * q_norm, eta)
                                                                        : M * q_norm;
      return gp_norm <= bound;
    };
    if (budget.exhausted()) {  // the inner solves charged it
      result.status = SolveStatus::max_iterations;
      return result;
    }
    MprgpSettings inner = settings.inner;
    if (outer > 0) inner.settle_rounds = 0;  // a start is settled once, not every multiplier update
    inner_problem.b = shifted_b;
    inner_problem.hessian_norm = std::max(problem.hessian_norm, rho);
    const MprgpResult inner_result =
        mprgp_with_gradient(inner_problem, inner, x, g, gradient_is_current,
                            budget, inner_stop, {}, &gradient_error);
    result.counts += inner_result.counts;
    result.rho = rho;
    if (globally_done) {
      result.status = SolveStatus::converged;
      return result;
    }
    if (inner_result.status != SolveStatus::converged) {
      result.status = inner_result.status;
      return result;
    }
    // No cap on outer iterations beside the budget: each costs at least one multiplication,
    // and near the onset of sliding a Tresca solve takes hundreds of cheap ones while its
    // multiplier crawls (a cap of 200 ended the 3D block at 0.999 mu W far below maxit).
    ++result.counts.outer;

    // Q x is current: the inner stop test computed it at this x.
    const double q_norm = Qx.norm();
    const double lagrangian = 0.5 * x.dot(g - shifted_b);  // L(x, nu, rho) = 1/2 x'Ax - x'(b - nu)
    if (held.undo(lagrangian, x, g, nu)) {
      shifted_b = b - nu;
      gradient_is_current = true;
      continue;
    }
    const double promised = lagrangian + 0.5 * rho * q_norm * q_norm;
    nu += rho * Qx;          // multiplier update mu <- mu + rho C x
    shifted_b = b - nu;
    g += rho * Qx;           // g = A x - (b - nu) with the new nu
    gradient_is_current = true;

    if (settings.variant == SmalbeVariant::smalbe_m) {
      if (outer > 0 && lagrangian < previous_lagrangian + 0.5 * rho * q_norm * q_norm)
        M /= settings.beta;
      previous_lagrangian = lagrangian;
      // With rho fixed, ||Qx|| can stall while the inner problems are solved well: the
      // multiplier grows by rho Qx per round and must move far before an active bound lets
      // go (the spanner at 50,000 unknowns: ||Qx|| flat for 160 rounds). When ||Qx|| has not
      // fallen below 0.9 of its best for `stall_rounds` rounds, rho grows by beta, as in
      // the seed's Algorithm 3.1.
      if (q_norm < 0.9 * best_q_norm) {
        best_q_norm = q_norm;
        stalled_rounds = 0;
      } else if (++stalled_rounds >= settings.stall_rounds) {
        const double rho_next = settings.beta * rho;
        g += (rho_next - rho) * Qx;  // A changed by (rho_next - rho) Q
        rho = rho_next;
        stalled_rounds = 0;
        best_q_norm = q_norm;
        ++result.counts.penalty_increases;
      }
      held.step(x, g - rho * Qx, rho * q_norm, promised, g, nu);
      shifted_b = b - nu;
    } else if (q_norm <= eta) {
      eta *= settings.alpha;
    } else {
      const double rho_next = settings.beta * rho;
      g += (rho_next - rho) * Qx;  // A changed by (rho_next - rho) Q
      rho = rho_next;
    }
  }
}

}  // namespace ffeti
