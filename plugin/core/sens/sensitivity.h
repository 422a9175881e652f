// Semi-analytic sensitivity of a solved contact problem (seed eq. 12, ALGORITHMS.md
// section 7): the directional derivative z = u'(alpha; beta) solves
//   min 1/2 z'K z - z'fbar  s.t.  B_E z = 0,  B_S z = c~_S,  B_W z <= c~_W,
//   fbar = f' - K'u - B''lambda,  c~ = c' - B'u,
// over the rows E (gluing, Dirichlet), S (strongly active contact) and W (weakly active);
// inactive rows drop. The sign of the B' term follows from differentiating the state's
// equilibrium K u - f + B'lambda = 0 (lambda >= 0 on B_I u <= c_I): the seed's "+N''lambda"
// is the same term with its multipliers of the opposite sign. The QP has the state's K, so
// it runs on the state's factorizations: a DualSystem over the rows E, S, W, built once per
// state solution and shared by every direction. No subdomain is factorized again.
//
// Adjoint mode: with W empty, beta -> (z, lambda') is linear, and for a cost J(u, lambda, alpha)
//   dJ/dalpha(beta) = dJ/dalpha_explicit(beta) + w'fbar + mu'c~,
// where (w, mu) solve the same equality-constrained problem with load dJ/du and right-hand
// side dJ/dlambda on the kept contact rows (K w + B'mu = dJ/du, B w = dJ/dlambda; the
// matrix [K B'; B 0] is symmetric, so (w, mu)'(fbar, c~) = dJ/du'z + dJ/dlambda'lambda'):
// one dual solve for all design variables. Inactive rows have lambda' = 0.
#pragma once

#include "feti/feti_problem.h"
#include "sens/contact_derivative.h"
#include "sens/design_derivative.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ffeti {

/// The contact rows of a state solution sorted into strongly active (lambda_i > t
/// max lambda_I), weakly active (lambda_i <= t max lambda_I and gap_i = c_i - B_i u <=
/// t max|u|) and inactive (the rest), t the threshold.
struct ContactClassification {
  double threshold = 0;
  double lambda_scale = 0, gap_scale = 0;  ///< max lambda_I and max|u|: t times these are the cut-offs
  std::vector<int> strong, weak, inactive;  ///< row indices of the state's constraints
};

ContactClassification classify_contact(const FetiProblem& problem, const FetiResult& state, double threshold);

/// The default threshold for a state solved to `state_tolerance`: ten times it, the
/// accuracy to which its multipliers are known, at most 1e-2 and at least 1e-8 (the
/// round-off of recovered gaps, which a tighter tol does not remove).
double default_classification_threshold(double state_tolerance);

/// One solve of the sensitivity QP (a design direction or an adjoint).
struct DerivativeSolve {
  SolveStatus status = SolveStatus::invalid_input;  ///< adjoint: weakly_active when not solved
  DualPath path = DualPath::cholesky;  ///< the sensitivity QP's path
  IterationCounts counts;
  KktResiduals kkt;               ///< of the sensitivity QP, recomputed in primal form
  double seconds = 0;             ///< the whole call: derivatives, dual data, solve, recovery, KKT
  /// Contact rows the direction moves whose derivative is one-sided (node to face on a bent
  /// edge): the answer is one of the one-sided values, and a direct solve's status is
  /// weakly_active.
  int one_sided_rows = 0;
};

/// A direction's solve and the derivatives it gives.
struct SensitivityResult : DerivativeSolve {
  std::vector<Vec> z;             ///< u'(alpha; beta) per subdomain of this rank
  Vec multipliers;                ///< lambda'(alpha; beta) on the rows E, S, W (in that row order)
  Vec contact_multipliers;        ///< lambda' per contact row of the state, in its row order (0 where inactive)
};

using AdjointResult = DerivativeSolve;

/// What the sensitivity solves of one state solution cost so far (over all ranks).
struct SensitivityCounters {
  int directions = 0;            ///< direct solves (one per design direction)
  long hessian = 0;              ///< their Hessian multiplications, all directions
  double seconds = 0;            ///< their wall time, all directions
  SensitivityResult last;        ///< the last direction (without z)
  int adjoint_solves = 0;
  AdjointResult adjoint;         ///< the last adjoint solve
  int adjoint_gradients = 0;     ///< adjoint_gradient calls (one per design variable)
  double adjoint_gradient_seconds = 0;
  double setup_seconds = 0;      ///< classification and the dual system of the rows E, S, W
};

class SensitivityProblem {
 public:
  /// Classifies the contact rows of `state` (a solution of `problem`) with `threshold` in
  /// (0, 1) and builds the dual system of the sensitivity QP over the same factorizations.
  /// Keeps references to `problem` (which must outlive it) and copies what it needs of
  /// `state`. Collective.
  SensitivityProblem(const FetiProblem& problem, const FetiResult& state, double threshold);

  const ContactClassification& classification() const { return classification_; }
  const SensitivityCounters& counters() const { return counters_; }
  DualPath path() const { return system_->path(); }
  int dual_dimension() const { return system_->rows(); }

  /// z = u'(alpha; beta) for one direction. Never throws for non-convergence. Collective.
  SensitivityResult direct(const DesignDerivative& direction, const DualSolveSettings& settings);

  /// The same for several directions at once: on the equality-constrained paths (no weakly
  /// active row) their dual CG runs share each application of F (DualSystem::solve of a
  /// block); each result's seconds is its share of the whole. Collective.
  std::vector<SensitivityResult> direct(const std::vector<DesignDerivative>& directions,
                                        const DualSolveSettings& settings);

  /// Solves the adjoint problem for the cost gradient dJ/du (this rank's subdomains) and
  /// dJ/dlambda (one entry per contact row, the same on every rank; empty: J does not
  /// depend on lambda) and keeps (w, mu). Status weakly_active, and nothing solved, when
  /// some row is weakly active: then beta -> z is not linear and only direct() is right.
  /// Collective.
  AdjointResult adjoint(const std::vector<Vec>& dJdu, const DualSolveSettings& settings, const Vec& dJdlambda = Vec());

  /// w per subdomain of this rank from the last converged adjoint(), or null: for scripts
  /// that form w'K'u themselves from the shape derivative of their bilinear form.
  const std::vector<Vec>* adjoint_displacement() const { return adjoint_ ? &adjoint_->u : nullptr; }

  /// w'fbar + mu'c~ for one direction: the part of dJ/dalpha(beta) that goes through u.
  /// Needs a converged adjoint(). No dual solve. Collective.
  double adjoint_gradient(const DesignDerivative& direction);

 private:
  struct DirectionData {       // fbar (this rank's) and c~ on the rows of the system
    std::vector<Vec> fbar;
    Vec c;
    int one_sided_rows = 0;     // rows in use whose derivative along the direction is one-sided
  };
  DirectionData direction_data(const DesignDerivative& direction) const;
  void check(const DesignDerivative& direction) const;

  const FetiProblem& problem_;
  std::vector<Vec> u_;          // the state, this rank's subdomains
  Vec lambda_;                  // the state's multipliers (all rows)
  ContactClassification classification_;
  std::vector<int> kept_;       // row of the state's constraints behind each row of system_
  std::unique_ptr<DualSystem> system_;
  std::optional<DualSolution> adjoint_;
  SensitivityCounters counters_;
};

}  // namespace ffeti
