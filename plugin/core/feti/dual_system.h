// The dual problem of one constraint set over factorized subdomains: B split by subdomain,
// the dual operator F, the coarse space where something floats, and the solve on the path
// the constraints call for (ALGORITHMS.md section 6). The state problem has one; the
// sensitivity problem of a design step (seed eq. 12: a subset of the rows) has another
// over the same factorizations. Its parts: dual_system.cpp (the operators, the right-hand
// side, the constraint set, the primal check and recovery), dual_formulations.cpp (one
// qp::Problem per formulation), dual_solve.cpp (the dispatcher onto qp/ by the path, both
// solve overloads).
#pragma once

#include "feti/coarse_space.h"
#include "constraints/constraints.h"
#include "feti/dirichlet_preconditioner.h"
#include "feti/dual_operator.h"
#include "feti/free_row_projector.h"
#include "feti/stopping_test.h"
#include "parallel/subdomain_sum.h"
#include "qp/norm_estimate.h"
#include "qp/problem.h"
#include "qp/smalbe.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ffeti {

/// The solver path the constraints call for (ALGORITHMS.md section 6).
enum class DualPath {
  cholesky,      ///< no constraint rows: one subdomain solve each
  cg,            ///< equality rows only, nothing floats: CG on F
  projected_cg,  ///< equality rows only, something floats: CG on P F P
  mprgp,         ///< contact rows, nothing floats: MPRGP on F
  smalbe,        ///< contact rows, something floats: SMALBE-M (MPRGP where the free-rows form leaves no equality part)
};

/// The path's name in reports and statistics ("projected_cg"); paths are compared as enums.
const char* path_name(DualPath path);

/// How the SMALBE path meets the coarse constraints G lambda = e (docs/algorithms.md).
enum class CoarseConstraints {
  penalty,    ///< all rows of G by SMALBE's augmented Lagrangian, on P F P
  free_rows,  ///< the rows the free multipliers can meet by the oblique projector T; the rest by SMALBE
};

/// Stopping test of every path (docs/algorithms.md): by default (relative_kkt) the recovered
/// u(lambda) violates no constraint by more than tolerance ||u||_inf,
/// or the seed's  ||gP||_2 <= tolerance ||b||_2,  b = P(d - F lambda~) (T'b with coarse
/// free_rows: the gradient at the start);  and on both, where there is a coarse space,
/// ||G lambda - e||_2 <= tolerance ||e||_2.

/// The relative distance min ||G lambda - e|| / ||e|| over lambda_I >= 0 below which a scene
/// counts as feasible whatever tol: MPRGP on G'G resolves it only to about 1e-11 (a feasible
/// spanner gave 1.3e-11, depending on the expansion steps), so a smaller tol must not turn
/// that round-off into "infeasible"; infeasible scenes are off by far more (docs/algorithms.md).
constexpr double kFeasibilityResolution = 1e-8;

struct DualSolveSettings {
  double tolerance = 1e-4;
  /// The relative distance from equilibrium below which the loads count as balanced by
  /// multipliers within their bounds (the Farkas check before SMALBE); 0: `tolerance`. A
  /// solve with a tolerance looser than the user's (Coulomb's early Tresca solves) keeps
  /// the user's here: at its own it let a pull of 1.01 mu W through to maxit.
  double feasibility_tolerance = 0;
  CoarseConstraints coarse_constraints = CoarseConstraints::free_rows;
  StoppingTest stopping = StoppingTest::relative_kkt;
  int max_hessian = 10000;          ///< over the whole solve (friction: over all its Tresca solves)
  SmalbeSettings smalbe{};          ///< used on the SMALBE path
  MprgpSettings mprgp{};            ///< used on the MPRGP path and inside SMALBE
  NormEstimateSettings norm_estimate{};
  Monitor monitor{};
  /// Seed test: measure ||gP|| against max(||b||, ||B K^+ f||) instead of ||b||: for right-hand sides
  /// whose b is small after cancellation (a sensitivity load f' - K'u in near equilibrium),
  /// ||b|| lies below the round-off of the data it came from, and a tolerance relative to it
  /// cannot be reached.
  bool reference_includes_data = false;
  /// Multipliers to start from (rows as constraints()), e.g. a previous solve's lambda or
  /// one interpolated from a coarser mesh; empty: lambda = 0 (lambda~ where bodies float).
  /// Moved onto the constraints' feasible set first, so any values of the right size do.
  Vec start;
  /// Face solves that settle a given start before MPRGP (qp/start_settling.h); 0: MPRGP
  /// from the start as given. Ignored without a start. 2: measured, docs/results/large-contact.md.
  int settle = 2;
  /// Coulomb friction: Tresca solves of the fixed point at most (feti/friction.h).
  int friction_iterations = 50;
  void validate() const;  ///< throws InputError naming the setting
};

/// Where the time of a set-up and a solve went, phase by phase.
struct PhaseTimes {  ///< wall-clock seconds; in a problem's result over several ranks, the slowest rank's
  double constraints = 0, factorization = 0, coarse_space = 0, dual_data = 0;  ///< set-up
  double norm_estimate = 0;   ///< estimating ||H|| (first solve of a system only)
  double free_rows = 0;       ///< building T of coarse "free-rows" (first solve of a system only)
  double solve = 0, recovery = 0, kkt = 0;
  double dual_operator = 0;   ///< the part of solve spent applying F
  double preconditioner = 0;  ///< the part of solve spent applying the preconditioner
  double primal_checks = 0;   ///< the part of solve spent in the stopping test's primal checks
  double hessian = 0;         ///< the part of solve in the solver's Hessian multiplications (F, projections)
  double factor_solves = 0;   ///< of dual_operator, the subdomain solves (thread-seconds: DualOperator)

  /// Several solves of one problem (friction's fixed point) add up phase by phase.
  PhaseTimes& operator+=(const PhaseTimes& o) {
    double* mine[] = {&constraints, &factorization, &coarse_space, &dual_data, &norm_estimate, &free_rows, &solve,
                      &recovery, &kkt, &dual_operator, &preconditioner, &primal_checks, &hessian, &factor_solves};
    const double* theirs[] = {&o.constraints, &o.factorization, &o.coarse_space, &o.dual_data, &o.norm_estimate,
                              &o.free_rows, &o.solve, &o.recovery, &o.kkt, &o.dual_operator, &o.preconditioner,
                              &o.primal_checks, &o.hessian, &o.factor_solves};
    for (size_t k = 0; k < sizeof(mine) / sizeof(mine[0]); ++k) *mine[k] += *theirs[k];
    return *this;
  }
};

/// The right-hand side of one dual problem, for loads f (as the operators see them) and
/// constraint right-hand side c: d = B K^+ f - c, e = R'f, lambda~ = G'(GG')^{-1} e and
/// b = P(d - F lambda~).
struct DualData {
  std::vector<Vec> loads;
  Vec c, e, lambda_tilde, b;
  double data_norm = 0;  ///< max(||B K^+ f||, ||c||): the size of what b was computed from
  Vec slip_bound;        ///< per friction row: g >= 0 of |lambda_t| <= g (empty without friction)
};

/// What a solve of a sequence (friction's fixed point: one system, other bounds) carries
/// over from the last, besides its multipliers (DualSolveSettings::start).
struct DualWarmStart {
  Vec equality_multiplier;  ///< DualSolution::equality_multiplier of the last solve (empty: 0)
};

struct DualSolution {
  SolveStatus status = SolveStatus::invalid_input;
  DualPath path = DualPath::cholesky;  ///< the path taken
  IterationCounts counts;
  double gradient_norm = 0;      ///< final ||gP|| (absolute) and its reference ||b||
  double gradient_reference = 0;
  double equality_norm = 0;      ///< final ||G lambda - e|| and its reference ||e||
  double equality_reference = 0;
  double violation = -1;         ///< relative_kkt: the last check's measure (-1: no check ran)
  int scale_evaluations = 0;     ///< relative_kkt: primal checks (a K^+ application each)
  long dual_operator_applications = 0;  ///< columns F was applied to in the solve (times.dual_operator's)
  Vec lambda;                    ///< multipliers, rows ordered as constraints()
  /// SMALBE path: the solver's final multiplier term of the equality part (qp/smalbe.h);
  /// empty on the other paths. The next solve of the same system with other bounds starts
  /// from it (DualWarmStart).
  Vec equality_multiplier;
  std::vector<Vec> u;            ///< primal solution per subdomain of this rank
  PhaseTimes times;              ///< this rank's: norm_estimate, free_rows, solve (and its parts), recovery
};

/// Coulomb's statics check (DualSystem::coulomb_feasibility).
struct CoulombFeasibility {
  /// min ||G lambda - e|| / ||e|| over lambda with lambda_n >= 0 and ||lambda_t|| <= mu
  /// lambda_n per contact row (gluing and Dirichlet multipliers free); -1: undecided.
  double distance = 0;
  /// The body whose rigid modes carry most of the residual at that minimum (-1 when
  /// feasible or undecided): the one that would slide.
  int body = -1;
};

class DualSystem {
 public:
  /// `subdomains` are this rank's (factorized), `global_ids` their global indices,
  /// `owner[s]` the rank and `bodies[s]` the body of every global subdomain s. Builds the
  /// coarse space when some subdomain floats (InputError if a body's rigid modes meet no
  /// row). Keeps references to `subdomains` and `comm`: both must outlive it. Collective.
  DualSystem(const SubdomainList& subdomains, const std::vector<int>& global_ids,
             const std::vector<int>& owner, const std::vector<int>& bodies, Constraints constraints,
             int threads, const Communicator& comm, GramLayout coarse_gram = GramLayout::automatic);

  const Constraints& constraints() const { return constraints_; }
  /// The same rows with other right-hand sides (new contact gaps or prescribed values):
  /// `rebuilt` must have this B, entry for entry (std::logic_error otherwise); its c, row
  /// geometries and watched rows replace these. Nothing factorized, projected or estimated
  /// depends on c, so every cached part stays valid.
  void replace_right_hand_side(Constraints rebuilt);
  const std::vector<LocalConstraints>& local() const { return local_; }
  const DualOperator& F() const { return *F_; }
  const CoarseSpace* coarse() const { return coarse_.get(); }
  int rows() const { return constraints_.rows(); }
  /// The solver path the constraints call for (ALGORITHMS.md section 6).
  DualPath path() const;

  /// Preconditions every path with the Dirichlet (or lumped) preconditioner built from
  /// `operator_matrices` (this rank's K as the dual operator sees them): CG and projected CG
  /// directly, MPRGP and SMALBE in face (docs/algorithms.md). The Dirichlet one costs one
  /// more factorization per subdomain (subdomains with identical interior blocks share one
  /// where `share_factors`), the lumped one none. Collective.
  void use_preconditioner(DualPreconditioner kind, const std::vector<const SparseMatrix*>& operator_matrices,
                          int threads, bool share_factors);
  bool preconditioned() const { return preconditioner_ != nullptr; }
  DualPreconditioner preconditioner_kind() const { return preconditioner_kind_; }

  /// The dual right-hand side for loads `loads` (this rank's) and constraint right-hand
  /// side `c` (all rows). Collective: two dual operator applications.
  DualData data(std::vector<Vec> loads, const Vec& c) const;

  /// Solves the dual problem and recovers u. Never throws for non-convergence: see status.
  /// Collective.
  DualSolution solve(const DualData& data, const DualSolveSettings& settings, const DualWarmStart& warm = {}) const;

  /// Solves the dual problems of several right-hand sides. On the CG paths with the seed's
  /// test their CG runs go in lockstep and share each application of F (a block of vectors,
  /// one pass over each factor), preconditioned as solve() is; each one's iterations and
  /// counts are those of solve() alone, its solve time the block's time divided by the
  /// count. Other paths solve one after the other. Collective.
  std::vector<DualSolution> solve(const std::vector<DualData>& data, const DualSolveSettings& settings) const;

  /// Coulomb's statics question for loads `data`: can contact forces within their friction
  /// cones balance the loads on the floating bodies? The free multipliers (gluing, Dirichlet)
  /// balance all of e but the whole bodies' rigid modes (FreeRowProjector: G_F spans all but
  /// Im W), so the distance is min ||C lambda_I - W'e|| over the cones, C = W'G: a small,
  /// well-conditioned problem (qp::cone_distance; on G itself projected gradients crawled and
  /// called a feasible 3D scene infeasible). `bodies[s]`: the body of global subdomain s.
  /// Feasible (distance 0) where no body floats as a whole. Same on every rank.
  CoulombFeasibility coulomb_feasibility(const DualData& data, const std::vector<int>& bodies, double enough) const;

 private:
  struct CachedNorm {  // an estimate of ||H||: the same H for every load case
    std::optional<double> norm;
    int cost = 0;
  };
  double estimated_norm(CachedNorm& cache, const LinearOperator& H, const std::function<void(Vec&)>& start_filter,
                        const NormEstimateSettings& settings, DualSolution& result) const;
  struct OperatorUse {  // F's running totals (DualOperator), to charge a solve their difference
    double seconds, solve_seconds;
    long applications;
  };
  OperatorUse operator_use() const { return {F_->application_seconds(), F_->solve_seconds(), F_->applications()}; }
  /// Adds F's use since `start`, times `sign` (-1: the norm estimate's, not the solve's), to
  /// result's dual_operator, factor_solves and dual_operator_applications, divided by `runs`.
  void charge_operator_use(const OperatorUse& start, double sign, int runs, DualSolution& result) const;
  void apply_PFP(const Vec& x, Vec& y) const;  // the projected dual operator, on reused buffers
  void apply_PFP(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;
  DualSolution prepared(const DualData& data, const DualSolveSettings& settings) const;  // path, references
  LinearOperator preconditioner_operator() const;  // M^{-1}, or empty without a preconditioner
  LinearOperator projected_preconditioner() const;  // P M^{-1} P, or empty without a preconditioner
  void recover(const DualData& data, Vec lambda, DualSolution& result) const;
  const FreeRowProjector& free_rows() const;  // built at first use
  /// Of the recovered u(lambda), which goes to `u` where given.
  PrimalCheck primal_check(const DualData& data, const Vec& lambda, std::vector<Vec>* u = nullptr) const;
  // Of lambda: free on equality rows, lambda_I >= 0 on contact rows, |lambda_t| <= g on
  // friction rows.
  qp::ConstraintSet multiplier_constraints(const DualData& data) const;
  Vec lambda_from_shifted(const Vec& mu, const qp::ConstraintSet& bounds, const DualData& data) const;

  /// One formulation's QP over the solver's variable x, and how x maps back to the shifted
  /// multipliers mu = lambda - lambda~.
  struct Formulation {
    qp::Problem qp;
    /// mu of a solver iterate x (empty: mu = x).
    std::function<void(const Vec& x, Vec& mu)> to_multipliers;
    /// ||G mu||, which the stopping test weighs (empty: the iterates meet G mu = 0 by
    /// construction, or nothing floats).
    std::function<double(const Vec& mu)> equality_norm;
    /// The same ||G mu|| from the solver's iterate x without forming mu, for the test at
    /// every iteration (empty: equality_norm of mu).
    std::function<double(const Vec& x)> iterate_equality_norm;
    Vec start;  ///< the solver's first iterate
  };
  // The formulations (dual_formulations.cpp), each the QP of one path; `bounds` are mu's.
  Formulation plain_qp(const DualData& data, const DualSolveSettings& settings, DualSolution& result,
                       const qp::ConstraintSet* bounds) const;  // F: CG, or MPRGP (bounded: with the norm estimate)
  Formulation projected_qp(const DualData& data, const DualSolveSettings& settings) const;  // P F P: projected CG
  Formulation penalty_qp(const DualData& data, const DualSolveSettings& settings, DualSolution& result,
                         const qp::ConstraintSet& bounds) const;
  Formulation free_rows_qp(const DualData& data, const DualSolveSettings& settings, DualSolution& result,
                           const qp::ConstraintSet& bounds) const;
  void set_equality_reference(DualSolution& result, double hessian_norm) const;

  // The dispatcher's pieces (dual_solve.cpp).
  Vec run(DualPath route, Formulation formulation, const DualStop& stop, const DualSolveSettings& settings,
          const DualWarmStart& warm, DualSolution& result) const;  // the route's solver on the formulation; returns mu
  DualSolution solved_by_subdomains(const DualData& data, DualSolution result) const;  // the cholesky path

  const SubdomainList& subdomains_;
  std::vector<int> global_ids_;  // of subdomains_, for errors that name a subdomain
  const Communicator& comm_;
  Constraints constraints_;
  std::vector<LocalConstraints> local_;
  std::unique_ptr<SubdomainSum> sum_;
  std::unique_ptr<DualOperator> F_;
  std::unique_ptr<CoarseSpace> coarse_;
  std::unique_ptr<DirichletPreconditioner> preconditioner_;
  DualPreconditioner preconditioner_kind_ = DualPreconditioner::none;
  // What solve() (const: it changes no part of the system a caller sees) keeps from call to
  // call. Each depends only on the system, never on a right-hand side or the settings, so a
  // later solve may reuse it; none is safe to share between threads (a DualSystem solves one
  // problem at a time, collectively). Work vectors, reused so that each application of an
  // operator allocates nothing:
  mutable Vec projected_, applied_;                   // buffers of apply_PFP and the preconditioner
  mutable Eigen::MatrixXd block_projected_, block_applied_;  // of the block apply_PFP
  // Built at first use, as only some paths need them (10-20 applications of the operator for
  // a norm estimate; a factorization of C C' for T):
  mutable CachedNorm norm_F_, norm_PFP_, norm_reduced_;  // ||F||, ||PFP||, ||T'PFPT||
  mutable std::unique_ptr<FreeRowProjector> free_rows_;
  mutable double check_seconds_ = 0;  // spent in primal_check so far (a solve reports its difference)
};

}  // namespace ffeti
