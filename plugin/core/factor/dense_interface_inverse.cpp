#include "factor/dense_interface_inverse.h"

#include <algorithm>

namespace ffeti {

PackedSymmetric::PackedSymmetric(const Eigen::MatrixXd& full) : size_(full.rows()) {
  values_.reserve(static_cast<size_t>(size_ * (size_ + 1) / 2));
  for (Eigen::Index j = 0; j < size_; ++j)
    values_.insert(values_.end(), full.col(j).data() + j, full.col(j).data() + size_);
}

void PackedSymmetric::apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.setZero(size_);
  const double* column = values_.data();
  for (Eigen::Index j = 0; j < size_; ++j) {
    const Eigen::Index below = size_ - j - 1;
    const Eigen::Map<const Eigen::VectorXd> lower(column + 1, below);  // rows j+1..t-1 of column j
    y[j] += column[0] * x[j] + lower.dot(x.tail(below));
    y.tail(below).noalias() += x[j] * lower;
    column += below + 1;
  }
}

void PackedSymmetric::apply(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  y.setZero(size_, x.cols());
  const double* column = values_.data();
  for (Eigen::Index j = 0; j < size_; ++j) {
    const Eigen::Index below = size_ - j - 1;
    const Eigen::Map<const Eigen::VectorXd> lower(column + 1, below);
    y.row(j).noalias() += column[0] * x.row(j) + lower.transpose() * x.bottomRows(below);
    y.bottomRows(below).noalias() += lower * x.row(j);
    column += below + 1;
  }
}

Eigen::MatrixXd PackedSymmetric::full() const {
  Eigen::MatrixXd S(size_, size_);
  const double* column = values_.data();
  for (Eigen::Index j = 0; j < size_; ++j) {
    for (Eigen::Index i = j; i < size_; ++i) S(i, j) = S(j, i) = column[i - j];
    column += size_ - j;
  }
  return S;
}

PackedSymmetric dense_interface_inverse(const CholmodFactor& factor, const std::vector<int>& columns,
                                        CholmodSolveWorkspace& workspace, Eigen::Index width) {
  const auto t = static_cast<Eigen::Index>(columns.size());
  std::vector<Eigen::Index> present;  // positions k with columns[k] >= 0
  for (Eigen::Index k = 0; k < t; ++k)
    if (columns[static_cast<size_t>(k)] >= 0) present.push_back(k);
  const auto count = static_cast<Eigen::Index>(present.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(t, t);
  Eigen::MatrixXd identity_columns, solved;
  for (Eigen::Index start = 0; start < count; start += width) {
    const Eigen::Index block = std::min(width, count - start);
    identity_columns.setZero(factor.size(), block);
    for (Eigen::Index c = 0; c < block; ++c)
      identity_columns(columns[static_cast<size_t>(present[static_cast<size_t>(start + c)])], c) = 1;
    factor.solve(identity_columns, solved, workspace);
    // Only the lower triangle is kept: rows from the column's own position on.
    for (Eigen::Index c = 0; c < block; ++c)
      for (Eigen::Index a = start + c; a < count; ++a)
        S(present[static_cast<size_t>(a)], present[static_cast<size_t>(start + c)]) =
            solved(columns[static_cast<size_t>(present[static_cast<size_t>(a)])], c);
  }
  return PackedSymmetric(S);
}

double packed_symmetric_bytes(Eigen::Index t) { return static_cast<double>(t) * static_cast<double>(t + 1) / 2 * sizeof(double); }

bool explicit_inverse_pays(double packed_bytes, double solve_pass_bytes) {
  return packed_bytes > 0 && packed_bytes <= solve_pass_bytes;
}

}  // namespace ffeti
