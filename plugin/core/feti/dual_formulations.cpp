// The dual QP of each formulation (docs/algorithms.md): what the solver minimizes, its
// constraint set, its preconditioner and, where something floats, how the balance
// G lambda = e is kept.
#include "feti/dual_system.h"

#include "base/errors.h"
#include "base/stopwatch.h"

#include <algorithm>
#include <array>
#include <memory>

namespace ffeti {
namespace {

/// The solvers' first iterate mu = lambda - lambda~ from settings.start (zero without one).
Vec shifted_start(const DualSolveSettings& settings, const DualData& data, Eigen::Index rows) {
  if (settings.start.size() == 0) return Vec::Zero(rows);
  if (settings.start.size() != rows)
    throw InputError("start: has " + std::to_string(settings.start.size()) + " values, the problem has " +
                     std::to_string(rows) + " multipliers (fetiInfo(P, \"dual\"))");
  return settings.start - data.lambda_tilde;
}

}  // namespace

DualSystem::Formulation DualSystem::plain_qp(const DualData& data, const DualSolveSettings& settings,
                                             DualSolution& result, const qp::ConstraintSet* bounds) const {
  Formulation f;
  qp::Problem& qp = f.qp;
  qp.hessian = [this](const Vec& x, Vec& y) { F_->apply(x, y); };
  qp.b = data.b;
  if (bounds) {
    f.solver = QpSolver::mprgp;
    qp.hessian_norm = estimated_norm(norms_.F, qp.hessian, {}, settings.norm_estimate, result);
    qp.constraints = *bounds;
  } else {
    qp.constraints.add_free(rows());
  }
  qp.preconditioner = preconditioner_operator();
  f.start = shifted_start(settings, data, rows());
  return f;
}

DualSystem::Formulation DualSystem::conjugate_qp(const DualData& data, const DualSolveSettings& settings,
                                                 DualSolution& result, const qp::ConstraintSet& bounds) const {
  // mu = mu_0 + P x: x minimizes 1/2 x'FPx - x'P'd under mu's bounds (P keeps the bounded
  // entries as they are); F P = P'F, one application of F per multiplication.
  Formulation f;
  qp::Problem& qp = f.qp;
  const ConjugateProjector& projector = *conjugate_;
  qp.hessian = [this, &projector](const Vec& x, Vec& y) {  // F (P x): the rigid directions out before F, not
    projector.project(x, work_.conjugate_Px);            // subtracted after it (F is largest along them)
    F_->apply(work_.conjugate_Px, y);
  };
  f.solver = QpSolver::mprgp;
  projector.project_transposed(data.b, qp.b);
  qp.hessian_norm = estimated_norm(norms_.conjugate, qp.hessian, {}, settings.norm_estimate, result);
  qp.constraints = bounds;
  if (const LinearOperator m = preconditioner_operator())
    qp.preconditioner = [this, m, &projector](const Vec& x, Vec& y) {  // P M^{-1} P'
      projector.project_transposed(x, work_.conjugate_r);
      m(work_.conjugate_r, work_.conjugate_z);
      projector.project(work_.conjugate_z, y);
    };
  const Vec base = projector.base(data.b);
  f.to_multipliers = [base, &projector](const Vec& x, Vec& mu) {
    projector.project(x, mu);
    mu += base;
  };
  f.start = shifted_start(settings, data, rows());
  return f;
}

LinearOperator DualSystem::projected_preconditioner() const {
  if (!preconditioner_) return {};
  return [this](const Vec& x, Vec& y) {  // P M^{-1} P on Ker G
    coarse_->project(x, work_.projected);
    preconditioner_->apply(work_.projected, work_.applied);
    coarse_->project(work_.applied, y);
  };
}

DualSystem::Formulation DualSystem::projected_qp(const DualData& data, const DualSolveSettings& settings) const {
  // CG on P F P: every iterate stays in Ker G, where the balance holds (docs/algorithms.md).
  Formulation f;
  qp::Problem& qp = f.qp;
  qp.constraints.add_free(rows());
  qp.hessian = [this](const Vec& x, Vec& y) { apply_PFP(x, y); };
  qp.b = data.b;
  qp.preconditioner = projected_preconditioner();
  f.start = shifted_start(settings, data, rows());
  if (settings.start.size() > 0) coarse_->project(Vec(f.start), f.start);  // G mu = 0
  return f;
}

void DualSystem::set_equality_reference(DualSolution& result, double hessian_norm) const {
  // ||e||, or where nothing loads the floating bodies (e = 0) the size G lambda - e would
  // have for a multiplier of the gradient's size.
  if (!(result.equality_reference > 0)) result.equality_reference = result.gradient_reference / hessian_norm;
}

DualSystem::Formulation DualSystem::penalty_qp(const DualData& data, const DualSolveSettings& settings,
                                               DualSolution& result, const qp::ConstraintSet& bounds) const {
  // The seed's formulation: SMALBE keeps all of G lambda = e by its augmented Lagrangian.
  Formulation f;
  f.solver = QpSolver::smalbe;
  qp::Problem& qp = f.qp;
  qp.constraints = bounds;
  qp.hessian = [this](const Vec& x, Vec& y) { apply_PFP(x, y); };
  qp.hessian_norm = estimated_norm(norms_.PFP, qp.hessian, [this](Vec& v) { coarse_->project(Vec(v), v); },
                                   settings.norm_estimate, result);
  set_equality_reference(result, qp.hessian_norm);
  qp.range_projector = [this](const Vec& x, Vec& y) { coarse_->project_range(x, y); };
  qp.b = data.b;
  qp.preconditioner = preconditioner_operator();
  f.equality_norm = [this](const Vec& mu) { return (coarse_->G() * mu).norm(); };  // G lambda - e = G mu
  f.start = shifted_start(settings, data, rows());
  return f;
}

DualSystem::Formulation DualSystem::free_rows_qp(const DualData& data, const DualSolveSettings& settings,
                                                 DualSolution& result, const qp::ConstraintSet& bounds) const {
  // mu = T nu: every iterate meets G mu = 0 but for the rows of C (docs/algorithms.md).
  Stopwatch projector_clock;
  const FreeRowProjector& T = free_rows();  // built at the first solve: its time is reported apart
  result.times.free_rows = projector_clock.seconds();
  const int m = rows();
  auto work = std::make_shared<std::array<Vec, 3>>();  // P T x, F P T x, x without its Ker T part
  for (Vec& v : *work) v.resize(m);
  // T' P F P T, its P T and T'P without the coarse solves of P (FreeRowProjector::apply_projected).
  const LinearOperator reduced = [this, &T, work](const Vec& x, Vec& y) {
    T.apply_projected(x, (*work)[0]);
    F_->apply((*work)[0], (*work)[1]);
    T.apply_projected_transpose((*work)[1], y);
  };
  const double norm = estimated_norm(norms_.reduced, reduced, {}, settings.norm_estimate, result);
  Formulation f;
  qp::Problem& qp = f.qp;
  // mu = T x changes only free components (gluing and Dirichlet rows): x has mu's bounds.
  qp.constraints = bounds;
  // T'PFPT vanishes on Ker T (free multipliers only, orthogonal to b, to the bounds and to
  // C), which the iterates never enter in exact arithmetic; in floating point they drift
  // into it unseen, and T x then cancels large components: at tol = 1e-12 the model problem
  // at n = 512 diverged (KKT 2e-3 after 10,000 multiplications). Adding ||H|| (I - Pi) on
  // Ker T changes nothing on the problem's own subspace and keeps that drift at round-off.
  qp.hessian = [reduced, &T, work, norm](const Vec& x, Vec& y) {
    reduced(x, y);
    T.project_out_kernel(x, (*work)[2]);
    y += norm * (x - (*work)[2]);
  };
  qp.hessian_norm = norm;
  T.apply_transpose(data.b, qp.b);
  // The seed's test measures the gradient against its value at the start: here T'b.
  result.gradient_reference = std::max(qp.b.norm(), settings.reference_includes_data ? data.data_norm : 0.0);
  if (!(result.gradient_reference > 0)) result.gradient_reference = 1.0;
  set_equality_reference(result, norm);
  if (preconditioner_)  // approximates (T'PFPT)^+ from M^{-1} ~ (PFP)^+
    qp.preconditioner = [this, &T, work](const Vec& v, Vec& y) {
      T.project_out_kernel(v, (*work)[0]);
      coarse_->project((*work)[0], work_.projected);
      preconditioner_->apply(work_.projected, work_.applied);
      coarse_->project(work_.applied, (*work)[0]);
      T.project_out_kernel((*work)[0], y);
    };
  // Bodies float as a whole: their balance is left to SMALBE. Otherwise T leaves no
  // equality part, bounds only, and MPRGP is SMALBE without a multiplier to update.
  f.solver = T.remaining() > 0 ? QpSolver::smalbe : QpSolver::mprgp;
  if (f.solver == QpSolver::smalbe) {
    qp.range_projector = [&T](const Vec& v, Vec& y) { T.project_remaining_range(v, y); };
    qp.equality_rows = &T.remaining_rows();  // the bodies' slides that friction alone holds (qp/held_modes.h)
  }
  f.to_multipliers = [&T](const Vec& x, Vec& mu) { T.apply(x, mu); };
  f.equality_norm = [this](const Vec& mu) { return (coarse_->G() * mu).norm(); };  // G lambda - e = G mu
  f.iterate_equality_norm = [&T](const Vec& x) { return T.remaining_norm(x); };  // ||G T x|| = ||C x||
  // The start without its part in Ker T, which T'PFPT does not see (free rows only: bounds kept).
  f.start.resize(m);
  T.project_out_kernel(shifted_start(settings, data, m), f.start);
  return f;
}

}  // namespace ffeti
