#include "feti/free_row_projector.h"

#include "feti/semidefinite_kernel.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace ffeti {

FreeRowProjector::FreeRowProjector(const RowMatrix& G, int free_columns) : G_(G), free_(free_columns) {
  const Eigen::Index r = G.rows();
  std::vector<Eigen::Triplet<double, int>> entries;
  for (Eigen::Index i = 0; i < r; ++i)
    for (RowMatrix::InnerIterator it(G, i); it; ++it)
      if (it.col() < free_) entries.emplace_back(static_cast<int>(i), static_cast<int>(it.col()), it.value());
  G_F_.resize(r, free_);
  G_F_.setFromTriplets(entries.begin(), entries.end());
  // Ker A, A = G_F G_F' (dense rank-revealing Cholesky when small, sparse inverse iteration
  // when large: semidefinite_kernel.h), and the rows to delete so that A^+ y for y in Im A
  // (every use) is a regular sparse solve: delete them, solve the rest, then remove Ker A.
  const Eigen::SparseMatrix<double> A_sparse = G_F_ * G_F_.transpose();
  SemidefiniteKernel kernel = semidefinite_kernel(A_sparse, 1e-10);  // on the pivots, relative
  W_ = std::move(kernel.basis);
  const Eigen::Index k = W_.cols();
  std::vector<char> kept(static_cast<size_t>(r), 1);
  for (int i : kernel.deleted_rows) kept[static_cast<size_t>(i)] = 0;
  std::vector<Eigen::Triplet<double, int>> selection;
  for (Eigen::Index i = 0, column = 0; i < r; ++i)
    if (kept[static_cast<size_t>(i)]) selection.emplace_back(static_cast<int>(i), static_cast<int>(column++), 1.0);
  keep_.resize(r, static_cast<Eigen::Index>(selection.size()));
  keep_.setFromTriplets(selection.begin(), selection.end());
  if (keep_.cols() > 0) {
    if (solver_.factorize(SparseMatrix(keep_.transpose() * A_sparse * keep_)) >= 0)
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

const Vec& FreeRowProjector::pseudo_solve(const Vec& y) const {
  pseudo_solution_.setZero(y.size());
  if (keep_.cols() > 0) {
    kept_rhs_.noalias() = keep_.transpose() * y;
    solver_.solve(kept_rhs_, kept_solution_);
    pseudo_solution_.noalias() = keep_ * kept_solution_;
  }
  remove_body_modes(pseudo_solution_);
  return pseudo_solution_;
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
