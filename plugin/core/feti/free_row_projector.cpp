#include "feti/free_row_projector.h"

#include <stdexcept>
#include <string>
#include <vector>

extern "C" {
// LAPACK: Cholesky factorization with complete pivoting of a positive semidefinite matrix.
void dpstrf_(const char* uplo, const int* n, double* a, const int* lda, int* piv, int* rank, const double* tol,
             double* work, int* info);
}

namespace ffeti {

FreeRowProjector::FreeRowProjector(const RowMatrix& G, int free_columns) : G_(G), free_(free_columns) {
  const Eigen::Index r = G.rows();
  std::vector<Eigen::Triplet<double, int>> entries;
  for (Eigen::Index i = 0; i < r; ++i)
    for (RowMatrix::InnerIterator it(G, i); it; ++it)
      if (it.col() < free_) entries.emplace_back(static_cast<int>(i), static_cast<int>(it.col()), it.value());
  G_F_.resize(r, free_);
  G_F_.setFromTriplets(entries.begin(), entries.end());
  const Eigen::MatrixXd A = Eigen::MatrixXd(G_F_ * G_F_.transpose());

  // Ker A from LAPACK's rank-revealing Cholesky with complete pivoting (dpstrf):
  // P'AP = R'R, R = [R11 R12; 0 0] with R11 of the rank; the null space is P[-R11^{-1} R12; I_k].
  const double largest = r > 0 ? A.diagonal().maxCoeff() : 0.0;
  Eigen::MatrixXd R = A;
  std::vector<int> pivot(static_cast<size_t>(r));
  for (Eigen::Index i = 0; i < r; ++i) pivot[static_cast<size_t>(i)] = static_cast<int>(i) + 1;  // G_F = 0: no call
  std::vector<double> work(static_cast<size_t>(2 * r));
  int n = static_cast<int>(r), rank = 0, info = 0;
  const double tolerance = 1e-10 * largest;  // on the pivots, which have the units of A
  if (r > 0 && largest > 0) {
    dpstrf_("U", &n, R.data(), &n, pivot.data(), &rank, &tolerance, work.data(), &info);
    if (info < 0) throw std::runtime_error("FreeRowProjector: dpstrf rejected argument " + std::to_string(-info));
  }
  const Eigen::Index k = r - rank;
  if (k > 0) {
    Eigen::MatrixXd Y(r, k);
    Y.topRows(rank) = -R.topLeftCorner(rank, rank).triangularView<Eigen::Upper>().solve(R.topRightCorner(rank, k));
    Y.bottomRows(k).setIdentity();
    Eigen::MatrixXd kernel(r, k);  // rows back to G's order
    for (Eigen::Index i = 0; i < r; ++i) kernel.row(pivot[static_cast<size_t>(i)] - 1) = Y.row(i);
    W_ = kernel.householderQr().householderQ() * Eigen::MatrixXd::Identity(r, k);
  } else {
    W_.resize(r, 0);
  }
  // A^+ y for y in Im A (every use): delete the k rows and columns of the last pivots (the
  // leading block of the pivoted factor is regular, and the deleted equations follow from
  // the kept ones for such y), solve the rest by a sparse factor, then remove Ker A = Im W.
  std::vector<char> kept(static_cast<size_t>(r), 1);
  for (Eigen::Index i = rank; i < r; ++i) kept[static_cast<size_t>(pivot[static_cast<size_t>(i)] - 1)] = 0;
  std::vector<Eigen::Triplet<double, int>> selection;
  for (Eigen::Index i = 0, column = 0; i < r; ++i)
    if (kept[static_cast<size_t>(i)]) selection.emplace_back(static_cast<int>(i), static_cast<int>(column++), 1.0);
  keep_.resize(r, static_cast<Eigen::Index>(selection.size()));
  keep_.setFromTriplets(selection.begin(), selection.end());
  if (keep_.cols() > 0) {
    const Eigen::SparseMatrix<double> A_sparse = G_F_ * G_F_.transpose();
    solver_.compute(Eigen::SparseMatrix<double>(keep_.transpose() * A_sparse * keep_));
    if (solver_.info() != Eigen::Success)
      throw std::runtime_error("FreeRowProjector: G_F G_F' restricted to its pivots is singular");
  }

  C_ = W_.transpose() * G;
  if (k > 0) {
    solver_C_.compute(C_ * C_.transpose());
    if (solver_C_.info() != Eigen::Success || solver_C_.rcond() < 1e-12)
      throw std::runtime_error("FreeRowProjector: the floating bodies' modes meet no contact row");
  }
}

void FreeRowProjector::remove_body_modes(Vec& v) const {
  if (W_.cols() > 0) v.noalias() -= W_ * (W_.transpose() * v);
}

Vec FreeRowProjector::pseudo_solve(const Vec& y) const {
  Vec x = Vec::Zero(y.size());
  if (keep_.cols() > 0) x = keep_ * solver_.solve(Vec(keep_.transpose() * y));
  remove_body_modes(x);
  return x;
}

void FreeRowProjector::apply(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  Vec defect = G_ * x;
  remove_body_modes(defect);
  y.head(free_).noalias() -= G_F_.transpose() * pseudo_solve(defect);
}

void FreeRowProjector::apply_transpose(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  y.noalias() -= G_.transpose() * pseudo_solve(G_F_ * x.head(free_));
}

void FreeRowProjector::project_out_kernel(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  y.head(free_).noalias() -= G_F_.transpose() * pseudo_solve(G_F_ * x.head(free_));
}

void FreeRowProjector::project_remaining_range(const Vec& x, Vec& y) const {
  if (C_.rows() == 0) {
    y.setZero(x.size());
    return;
  }
  y.noalias() = C_.transpose() * solver_C_.solve(C_ * x);
}

}  // namespace ffeti
