// Manufactured QPs with known KKT solutions (fixed seeds) for the solver unit tests.
#pragma once

#include "qp/problem.h"

#include <Eigen/Dense>

namespace ffeti::test {

/// Dense symmetric positive definite matrix with eigenvalues in [1, condition].
Eigen::MatrixXd random_spd(int n, double condition, unsigned seed);

/// min 1/2 x'Ax - b'x s.t. x_i >= l_i on the bounded components, with the solution
/// x_star known: a third of the bounded components strongly active (g > 0), one weakly
/// active (g = 0 at the bound), the rest free.
struct BoundQp {
  Eigen::MatrixXd A;
  Vec b, lower, x_star;
};
BoundQp manufactured_bound_qp(int n, double condition, unsigned seed, bool some_unbounded);

/// The same with the equality C x = 0 (C: k x n, full row rank) and its multiplier.
struct BoundEqualityQp {
  Eigen::MatrixXd H, C, Q;  // Q = C'(CC')^{-1}C
  Vec b, lower, x_star;
};
BoundEqualityQp manufactured_bound_equality_qp(int n, int k, double condition, unsigned seed);

LinearOperator dense_operator(const Eigen::MatrixXd& A);

/// The qp::Problem min 1/2 x'Ax - b'x over `bounds` (kUnbounded in `lower`: free; `upper`
/// empty or +infinity: no upper bound), with the norm estimate and optional preconditioner.
qp::Problem bound_problem(const LinearOperator& A, const Vec& b, const Vec& lower, double norm,
                          const Vec& upper = Vec(), const LinearOperator& preconditioner = {});
/// The same without bounds (all components free).
qp::Problem free_problem(const LinearOperator& A, const Vec& b);
/// A budget larger than any unit test's solve needs, fresh for each solve (a solver
/// charges the budget it is given).
inline qp::Budget& large_budget() {
  static qp::Budget budget(1000000);
  budget = qp::Budget(1000000);
  return budget;
}

}  // namespace ffeti::test
