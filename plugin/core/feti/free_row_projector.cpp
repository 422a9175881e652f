#include "feti/free_row_projector.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace ffeti {

FreeRowProjector::FreeRowProjector(const CoarseGram& gram, int free_columns) : G_(gram.G()), free_(free_columns) {
  const Eigen::Index r = G_.rows();
  std::vector<Eigen::Triplet<double, int>> entries;
  for (Eigen::Index i = 0; i < r; ++i)
    for (RowMatrix::InnerIterator it(G_, i); it; ++it)
      if (it.col() < free_) entries.emplace_back(static_cast<int>(i), static_cast<int>(it.col()), it.value());
  G_F_.resize(r, free_);
  G_F_.setFromTriplets(entries.begin(), entries.end());
  // A = G_F G_F', semidefinite: Ker A (W) and solves on Im A (every use) from the coarse
  // problem's Gram matrices (coarse_gram.h).
  Vec free = Vec::Zero(G_.cols());
  free.head(free_).setOnes();
  free_gram_ = gram.over_columns(free, RankDecision::search);
  W_ = free_gram_->kernel();
  const Eigen::Index k = W_.cols();
  C_ = W_.transpose() * G_;
  if (k > 0) {
    solver_C_.compute(C_ * C_.transpose());
    if (solver_C_.info() != Eigen::Success || solver_C_.rcond() < 1e-12)
      throw std::runtime_error("FreeRowProjector: the floating bodies' modes meet no contact row");
    Z_.resize(r, k);
    Vec column(r), solution(r);
    for (Eigen::Index j = 0; j < k; ++j) {
      column = W_.col(j);
      gram.solve(column, solution);
      Z_.col(j) = solution;
    }
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
  y.head(free_).noalias() -= G_F_.transpose() * free_gram_->solve(defect);
}

void FreeRowProjector::apply_transpose(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  y.noalias() -= G_.transpose() * free_gram_->solve(G_F_ * x.head(free_));
}

void FreeRowProjector::apply_projected(const Vec& x, Vec& y) const {
  apply(x, y);
  if (Z_.cols() > 0) y.noalias() -= G_.transpose() * (Z_ * (C_ * x));
}

void FreeRowProjector::apply_projected_transpose(const Vec& x, Vec& y) const {
  apply_transpose(x, y);
  if (Z_.cols() > 0) y.noalias() -= C_.transpose() * (Z_.transpose() * (G_ * x));
}

void FreeRowProjector::project_out_kernel(const Vec& x, Vec& y) const {
  y = x;
  if (G_.rows() == 0) return;
  y.head(free_).noalias() -= G_F_.transpose() * free_gram_->solve(G_F_ * x.head(free_));
}

void FreeRowProjector::project_remaining_range(const Vec& x, Vec& y) const {
  if (C_.rows() == 0) {
    y.setZero(x.size());
    return;
  }
  y.noalias() = C_.transpose() * solver_C_.solve(C_ * x);
}

}  // namespace ffeti
