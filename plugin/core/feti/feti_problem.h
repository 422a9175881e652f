// A FETI problem set up once (constraints, kernels, factorizations, coarse space) and
// solved for one or more load cases, choosing the solver path the scene needs.
#pragma once

#include "feti/coarse_space.h"
#include "feti/constraints.h"
#include "feti/dual_operator.h"
#include "feti/primal.h"
#include "feti/problem_input.h"
#include "feti/subdomain.h"
#include "parallel/communicator.h"
#include "parallel/subdomain_sum.h"
#include "qp/conjugate_gradient.h"
#include "qp/norm_estimate.h"
#include "qp/smalbe.h"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ffeti {

struct FetiSetupSettings {
  FetiVariant variant = FetiVariant::feti1;
  FactorKind factor = FactorKind::simplicial;
  /// OpenMP threads over subdomains; 0: the runtime default. Supernodal factors run on one
  /// thread: they call BLAS, and Debian's serial OpenBLAS is not safe to call concurrently.
  int threads = 0;
};

/// Relative stopping test of every path (the seed's, with its "N f" read as the dual
/// right-hand side, see docs/algorithms.md):
///   ||gP(lambda, mu, 0)||_2 <= tolerance ||b||_2,  b = P(d - F lambda~)
///   ||G lambda - e||_2      <= tolerance ||e||_2   (where there is a coarse space)
struct DualSolveSettings {
  double tolerance = 1e-4;
  int max_hessian = 10000;          ///< over the whole solve
  SmalbeSettings smalbe{};          ///< used on the SMALBE path (its max_hessian is overridden)
  MprgpSettings mprgp{};            ///< used on the MPRGP path and inside SMALBE
  NormEstimateSettings norm_estimate{};
  Monitor monitor{};

  void validate() const;  ///< throws InputError naming the setting
};

struct PhaseTimes {  ///< wall-clock seconds; over several ranks, the slowest rank's
  double constraints = 0, factorization = 0, coarse_space = 0, dual_data = 0;
  double norm_estimate = 0, solve = 0, recovery = 0, kkt = 0;
};

struct FetiResult {
  SolveStatus status = SolveStatus::invalid_input;
  std::string path;              ///< cholesky, cg, projected_cg, mprgp or smalbe
  std::string phases;            ///< the phases this solve ran, comma separated
  IterationCounts counts;
  double gradient_norm = 0;      ///< final ||gP|| (absolute) and its reference ||b||
  double gradient_reference = 0;
  double equality_norm = 0;      ///< final ||G lambda - e|| and its reference ||e||
  double equality_reference = 0;
  std::vector<Vec> u;            ///< primal solution per subdomain of this rank
  Vec lambda;                    ///< multipliers, rows ordered as constraints()
  double energy = 0;             ///< 1/2 u'Ku - f'u
  KktResiduals kkt;
  int active_contact = 0;        ///< contact rows with lambda > 0
  PhaseTimes times;              ///< norm_estimate, solve, recovery, kkt of this call
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

  int subdomain_count() const { return global_count_; }
  int local_subdomain_count() const { return static_cast<int>(inputs_.size()); }
  const std::vector<int>& global_ids() const { return global_ids_; }
  const Communicator& communicator() const { return *comm_; }
  long primal_dimension() const { return primal_dimension_; }
  int dual_dimension() const { return constraints_.rows(); }
  int floating_subdomains() const { return coarse_ ? coarse_->floating_subdomains() : 0; }
  int coarse_dimension() const { return coarse_ ? coarse_->dimension() : 0; }
  /// Per-rank figures gathered at set-up and after each solve (rank order).
  const std::vector<RankStatistics>& rank_statistics() const { return rank_statistics_; }
  const Constraints& constraints() const { return constraints_; }
  /// The input as given (original K_s and current loads f_s).
  const std::vector<SubdomainInput>& inputs() const { return inputs_; }
  /// Position and multiplier of every contact row's slave dof (gathered: the same on all
  /// ranks; every contact row, in row order).
  const std::vector<std::array<double, 2>>& contact_positions() const { return contact_positions_; }
  const PhaseTimes& setup_times() const { return setup_times_; }
  FetiVariant variant() const { return settings_.variant; }
  double factor_nonzeros() const { return factor_nonzeros_; }
  /// The solver path the data call for (ALGORITHMS.md section 6).
  std::string path() const;

 private:
  void set_up(const ContactInput& local_contact);
  void factorize();
  void compute_dual_data();
  void gather_rank_statistics(double solve_seconds) const;
  double operator_norm(bool projected, IterationCounts& counts, double& seconds) const;
  void apply_PFP(const Vec& x, Vec& y) const;  // the projected dual operator, on reused buffers
  FetiResult finish(FetiResult result, const Vec& lambda) const;

  FetiSetupSettings settings_;
  std::shared_ptr<const Communicator> comm_;
  std::vector<SubdomainInput> inputs_;  // this rank's: original K_s, f_s (energy, KKT)
  std::vector<int> global_ids_;
  int global_count_ = 0;
  std::vector<Vec> operator_loads_;     // f_s as the operators see them (FETI-1: eliminated)
  Constraints constraints_;
  std::vector<std::array<double, 2>> contact_positions_;
  SubdomainList subdomains_;
  std::vector<LocalConstraints> local_;
  std::unique_ptr<SubdomainSum> sum_;
  std::unique_ptr<DualOperator> F_;
  std::unique_ptr<CoarseSpace> coarse_;
  long primal_dimension_ = 0;
  double factor_nonzeros_ = 0;
  mutable std::vector<RankStatistics> rank_statistics_;
  mutable Vec projected_, applied_;  // buffers of apply_PFP
  Vec d_, e_, lambda_tilde_, b_;        // dual data; b = P(d - F lambda~)
  PhaseTimes setup_times_;
  double local_factor_seconds_ = 0;  // this rank's, for the rank report
  mutable std::optional<double> norm_F_, norm_PFP_;  // cached: same F for every load case
  mutable int norm_F_cost_ = 0, norm_PFP_cost_ = 0;
};

}  // namespace ffeti
