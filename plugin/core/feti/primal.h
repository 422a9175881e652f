// From the dual solution back to the primal one, and the KKT conditions checked there.
#pragma once

#include "feti/coarse_space.h"
#include "feti/dual_operator.h"

#include <vector>

namespace ffeti {

/// u = K^+(f - B'lambda) + R alpha, with alpha the least-squares solution of
/// B R alpha = c - B K^+(f - B'lambda) on the rows that hold with equality (all equality
/// rows, the contact rows with lambda_i > 0 and the friction rows that stick, ||lambda_t||
/// < g); the rigid modes those leave free, as far as the slipping friction pairs of a 3D
/// problem fix them, such that each pair slips along its force. `f` are the loads the
/// operators use, `c` the right-hand side of the rows, `slip_bound` g per friction row. Collective; returns u for this rank's subdomains.
std::vector<Vec> recover_primal(const DualOperator& F, const CoarseSpace* coarse,
                                const Constraints& constraints, const std::vector<Vec>& f,
                                const Vec& c, const Vec& lambda, const Vec& slip_bound = Vec());

/// A friction group: the friction rows of one contact row starting at global row `row`, one
/// in a plane problem, the pair (t1, t2) in three dimensions (Constraints::tangent_directions).
/// Its tangential force lambda_t is the group's multipliers; `g` its bound.
/// The norm ||lambda_t|| (|lambda_t| in a plane problem).
double tangential_norm(const Constraints& constraints, const Vec& lambda, int row);
/// Whether the group slips, lambda_t at its bound: |lambda_t| >= g; a disc's boundary is met
/// only to round-off, so a pair's norm counts from (1 - 1e-12) g on.
bool at_slip_bound(const Constraints& constraints, const Vec& lambda, int row, double g);

/// A group's friction conditions, lambda_scale times the (relative) KKT measures, with
/// `gap` = B u - c over all rows (the slip s of the step on the group's rows): `excess`
/// ||lambda_t|| - g; `complementarity`: it may slip (s != 0) only at its bound and against
/// its force, max(min(g - ||lambda_t||, lambda_scale) ||s||, ||lambda_t|| ||s|| - lambda_t.s)
/// in 3D (s parallel to lambda_t), max(min(g - |lambda_t|, lambda_scale) |s|, -lambda_t s) in
/// a plane problem; the distance from the bound counts up to lambda_scale (g may be +inf: a
/// row that must stick).
struct FrictionResidual {
  double excess = 0, complementarity = 0;
};
FrictionResidual friction_residual(const Constraints& constraints, const Vec& lambda, const Vec& gap, int row, double g,
                                   double lambda_scale);
/// The force scale of the friction measures: ||lambda||_inf, or where every multiplier is 0
/// (a Tresca scene with no force at all) the largest finite bound g, so that a row that
/// slips while its bound could have held it still counts (1 if no bound is finite).
double friction_force_scale(double lambda_scale, const Vec& slip_bound);

/// A row holds with equality at lambda: an equality row, a contact row with lambda_i > 0, a
/// friction row whose group sticks (not at_slip_bound, g its `slip_bound` entry).
bool holds_with_equality(const Constraints& constraints, const Vec& lambda, const Vec& slip_bound, int row);

/// KKT conditions of  min 1/2 u'Ku - f'u  s.t.  B_E u = c_E, B_I u <= c_I, recomputed in
/// primal form from the original (not eliminated) K_s of `inputs` (their lower triangles), the loads `f` (this
/// rank's) and the right-hand side `c` of `constraints`; the Dirichlet values are the
/// inputs' or, if `homogeneous_dirichlet`, zero (a sensitivity problem). All relative:
///   equilibrium     = ||K u - f + B'lambda||_2 / max(||f||_2, ||B'lambda||_2)
///                     (FETI-1: Dirichlet dofs excluded, their reactions are not in lambda)
///   equality        = max(|B_E u - c_E|, |u_D - g|) / ||u||_inf
///   inequality      = max(0, max(B_I u - c_I)) / ||u||_inf
///   dual_feasibility= max(0, -min lambda_I, max(||lambda_t|| - g)) / ||lambda||_inf
///   complementarity = max |lambda_i (B_I u - c_I)_i| / (||lambda||_inf ||u||_inf), and on
///                     the friction groups, s = B_t u - c_t the slip of the step:
///                     friction_residual's complementarity over the same scale (a group
///                     slips only at its bound, and against its friction force)
/// (friction rows: slip_bound g per row, empty without friction)
struct KktResiduals {
  double equilibrium = 0, equality = 0, inequality = 0, dual_feasibility = 0, complementarity = 0;
  double max() const;
  bool finite() const;  ///< every residual a number (an overflow of the data makes them nan or inf)
};

/// Collective over the ranks of `comm`; `inputs`, `local` and `u` are this rank's.
KktResiduals kkt_residuals(const std::vector<SubdomainInput>& inputs, const std::vector<Vec>& f, const Vec& c,
                           bool homogeneous_dirichlet, const std::vector<LocalConstraints>& local, const DualOperator& F,
                           const Constraints& constraints, bool dirichlet_eliminated,
                           const std::vector<Vec>& u, const Vec& lambda, const Communicator& comm,
                           const Vec& slip_bound = Vec());

/// 1/2 u'Ku - f'u summed over all subdomains, with the original K_s and f_s (collective).
double energy(const std::vector<SubdomainInput>& inputs, const std::vector<Vec>& u, const Communicator& comm);

}  // namespace ffeti
