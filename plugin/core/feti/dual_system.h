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
#include "feti/conjugate_projector.h"
#include "constraints/constraints.h"
#include "feti/dirichlet_preconditioner.h"
#include "feti/dual_data.h"
#include "feti/dual_operator.h"
#include "feti/dual_settings.h"
#include "feti/dual_solution.h"
#include "feti/free_row_projector.h"
#include "parallel/subdomain_sum.h"
#include "qp/problem.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ffeti {

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
  /// Bytes this rank holds beside the subdomains' factors and the input copies, by part (the
  /// conjugate projector's C and FC, an option of transient scenes, are not counted).
  struct HeldBytes {
    double rows = 0;            ///< the blocks B_s (twice: by rows, and renumbered to the interfaces) and buffers
    double coarse = 0;          ///< G and GG''s factor
    double preconditioner = 0;  ///< the lumped or Dirichlet preconditioner's blocks and factors
  };
  HeldBytes held_bytes() const;
  /// Where nothing floats (the MPRGP path): the conjugate projector onto the rigid modes of
  /// the subdomains on the equality rows, `modes[k]` local subdomain k's (n_k x r, the same r
  /// on every subdomain; candidate_kernel), used by every later solve. Collective.
  void use_conjugate_projector(const std::vector<Eigen::MatrixXd>& modes);
  int rows() const { return constraints_.rows(); }
  /// The solver path the constraints call for (ALGORITHMS.md section 6), chosen once by the
  /// constructor.
  DualPath path() const { return path_; }

  /// Preconditions every path with the Dirichlet (or lumped) preconditioner built from
  /// `operator_matrices` (this rank's K as the dual operator sees them): CG and projected CG
  /// directly, MPRGP and SMALBE in face (docs/algorithms.md). The Dirichlet one costs one
  /// more factorization per subdomain (subdomains with identical interior blocks share one
  /// where `share_factors`), the lumped one none. Collective.
  void use_preconditioner(DualPreconditioner kind, const std::vector<const SparseMatrix*>& operator_matrices,
                          int threads, bool share_factors, InterfaceScaling scaling = InterfaceScaling::multiplicity);
  bool preconditioned() const { return preconditioner_ != nullptr; }
  LinearOperator preconditioner_operator() const;  // M^{-1}, or empty without a preconditioner
  DualPreconditioner preconditioner_kind() const { return preconditioner_kind_; }

  /// The dual right-hand side for loads `loads` (this rank's) and constraint right-hand
  /// side `c` (all rows). Collective: two dual operator applications.
  DualData data(std::vector<Vec> loads, const Vec& c) const;

  /// Solves the dual problem and recovers u. Never throws for non-convergence: see status.
  /// Collective.
  DualSolution solve(const DualData& data, const DualSolveSettings& settings, const DualWarmStart& warm = {}) const;
  /// The same as one of several solves of a user call (friction's fixed point): `settings`
  /// validated by the caller, whose `budget` (DualSolveSettings::validate) this solve's
  /// solvers charge. Collective.
  DualSolution solve(const DualData& data, const DualSolveSettings& settings, const DualWarmStart& warm,
                     qp::Budget& budget) const;

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
  LinearOperator projected_preconditioner() const;  // P M^{-1} P, or empty without a preconditioner
  void recover(const DualData& data, Vec lambda, DualSolution& result) const;
  const FreeRowProjector& free_rows() const;  // built at first use
  /// Of the recovered u(lambda), which goes to `u` where given.
  PrimalCheck primal_check(const DualData& data, const Vec& lambda, std::vector<Vec>* u = nullptr) const;
  // Of lambda: free on equality rows, lambda_I >= 0 on contact rows, |lambda_t| <= g on
  // friction rows.
  qp::ConstraintSet multiplier_constraints(const DualData& data) const;
  Vec lambda_from_shifted(const Vec& mu, const qp::ConstraintSet& bounds, const DualData& data) const;

  /// The qp/ solver a formulation's QP calls for, set by the formulation that builds it.
  enum class QpSolver { cg, mprgp, smalbe };
  /// One formulation's QP over the solver's variable x, the solver that fits it, and how x
  /// maps back to the shifted multipliers mu = lambda - lambda~.
  struct Formulation {
    qp::Problem qp;
    QpSolver solver = QpSolver::cg;
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
  Formulation conjugate_qp(const DualData& data, const DualSolveSettings& settings, DualSolution& result,
                           const qp::ConstraintSet& bounds) const;  // F P, P'd: MPRGP with the conjugate projector
  Formulation free_rows_qp(const DualData& data, const DualSolveSettings& settings, DualSolution& result,
                           const qp::ConstraintSet& bounds) const;
  void set_equality_reference(DualSolution& result, double hessian_norm) const;

  // The dispatcher's pieces (dual_solve.cpp).
  Vec run(Formulation formulation, const DualStop& stop, const DualSolveSettings& settings, const DualWarmStart& warm,
          qp::Budget& budget, DualSolution& result) const;  // the formulation's solver on its QP; returns mu
  DualSolution solved_by_subdomains(const DualData& data, DualSolution result) const;  // the cholesky path

  const SubdomainList& subdomains_;
  std::vector<int> global_ids_;  // of subdomains_, for errors that name a subdomain
  const Communicator& comm_;
  Constraints constraints_;
  std::vector<LocalConstraints> local_;
  std::unique_ptr<SubdomainSum> sum_;
  std::unique_ptr<DualOperator> F_;
  std::unique_ptr<CoarseSpace> coarse_;
  DualPath path_ = DualPath::cholesky;
  std::unique_ptr<ConjugateProjector> conjugate_;
  std::unique_ptr<DirichletPreconditioner> preconditioner_;
  DualPreconditioner preconditioner_kind_ = DualPreconditioner::none;
  // What solve() (const: it changes no part of the system a caller sees) keeps from call to
  // call, in four mutable members. Each depends only on the system, never on a right-hand
  // side or the settings, so a later solve may reuse it; none is safe to share between
  // threads (a DualSystem solves one problem at a time, collectively).
  struct Workspace {  // reused so that each application of an operator allocates nothing
    Vec projected, applied;                       // of apply_PFP and the preconditioner
    Vec conjugate_Px, conjugate_r, conjugate_z;   // P x of the conjugate Hessian; P'x, M^-1 P'x of its preconditioner
    Eigen::MatrixXd block_projected, block_applied;  // of the block apply_PFP
  };
  mutable Workspace work_;
  // Built at first use, as only some paths need them (10-20 applications of the operator for
  // a norm estimate; a factorization of C C' for T):
  struct Norms {
    CachedNorm F, PFP, reduced, conjugate;  // ||F||, ||PFP||, ||T'PFPT||, ||FP||
  };
  mutable Norms norms_;
  mutable std::unique_ptr<FreeRowProjector> free_rows_;
  mutable double check_seconds_ = 0;  // spent in primal_check so far (a solve reports its difference)
};

}  // namespace ffeti
