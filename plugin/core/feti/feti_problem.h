// A FETI problem set up once (constraints, kernels, factorizations, coarse space) and
// solved for one or more load cases, choosing the solver path the scene needs.
#pragma once

#include "feti/contact_reach.h"
#include "feti/dual_system.h"
#include "feti/friction.h"
#include "feti/primal.h"
#include "constraints/problem_input.h"
#include "feti/subdomain.h"
#include "parallel/communicator.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace ffeti {

struct FetiSetupSettings {
  FetiVariant variant = FetiVariant::feti1;
  FactorKind factor = FactorKind::automatic;
  /// Where each subdomain's interface goes in its factor's elimination order (CholmodFactor).
  InterfaceOrdering ordering = InterfaceOrdering::automatic;
  /// Subdomains of bitwise equal matrices, fixing dofs and interfaces share one factor
  /// (SharedFactors): the same generalized inverse, factorized once.
  bool share_factors = true;
  /// OpenMP threads over subdomains; 0: the runtime default. Under Debian's serial OpenBLAS,
  /// not safe to call concurrently, supernodal factors run on one thread (set_up).
  int threads = 0;
  /// Preconditioner of the dual problem (docs/algorithms.md): Dirichlet (iterations bounded
  /// in h and in the number of subdomains, one more factorization per subdomain) or lumped
  /// (no factorization); projected CG directly, MPRGP in face (docs/results/scalability.md).
  DualPreconditioner preconditioner = DualPreconditioner::lumped;
  /// How the preconditioner weighs each row's sides (DirichletPreconditioner): a speed option.
  InterfaceScaling scaling = InterfaceScaling::multiplicity;
  /// How the coarse problem's Gram matrices over fewer columns (G_F G_F', G_S G_S') are
  /// factorized (coarse_gram.h): a speed option, the same answers to round-off.
  GramLayout coarse_gram = GramLayout::automatic;
  /// Where nothing floats (a time step's K + c M): the conjugate projector onto the
  /// subdomains' rigid modes on the equality rows (ConjugateProjector).
  bool conjugate_projector = false;  /// How the dual operator applies each K_s^+ on its interface: the factor's solves, or a
  /// dense block formed once (Subdomain::form_explicit_block), or the latter where it reads
  /// fewer bytes. A speed option: the same answers to round-off.
  DualOperatorForm dual_operator = DualOperatorForm::automatic;
};

/// A solve of the problem: the dual solve's outcome (its times the slowest rank's), and
/// what the problem adds to it.
struct FetiResult : DualSolution {
  std::string phases;            ///< the phases this solve ran, comma separated
  double energy = 0;             ///< 1/2 u'Ku - f'u
  KktResiduals kkt;
  int active_contact = 0;        ///< contact rows with lambda > 0
  // With friction (counts and times above are summed over the Tresca solves):
  int friction_iterations = 0;   ///< Tresca solves (Coulomb: of the fixed point)
  std::vector<int> friction_hessian;  ///< Hessian multiplications of each
  double friction_bound_change = 0;   ///< Coulomb: the fixed point's last relative change of g
  int sliding_body = -1;              ///< Coulomb, status infeasible: the body that would slide (-1: none named)
  int newton_steps = 0;               ///< Coulomb by Newton: its steps (FrictionSolution)
  int newton_hessian = 0;             ///< ... and their multiplications (in counts.hessian, not friction_hessian)
  Vec slip_bound;                ///< g per friction row of the last Tresca solve
  Vec slip;                      ///< per friction row B u - c: the slip of this load step along its tangent
  int slipping_contact = 0;      ///< contact rows whose friction force is at its bound
  ReachCheck beyond_reach;       ///< slaves without a row (contactRadius) that penetrate
};

/// What one rank holds and spent, for load-balance reports.
struct RankStatistics {
  int rank = 0, subdomains = 0;
  long primal = 0;
  double time_factor = 0, time_solve = 0, peak_memory_mb = 0;
};

class FetiProblem {
 public:
  /// Both constructors validate the input (InputError on bad data, thrown on every rank),
  /// build B and c, the kernels and factorizations, the coarse space when some subdomain
  /// floats, and the dual data.
  /// One process: every subdomain is here (global index = position).
  FetiProblem(std::vector<SubdomainInput> subdomains, const ContactInput& contact,
              const FetiSetupSettings& settings = {});

  /// Subdomains spread over the ranks of `comm`: this rank holds `local`, whose global
  /// indices are `global_ids` (ascending); together the ranks hold 0..global_count-1, each
  /// once. `local_contact` lists the contact dofs of the local subdomains. Collective.
  FetiProblem(std::vector<SubdomainInput> local, std::vector<int> global_ids, int global_count,
              const ContactInput& local_contact, const FetiSetupSettings& settings,
              std::shared_ptr<const Communicator> comm);

  /// Solves the dual problem and recovers u. Never throws for non-convergence: see status.
  /// Collective.
  FetiResult solve(const DualSolveSettings& settings = {}) const;

  /// New loads for the local subdomains, same matrices: keeps every factorization and the
  /// coarse factor. Collective.
  void set_loads(const std::vector<Vec>& loads);

  /// New prescribed values of the Dirichlet dofs (per local subdomain, one per
  /// SubdomainInput::dirichlet_dofs entry), same dofs: the right-hand sides of the rows they
  /// enter (Dirichlet rows, rows they were substituted into, friction rows: the prescribed
  /// motion's change is part of the step's slip) and, in FETI-1, the eliminated loads.
  /// Keeps every factorization. With friction call start_load_step first. Collective.
  void set_dirichlet_values(const std::vector<std::vector<double>>& values);

  /// New contact gaps (ContactInput::gap_field's layout: per local subdomain one value per
  /// dof, or empty for none), same rows: K does not depend on them, so only the contact
  /// rows' right-hand sides change (every contact kind adds its slave's entry to its c). Keeps
  /// every factorization, the coarse space and the norm estimates: the next solve equals a
  /// fresh set-up's with these gaps. With friction call start_load_step first. Collective.
  void set_contact_gaps(const std::vector<std::vector<double>>& gaps);

  /// With friction: `last` (a converged solve of this problem) becomes the state the next
  /// load step starts from: the slip of the friction rows is measured from its u, and its
  /// multipliers start the next solve. Collective.
  void start_load_step(const FetiResult& last);
  bool has_friction() const { return constraints().friction_rows > 0; }
  const FrictionLaw& friction_law() const { return friction_; }

  int subdomain_count() const { return global_count_; }
  int local_subdomain_count() const { return static_cast<int>(inputs_.size()); }
  const std::vector<int>& global_ids() const { return global_ids_; }
  /// Rank holding each global subdomain, and its body.
  const std::vector<int>& owners() const { return owner_; }
  const std::vector<int>& bodies() const { return bodies_; }
  const Communicator& communicator() const { return *comm_; }
  std::shared_ptr<const Communicator> shared_communicator() const { return comm_; }
  long primal_dimension() const { return primal_dimension_; }
  /// 2 for a plane problem, 3 with a third coordinate.
  int space_dimension() const { return space_dimension_; }
  int dual_dimension() const { return dual_->rows(); }
  int floating_subdomains() const { return dual_->coarse() ? dual_->coarse()->floating_subdomains() : 0; }
  int coarse_dimension() const { return dual_->coarse() ? dual_->coarse()->dimension() : 0; }
  /// Numeric factorizations of subdomain matrices this problem ran, over all ranks: one
  /// per subdomain at set-up, except those that share an identical one (shared_factors()),
  /// and never another (sensitivities and load cases reuse them).
  long factorizations() const { return factorizations_; }
  /// Subdomains that took the factor of an identical subdomain instead of factorizing
  /// (factorizations() + shared_factors() = subdomains). Over all ranks.
  long shared_factors() const { return shared_factors_; }
  /// Of those, the ones CHOLMOD made supernodal, and the symbolic analyses they took (the
  /// others copied the analysis of a subdomain with the same pattern). Over all ranks.
  long supernodal_factors() const { return supernodal_factors_; }
  /// Subdomains whose factor ordered the interface last (the dual operator solves on it).
  long interface_factors() const { return interface_factors_; }
  long symbolic_analyses() const { return symbolic_analyses_; }
  /// Subdomains whose dual operator applies an explicit block of K_s^+ on the interface
  /// (FetiSetupSettings::dual_operator), over all ranks; the distinct blocks' bytes (held
  /// besides the factors) and the slowest rank's seconds forming them (not in
  /// setup_times().factorization).
  long explicit_operators() const { return explicit_blocks_.subdomains; }
  double explicit_bytes() const { return explicit_bytes_; }
  double explicit_seconds() const { return explicit_blocks_.seconds; }
  /// Per-rank figures gathered at set-up and after each solve (rank order).
  const std::vector<RankStatistics>& rank_statistics() const { return rank_statistics_; }
  const Constraints& constraints() const { return dual_->constraints(); }
  const DualSystem& dual() const { return *dual_; }
  /// This rank's factorized subdomains (kernels, generalized inverses).
  const SubdomainList& subdomains() const { return subdomains_; }
  /// The input as given (original K_s and current loads f_s), but each K_s held as its
  /// lower triangle once checked (read it as K.get().selfadjointView<Eigen::Lower>()).
  const std::vector<SubdomainInput>& inputs() const { return inputs_; }
  /// Position and multiplier of every contact row's slave dof (gathered: the same on all
  /// ranks; every contact row, in row order).
  const std::vector<std::array<double, 2>>& contact_positions() const { return contact_positions_; }
  /// The third coordinate of the same (0 in a plane problem).
  const std::vector<double>& contact_heights() const { return contact_heights_; }
  /// Body and field component of every contact row's slave dof (the dof that carries its
  /// gap: node to segment and obstacle rows name the node by its component-0 dof).
  const std::vector<std::array<int, 2>>& contact_body_component() const { return contact_body_component_; }
  /// Coordinates closer than this are one node (snapping_length of all subdomain boxes).
  double snap() const { return snap_; }
  const PhaseTimes& setup_times() const { return setup_times_; }
  const FetiSetupSettings& settings() const { return settings_; }
  FetiVariant variant() const { return settings_.variant; }
  /// nnz(L) over the distinct factors (a factor shared by identical subdomains counts once).
  double factor_nonzeros() const { return factor_nonzeros_; }
  /// Bytes one pass over every distinct factor reads (CholmodFactor::factor_bytes): the
  /// memory the factors hold.
  double factor_bytes() const { return factor_bytes_; }
  /// What one pass of a dual-operator multiplication reads (Subdomain::operator_bytes: less
  /// where the subdomains solve on their interface; an explicit block's bytes where one is
  /// held), each distinct factor once: what a pass must bring from memory unless it stays
  /// in cache.
  double operator_bytes() const { return operator_bytes_; }
  /// The plugin's copies of the subdomains' input (K_s, f_s, coordinates, lists) and the
  /// kernels R_s with their index maps, summed over the ranks (feti/held_bytes.h).
  double input_bytes() const { return input_bytes_; }
  /// Floating-point operations of the numeric factorizations (CHOLMOD's count from each
  /// distinct factor's analysis), summed over the ranks: over time_factor, their rate.
  double factor_flops() const { return factor_flops_; }
  double kernel_bytes() const { return kernel_bytes_; }
  /// The dual system's bytes over all ranks as set up (DualSystem::held_bytes).
  const DualSystem::HeldBytes& dual_bytes() const { return dual_bytes_; }
  /// The solver path the data call for (ALGORITHMS.md section 6).
  DualPath path() const { return dual_->path(); }

  /// Gives `system`, a dual system over this problem's factorized subdomains (the
  /// sensitivity problem's), the preconditioner `kind` built from K as its dual operator sees
  /// it. Collective.
  void precondition(DualSystem& system, DualPreconditioner kind) const;

  /// The loads as the dual operators see them: FETI-1 eliminates the Dirichlet dofs of
  /// `loads` (with the prescribed values, or zero if `homogeneous`). This rank's.
  std::vector<Vec> operator_loads(const std::vector<Vec>& loads, bool homogeneous) const;

 private:
  void set_up(const ContactInput& local_contact);
  /// B and c from the current inputs (the records of all ranks gathered; the slaves' also
  /// into `gathered` if given). Collective.
  Constraints build_rows(std::vector<DofRecord>* gathered = nullptr) const;
  /// The rows built anew from the current inputs take over c (B must come out the same);
  /// then the dual right-hand side. Collective.
  void rebuild_right_hand_side();
  void factorize(const Constraints& constraints);
  void compute_dual_data();
  void gather_rank_statistics(double solve_seconds) const;

  FetiSetupSettings settings_;
  std::shared_ptr<const Communicator> comm_;
  std::vector<SubdomainInput> inputs_;  // this rank's: original K_s (lower triangle), f_s (energy, KKT)
  std::vector<int> global_ids_;
  int global_count_ = 0;
  std::vector<int> owner_, bodies_;     // of every global subdomain
  std::vector<std::array<double, 2>> contact_positions_;
  std::vector<double> contact_heights_;
  std::vector<std::array<int, 2>> contact_body_component_;
  double snap_ = 0;
  int space_dimension_ = 2;
  SubdomainList subdomains_;
  std::unique_ptr<DualSystem> dual_;
  DualData data_;                       // the state problem's dual right-hand side
  Vec rhs_;                             // c: the constraints' rhs, friction rows' from the last load step
  Vec built_rhs_;                       // c as built for the current Dirichlet values
  ContactInput local_contact_;          // this rank's contact input, to rebuild the rows' rhs
  std::vector<BoundingBox> boxes_;      // of every global subdomain
  FrictionLaw friction_;
  Vec step_start_;                      // friction: multipliers of the last load step (empty: none)
  long primal_dimension_ = 0;
  long factorizations_ = 0, shared_factors_ = 0, supernodal_factors_ = 0, interface_factors_ = 0, symbolic_analyses_ = 0;
  DualSystem::HeldBytes dual_bytes_;
  double factor_nonzeros_ = 0, factor_bytes_ = 0, operator_bytes_ = 0, input_bytes_ = 0, kernel_bytes_ = 0, factor_flops_ = 0;
  mutable std::vector<RankStatistics> rank_statistics_;
  PhaseTimes setup_times_;
  ExplicitBlocks explicit_blocks_;      // over all ranks (seconds: the slowest rank's)
  double explicit_bytes_ = 0;           // over all ranks
  double local_factor_seconds_ = 0;  // this rank's, for the rank report
};

}  // namespace ffeti
