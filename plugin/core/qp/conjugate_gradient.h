// Conjugate gradients for A x = b with A symmetric positive definite on the iteration's
// subspace. With A = P F P and b in Ker G this is the projected CG of FETI-1 (Farhat-Roux).
// Several independent systems with the same A may run in lockstep and share each
// application of A to a block of vectors (conjugate_gradient_block): the sensitivity
// directions of one design step do, since a subdomain factor solves a block of
// right-hand sides in one pass.
#pragma once

#include "qp/problem.h"

#include <vector>

namespace ffeti {

struct CgSettings {
  /// Restarts from the true gradient A x - b after the updated one passed the test and the
  /// true one did not; one more such failure returns `stagnated`.
  int residual_replacements = 2;
  void validate() const;
};

using CgResult = QpResult;

/// Minimizes 1/2 x'Hx - b'x of a problem without constraints (all blocks free, no equality
/// part) from the start x (updated in place). `stop` receives x, g = Hx - b and ||g||_2.
/// Convergence is declared only on the true gradient H x - b (recomputed once the updated
/// one passes the test: one more multiplication); if it fails the test, CG restarts from it,
/// and after `settings.residual_replacements` such restarts returns `stagnated`: the
/// tolerance asked for lies below what round-off lets the data reach. An updated gradient
/// that stalls or grows far below the first one (round-off, not the test) is checked the
/// same way.
/// With `problem.preconditioner` M (symmetric positive definite on the iteration's subspace)
/// this is preconditioned CG: directions from M g instead of g; the stop test still
/// receives ||g||_2. Multiplies at most budget.remaining() times and charges the budget.
CgResult conjugate_gradient(const qp::Problem& problem, const CgSettings& settings, Vec& x, qp::Budget& budget,
                            const StopTest& stop, const Monitor& monitor = {});

/// Y = A X, column by column the same operator as a LinearOperator.
using BlockOperator = std::function<void(const Eigen::MatrixXd& x, Eigen::MatrixXd& y)>;

/// conjugate_gradient for the systems A x_j = b_j, j = 0..k-1, with stop test stop[j] and
/// budget.remaining() multiplications for each (the budget is not charged: each run counts
/// as a solve on its own), preconditioned by M (applied to one vector at a time; empty: none):
/// every step multiplies the vectors of the unfinished systems as one block (A is called as
/// often as the longest run needs). Each system runs the same iteration, with the same
/// counts, as on its own.
std::vector<CgResult> conjugate_gradient_block(const BlockOperator& A, const std::vector<Vec>& b,
                                               std::vector<Vec>& x, const CgSettings& settings,
                                               const qp::Budget& budget, const std::vector<StopTest>& stop,
                                               const LinearOperator& preconditioner = {});

}  // namespace ffeti
