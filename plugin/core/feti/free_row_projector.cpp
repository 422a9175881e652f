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
  // A + s W W' is regular, acts as A on Im A and as s on Ker A; s of A's scale keeps it
  // as well conditioned as A is on its range.
  const double s = largest > 0 ? largest : 1.0;  // G_F = 0: every row of G is left to C
  solver_.compute(A + s * W_ * W_.transpose());
  if (r > 0 && (solver_.info() != Eigen::Success || solver_.rcond() < 1e-14))
    throw std::runtime_error("FreeRowProjector: G_F G_F' + s W W' is singular");

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

void FreeRowProjector::apply(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  Vec defect = G_ * x;
  remove_body_modes(defect);
  const Vec z = solver_.solve(defect);
  y.head(free_).noalias() -= G_F_.transpose() * z;
}

void FreeRowProjector::apply_transpose(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  Vec z = solver_.solve(G_F_ * x.head(free_));
  remove_body_modes(z);
  y.noalias() -= G_.transpose() * z;
}

void FreeRowProjector::project_out_kernel(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  Vec z = solver_.solve(G_F_ * x.head(free_));
  remove_body_modes(z);
  y.head(free_).noalias() -= G_F_.transpose() * z;
}

void FreeRowProjector::project_remaining_range(const Vec& x, Vec& y) const {
  if (C_.rows() == 0) {
    y.setZero(x.size());
    return;
  }
  y.noalias() = C_.transpose() * solver_C_.solve(C_ * x);
}

}  // namespace ffeti
