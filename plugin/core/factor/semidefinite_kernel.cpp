#include "factor/semidefinite_kernel.h"

#include "factor/cholmod_factor.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <random>
#include <stdexcept>
#include <string>

extern "C" {
// LAPACK: Cholesky factorization with complete pivoting of a positive semidefinite matrix.
void dpstrf_(const char* uplo, const int* n, double* a, const int* lda, int* piv, int* rank, const double* tol,
             double* work, int* info);
}

namespace ffeti {
namespace {

/// Dense: P'AP = R'R with R = [R11 R12; 0 0], R11 of the rank; Ker A = P[-R11^{-1} R12; I_k],
/// the deleted rows the last k pivots.
SemidefiniteKernel dense_kernel(const SparseMatrix& A, double tolerance) {
  const Eigen::Index r = A.rows();
  Eigen::MatrixXd R = Eigen::MatrixXd(A);
  std::vector<int> pivot(static_cast<size_t>(r));
  for (Eigen::Index i = 0; i < r; ++i) pivot[static_cast<size_t>(i)] = static_cast<int>(i) + 1;  // A = 0: no call
  std::vector<double> work(static_cast<size_t>(2 * r));
  int n = static_cast<int>(r), rank = 0, info = 0;
  if (r > 0 && tolerance > 0) {
    dpstrf_("U", &n, R.data(), &n, pivot.data(), &rank, &tolerance, work.data(), &info);
    if (info < 0) throw std::runtime_error("semidefinite_kernel: dpstrf rejected argument " + std::to_string(-info));
  }
  const Eigen::Index k = r - rank;
  SemidefiniteKernel out;
  out.basis.resize(r, k);
  if (k > 0) {
    Eigen::MatrixXd Y(r, k);
    Y.topRows(rank) = -R.topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solve(R.topRightCorner(rank, k));
    Y.bottomRows(k).setIdentity();
    Eigen::MatrixXd kernel(r, k);  // rows back to A's order
    for (Eigen::Index i = 0; i < r; ++i) kernel.row(pivot[static_cast<size_t>(i)] - 1) = Y.row(i);
    out.basis = orthonormal_columns(kernel);
  }
  for (Eigen::Index i = rank; i < r; ++i) out.deleted_rows.push_back(pivot[static_cast<size_t>(i)] - 1);
  return out;
}

/// Block inverse iteration with A + shift I (`solve_shifted`); the Ritz vectors whose Ritz
/// values are below `tolerance` span Ker A once the non-null components have died out: each
/// step shrinks them by shift / (lambda + shift) for an eigenvalue lambda. The shift is the
/// tolerance itself: smaller, A + shift I would be too close to singular for its factor.
template <class Apply, class SolveShifted>
SemidefiniteKernel inverse_iteration_kernel(Eigen::Index r, double tolerance, const Apply& apply_A,
                                            const SolveShifted& solve_shifted) {
  constexpr int kSteps = 6;  // an eigenvalue 1e4 times the tolerance keeps (1e-4)^6 of its part: nothing
  std::mt19937 random(20261127);
  std::normal_distribution<double> gauss;
  for (Eigen::Index block = std::min<Eigen::Index>(8, r);; block = std::min<Eigen::Index>(2 * block, r)) {
    Eigen::MatrixXd X = Eigen::MatrixXd::NullaryExpr(r, block, [&] { return gauss(random); });
    X = orthonormal_columns(X);
    for (int step = 0; step < kSteps; ++step) X = orthonormal_columns(solve_shifted(X));
    const Eigen::MatrixXd AX = apply_A(X);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ritz(X.transpose() * AX);
    Eigen::Index k = 0;  // Ritz values ascend
    while (k < block && ritz.eigenvalues()[k] <= tolerance) ++k;
    if (k == block && block < r) continue;  // the null space may be larger than the block
    SemidefiniteKernel out;
    out.basis = orthonormal_columns(X * ritz.eigenvectors().leftCols(k));
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> pivoting(out.basis.transpose());
    for (Eigen::Index i = 0; i < k; ++i) out.deleted_rows.push_back(pivoting.colsPermutation().indices()[i]);
    return out;
  }
}

/// Sparse: the shifted matrix by a sparse Cholesky factor.
SemidefiniteKernel sparse_kernel(const SparseMatrix& A, double tolerance) {
  SparseMatrix shifted = A;
  for (Eigen::Index i = 0; i < A.rows(); ++i) shifted.coeffRef(i, i) += tolerance;
  CholmodFactor factor(FactorKind::supernodal);
  if (factor.factorize(shifted) >= 0)
    throw std::runtime_error("semidefinite_kernel: A + shift I is not positive definite (A is not semidefinite)");
  return inverse_iteration_kernel(
      A.rows(), tolerance, [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(A * X); },
      [&](const Eigen::MatrixXd& X) {
        Eigen::MatrixXd Y;
        factor.solve(X, Y);
        return Y;
      });
}

double largest_diagonal(const Eigen::VectorXd& diagonal) { return diagonal.size() > 0 ? diagonal.maxCoeff() : 0.0; }

/// A = 0: everything is null, every row deleted.
SemidefiniteKernel everything_null(Eigen::Index r) {
  SemidefiniteKernel out{Eigen::MatrixXd::Identity(r, r), {}};
  for (int i = 0; i < r; ++i) out.deleted_rows.push_back(i);
  return out;
}

}  // namespace

Eigen::MatrixXd orthonormal_columns(const Eigen::MatrixXd& X) {
  return X.householderQr().householderQ() * Eigen::MatrixXd::Identity(X.rows(), X.cols());
}

SemidefiniteKernel semidefinite_kernel(const SparseMatrix& A, double relative_tolerance, Eigen::Index dense_limit) {
  if (A.rows() != A.cols()) throw std::invalid_argument("semidefinite_kernel: A is not square");
  const double largest = largest_diagonal(A.diagonal());
  if (largest <= 0) return everything_null(A.rows());
  const double tolerance = relative_tolerance * largest;  // in the units of A
  return A.rows() <= dense_limit ? dense_kernel(A, tolerance) : sparse_kernel(A, tolerance);
}

SemidefiniteKernel semidefinite_kernel_by_iteration(const Eigen::MatrixXd& A, double relative_tolerance) {
  if (A.rows() != A.cols()) throw std::invalid_argument("semidefinite_kernel: A is not square");
  const double largest = largest_diagonal(A.diagonal());
  if (largest <= 0) return everything_null(A.rows());
  const double tolerance = relative_tolerance * largest;
  Eigen::MatrixXd shifted = A;
  shifted.diagonal().array() += tolerance;
  const Eigen::LLT<Eigen::MatrixXd> factor(shifted);
  if (factor.info() != Eigen::Success)
    throw std::runtime_error("semidefinite_kernel: A + shift I is not positive definite (A is not semidefinite)");
  return inverse_iteration_kernel(
      A.rows(), tolerance, [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(A * X); },
      [&](const Eigen::MatrixXd& X) { return Eigen::MatrixXd(factor.solve(X)); });
}

}  // namespace ffeti
