#include "factor/dense_interface_inverse.h"

#include "parallel/process.h"

#include <algorithm>

namespace ffeti {

PackedSymmetric::PackedSymmetric(const Eigen::MatrixXd& full) : size_(full.rows()) {
  values_.reserve(static_cast<size_t>(size_ * (size_ + 1) / 2));
  for (Eigen::Index p = 0; p < size_; p += kPanelWidth) {
    const Eigen::Index width = std::min(kPanelWidth, size_ - p);
    for (Eigen::Index c = 0; c < width; ++c)  // the diagonal block's lower triangle
      values_.insert(values_.end(), full.col(p + c).data() + p + c, full.col(p + c).data() + p + width);
    for (Eigen::Index i = p + width; i < size_; ++i)  // the rows below it
      for (Eigen::Index c = 0; c < width; ++c) values_.push_back(full(i, p + c));
  }
}

PackedSymmetric::Panel PackedSymmetric::panel(Eigen::Index p, const double*& next) const {
  const Eigen::Index width = std::min(kPanelWidth, size_ - p), below = size_ - p - width;
  const double* diagonal = next;
  next += width * (width + 1) / 2;
  const Eigen::Map<const RowMajorBlock> A(next, below, width);
  next += below * width;
  return {diagonal, width, A};
}

namespace {

/// A full panel's rows below its diagonal block, each read once: y_below(i) += row_i . x_panel
/// and y_panel += sum over i of row_i x_below(i), the sum in registers (fixed size, so Eigen
/// vectorizes both). Two GEMVs read every value twice and the result's rows once per column
/// pass: 7-12 against 15-20 GB/s at t = 128 to 512 on one thread (docs/log.md, 2026-12-07).
void apply_full_panel_below(const double* rows, Eigen::Index below, const double* x_panel, const double* x_below,
                            double* y_panel, double* y_below) {
  using Row = Eigen::Matrix<double, PackedSymmetric::kPanelWidth, 1>;
  const Eigen::Map<const Row> x(x_panel);
  Row sum = Row::Zero();
  for (Eigen::Index i = 0; i < below; ++i, rows += PackedSymmetric::kPanelWidth) {
    const Eigen::Map<const Row> row(rows);
    y_below[i] += row.dot(x);
    sum += row * x_below[i];
  }
  Eigen::Map<Row>(y_panel) += sum;
}

}  // namespace

void PackedSymmetric::apply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  y.setZero(size_);
  const double* next = values_.data();
  for (Eigen::Index p = 0; p < size_; p += kPanelWidth) {
    const Panel panel_p = panel(p, next);
    const Eigen::Index width = panel_p.width, below = panel_p.below.rows();
    // The diagonal block by scalars, each column's sum kept in a register (the block apply
    // below does it by rows, which would need a row temporary per column here).
    const double* d = panel_p.diagonal;
    double* y_panel = y.data() + p;
    const double* x_panel = x.data() + p;
    for (Eigen::Index c = 0; c < width; ++c) {
      double sum = *d++ * x_panel[c];
      for (Eigen::Index i = c + 1; i < width; ++i, ++d) y_panel[i] += *d * x_panel[c], sum += *d * x_panel[i];
      y_panel[c] += sum;
    }
    // Only the last panel can be narrower, and nothing lies below it.
    if (below > 0) apply_full_panel_below(panel_p.below.data(), below, x_panel, x_panel + width, y_panel, y_panel + width);
  }
}

void PackedSymmetric::apply(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  // The panels' products are GEMMs of depth up to t: on one thread, as everywhere a product's
  // rounding must not depend on the thread count (Eigen blocks a threaded GEMM by it).
  const ThreadLimit one_thread(1);
  y.setZero(size_, x.cols());
  const double* next = values_.data();
  for (Eigen::Index p = 0; p < size_; p += kPanelWidth) {
    const Panel panel_p = panel(p, next);
    const Eigen::Index width = panel_p.width, below = panel_p.below.rows();
    const double* d = panel_p.diagonal;
    for (Eigen::Index c = 0; c < width; ++c) {
      y.row(p + c) += *d++ * x.row(p + c);
      for (Eigen::Index i = c + 1; i < width; ++i, ++d) y.row(p + i) += *d * x.row(p + c), y.row(p + c) += *d * x.row(p + i);
    }
    y.bottomRows(below).noalias() += panel_p.below * x.middleRows(p, width);
    y.middleRows(p, width).noalias() += panel_p.below.transpose() * x.bottomRows(below);
  }
}

Eigen::MatrixXd PackedSymmetric::full() const {
  Eigen::MatrixXd S(size_, size_);
  const double* next = values_.data();
  for (Eigen::Index p = 0; p < size_; p += kPanelWidth) {
    const Panel panel_p = panel(p, next);
    const double* d = panel_p.diagonal;
    for (Eigen::Index c = 0; c < panel_p.width; ++c)
      for (Eigen::Index i = c; i < panel_p.width; ++i, ++d) S(p + i, p + c) = S(p + c, p + i) = *d;
    for (Eigen::Index c = 0; c < panel_p.width; ++c)
      for (Eigen::Index i = 0; i < panel_p.below.rows(); ++i)
        S(p + panel_p.width + i, p + c) = S(p + c, p + panel_p.width + i) = panel_p.below(i, c);
  }
  return S;
}

namespace {

/// Where a simplicial factor ordered `present`'s columns last (the interface of
/// InterfaceOrdering::interface_last), they are closed under the elimination tree's
/// ancestors: with A = P'LDL'P (or LL'), L's columns there have rows there only, so L^{-1}'s
/// columns there do too, and A^{-1} on them is W'D_I^{-1}W with W = L_II^{-1}, L_II the
/// (lower triangular) block of L on them: 2/3 t^3 dense flops, no pass over the rest of L.
/// Returns false (S untouched) where a column there has a row elsewhere.
bool inverse_from_interface_block(const cholmod_factor& L, const std::vector<int>& columns,
                                  const std::vector<Eigen::Index>& present, Eigen::MatrixXd& S) {
  const auto n = static_cast<Eigen::Index>(L.n), count = static_cast<Eigen::Index>(present.size());
  const auto* permutation = static_cast<const int*>(L.Perm);
  std::vector<Eigen::Index> position_of(static_cast<size_t>(n), -1);  // factor column -> interface position
  for (Eigen::Index p : present) position_of[static_cast<size_t>(columns[static_cast<size_t>(p)])] = p;
  std::vector<Eigen::Index> local(static_cast<size_t>(n), -1), positions;  // L's column -> block index
  for (Eigen::Index k = 0; k < n; ++k)
    if (position_of[static_cast<size_t>(permutation[k])] >= 0)
      local[static_cast<size_t>(k)] = static_cast<Eigen::Index>(positions.size()), positions.push_back(k);
  if (static_cast<Eigen::Index>(positions.size()) != count) return false;
  const auto* start = static_cast<const int*>(L.p);
  const auto* entries = static_cast<const int*>(L.nz);
  const auto* rows = static_cast<const int*>(L.i);
  const auto* values = static_cast<const double*>(L.x);
  Eigen::MatrixXd block_of_L = Eigen::MatrixXd::Zero(count, count);
  Eigen::VectorXd pivots = Eigen::VectorXd::Ones(count);  // D (LDL'); 1 for LL'
  for (Eigen::Index j = 0; j < count; ++j) {
    const Eigen::Index column = positions[static_cast<size_t>(j)];
    for (int e = start[column]; e < start[column] + entries[column]; ++e) {
      const Eigen::Index row = local[static_cast<size_t>(rows[e])];
      if (row < 0) return false;
      if (row == j && !L.is_ll) pivots[j] = values[e], block_of_L(j, j) = 1;
      else block_of_L(row, j) = values[e];
    }
  }
  // V = D^{-1/2} W, so that A^{-1} on the block is V'V.
  Eigen::MatrixXd V = block_of_L.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(count, count));
  V = pivots.cwiseSqrt().cwiseInverse().asDiagonal() * V;
  Eigen::MatrixXd inverse = Eigen::MatrixXd::Zero(count, count);
  inverse.selfadjointView<Eigen::Lower>().rankUpdate(V.transpose());
  for (Eigen::Index b = 0; b < count; ++b)
    for (Eigen::Index a = b; a < count; ++a) {  // its lower triangle, into S's by interface position
      const Eigen::Index pa = position_of[static_cast<size_t>(permutation[positions[static_cast<size_t>(a)]])];
      const Eigen::Index pb = position_of[static_cast<size_t>(permutation[positions[static_cast<size_t>(b)]])];
      S(std::max(pa, pb), std::min(pa, pb)) = inverse(a, b);
    }
  return true;
}

}  // namespace

PackedSymmetric dense_interface_inverse(const CholmodFactor& factor, const std::vector<int>& columns,
                                        CholmodSolveWorkspace& workspace, Eigen::Index width) {
  const auto t = static_cast<Eigen::Index>(columns.size());
  std::vector<Eigen::Index> present;  // positions k with columns[k] >= 0
  for (Eigen::Index k = 0; k < t; ++k)
    if (columns[static_cast<size_t>(k)] >= 0) present.push_back(k);
  const auto count = static_cast<Eigen::Index>(present.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(t, t);
  if (factor.interface_solves() && !factor.supernodal() && inverse_from_interface_block(*factor.cholmod(), columns, present, S))
    return PackedSymmetric(S);
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

bool explicit_inverse_pays(double packed_bytes, double solve_pass_bytes, bool from_interface_block) {
  return from_interface_block && packed_bytes > 0 && packed_bytes <= solve_pass_bytes;
}

}  // namespace ffeti
