#include "qp_test_problems.h"

#include <random>

namespace ffeti::test {

Eigen::MatrixXd random_spd(int n, double condition, unsigned seed) {
  std::mt19937 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd M(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) M(i, j) = normal(generator);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(M);
  const Eigen::MatrixXd Q = qr.householderQ();
  Vec eigenvalues(n);
  for (int i = 0; i < n; ++i) eigenvalues[i] = std::pow(condition, double(i) / std::max(n - 1, 1));
  return Q * eigenvalues.asDiagonal() * Q.transpose();
}

BoundQp manufactured_bound_qp(int n, double condition, unsigned seed, bool some_unbounded) {
  std::mt19937 generator(seed + 1);
  std::uniform_real_distribution<double> uniform(0.5, 2.0);
  BoundQp qp;
  qp.A = random_spd(n, condition, seed);
  qp.x_star.resize(n);
  qp.lower.resize(n);
  Vec g = Vec::Zero(n);  // gradient at the solution
  for (int i = 0; i < n; ++i) {
    const bool bounded = !(some_unbounded && i % 4 == 3);
    const double value = uniform(generator);
    if (!bounded) {
      qp.lower[i] = kUnbounded;
      qp.x_star[i] = value - 1.25;
    } else if (i % 3 == 0) {           // strongly active
      qp.lower[i] = -value;
      qp.x_star[i] = -value;
      g[i] = uniform(generator);
    } else if (i == 1) {               // weakly active
      qp.lower[i] = value;
      qp.x_star[i] = value;
    } else {                           // free, inside the bounds
      qp.lower[i] = -value;
      qp.x_star[i] = value;
    }
  }
  qp.b = qp.A * qp.x_star - g;
  return qp;
}

BoundEqualityQp manufactured_bound_equality_qp(int n, int k, double condition, unsigned seed) {
  std::mt19937 generator(seed + 2);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(0.5, 2.0);
  BoundEqualityQp qp;
  qp.H = random_spd(n, condition, seed);
  qp.C.resize(k, n);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < n; ++j) qp.C(i, j) = normal(generator);
  qp.Q = qp.C.transpose() * (qp.C * qp.C.transpose()).ldlt().solve(qp.C);
  Vec z(n);
  for (int i = 0; i < n; ++i) z[i] = normal(generator);
  qp.x_star = z - qp.Q * z;  // in Ker C
  qp.lower.resize(n);
  Vec g = Vec::Zero(n);
  for (int i = 0; i < n; ++i) {
    if (i % 5 == 4) {
      qp.lower[i] = kUnbounded;
    } else if (i % 3 == 0) {  // strongly active
      qp.lower[i] = qp.x_star[i];
      g[i] = uniform(generator);
    } else {
      qp.lower[i] = qp.x_star[i] - uniform(generator);
    }
  }
  Vec mu(k);
  for (int i = 0; i < k; ++i) mu[i] = normal(generator);
  // KKT: H x - b + C'mu = g with g >= 0 on the active set, 0 elsewhere.
  qp.b = qp.H * qp.x_star + qp.C.transpose() * mu - g;
  return qp;
}

LinearOperator dense_operator(const Eigen::MatrixXd& A) {
  return [A](const Vec& x, Vec& y) { y = A * x; };
}

qp::Problem bound_problem(const LinearOperator& A, const Vec& b, const Vec& lower, double norm, const Vec& upper,
                          const LinearOperator& preconditioner) {
  qp::Problem problem;
  problem.hessian = A;
  problem.b = b;
  problem.hessian_norm = norm;
  problem.preconditioner = preconditioner;
  problem.constraints = qp::ConstraintSet::from_bounds(lower, upper);
  return problem;
}

qp::Problem free_problem(const LinearOperator& A, const Vec& b) {
  qp::Problem problem;
  problem.hessian = A;
  problem.b = b;
  problem.constraints.add_free(b.size());
  return problem;
}

}  // namespace ffeti::test
