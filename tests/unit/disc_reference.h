// Disc-constrained test QPs (isotropic friction's constraint set) and their independent
// dense answers: an accelerated projected gradient (FISTA with restarts) and a KKT check,
// both written here apart from the solvers' code.
#pragma once

#include "qp/problem.h"

#include <Eigen/Dense>

namespace ffeti::test {

/// min 1/2 x'Hx - b'x, optionally with C x = 0, over `free` free components, then
/// half-lines x_i >= lower, then discs ||x_pair - centre_pair|| <= radius (one per pair).
/// The solvers get set(); the reference below reads the data itself.
struct DiscQp {
  Eigen::MatrixXd H, C;
  Vec b;
  Eigen::Index free = 0;
  Vec lower, centre, radius;
  qp::ConstraintSet set() const;
  Eigen::Index first_disc() const { return free + lower.size(); }
};

/// 2 free components, 3 half-lines, 5 discs (one of radius 0, one far larger than the
/// distance from the unconstrained minimum, three smaller), H with eigenvalues in [1, condition].
DiscQp random_disc_qp(double condition, unsigned seed);

/// The Euclidean projection onto the set (free: none, half-line: max, disc: radial).
Vec project_onto_set(const Vec& x, const DiscQp& qp);

/// FISTA with adaptive restart on the dense problem, to ||x_k+1 - x_k|| <= 1e-15 (1 + ||x||).
/// With C (only on free components), the free part is projected onto Ker C_free as well.
Vec accelerated_projected_gradient(const DiscQp& qp);

/// The largest violation of the KKT conditions at x, relative to ||b||: feasibility,
/// stationarity of Hx - b + C'mu (mu by least squares on the components no bound holds),
/// the multipliers' signs (half-line: g_i >= 0 at the bound; circle: g_pair = -lambda n,
/// lambda >= 0) and complementarity (g = 0 where nothing holds).
double kkt_violation(const DiscQp& qp, const Vec& x);

}  // namespace ffeti::test
