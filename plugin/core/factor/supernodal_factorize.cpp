#include "factor/supernodal_factorize.h"

#include "factor/supernodal_solve.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cstring>
#include <vector>

namespace ffeti {
namespace {

using Block = Eigen::Map<Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

/// The lower triangle of P A P' by columns: (row, value) pairs of permuted column j at
/// start[j] .. start[j+1]-1, rows >= j.
struct PermutedLower {
  std::vector<int> start, row;
  std::vector<double> value;

  PermutedLower(const cholmod_sparse& A, const int* permutation) {
    const auto n = static_cast<int>(A.ncol);
    const auto* p = static_cast<const int*>(A.p);
    const auto* i = static_cast<const int*>(A.i);
    const auto* x = static_cast<const double*>(A.x);
    std::vector<int> inverse(static_cast<size_t>(n));
    for (int k = 0; k < n; ++k) inverse[static_cast<size_t>(permutation[k])] = k;
    start.assign(static_cast<size_t>(n) + 1, 0);
    const auto each_entry = [&](auto&& visit) {
      for (int c = 0; c < n; ++c)
        for (int e = p[c]; e < p[c + 1]; ++e)
          if (i[e] >= c) {
            const int a = inverse[static_cast<size_t>(i[e])], b = inverse[static_cast<size_t>(c)];
            visit(std::max(a, b), std::min(a, b), x[e]);
          }
    };
    each_entry([&](int, int column, double) { ++start[static_cast<size_t>(column) + 1]; });
    for (int c = 0; c < n; ++c) start[static_cast<size_t>(c) + 1] += start[static_cast<size_t>(c)];
    row.resize(static_cast<size_t>(start.back()));
    value.resize(row.size());
    std::vector<int> next(start.begin(), start.end() - 1);
    each_entry([&](int r, int column, double v) {
      const auto at = static_cast<size_t>(next[static_cast<size_t>(column)]++);
      row[at] = r, value[at] = v;
    });
  }
};

}  // namespace

bool supernodal_factorize(const cholmod_sparse& lower, cholmod_factor& L) {
  const auto n = static_cast<int>(L.n);
  const auto nsuper = static_cast<int>(L.nsuper);
  const auto* super = static_cast<const int*>(L.super);
  const auto* pi = static_cast<const int*>(L.pi);
  const auto* px = static_cast<const int*>(L.px);
  const auto* s = static_cast<const int*>(L.s);
  auto* x = static_cast<double*>(L.x);
  std::memset(x, 0, sizeof(double) * L.xsize);
  const PermutedLower A(lower, static_cast<const int*>(L.Perm));

  std::vector<int> owner(static_cast<size_t>(n));  // the supernode of each column
  for (int k = 0; k < nsuper; ++k) std::fill(owner.begin() + super[k], owner.begin() + super[k + 1], k);
  // Supernodes waiting to update a later one: a list per supernode (head, next), and in
  // each waiting supernode the position of its first row not yet used (`unused`).
  std::vector<int> head(static_cast<size_t>(nsuper), -1), next(static_cast<size_t>(nsuper), -1),
      unused(static_cast<size_t>(nsuper), 0);
  const auto wait_for = [&](int d, int position) {
    unused[static_cast<size_t>(d)] = position;
    const int target = owner[static_cast<size_t>(s[pi[d] + position])];
    next[static_cast<size_t>(d)] = head[static_cast<size_t>(target)];
    head[static_cast<size_t>(target)] = d;
  };
  std::vector<int> position_in(static_cast<size_t>(n), -1);  // a row's place in the current supernode
  Eigen::MatrixXd scratch;  // the updates' products (scratch_block)

  for (int j = 0; j < nsuper; ++j) {
    const int first = super[j], width = super[j + 1] - first, height = pi[j + 1] - pi[j];
    const int* rows = s + pi[j];
    Block Lj(x + px[j], height, width, Eigen::OuterStride<>(height));
    for (int i = 0; i < height; ++i) position_in[static_cast<size_t>(rows[i])] = i;
    for (int c = first; c < first + width; ++c)
      for (int e = A.start[static_cast<size_t>(c)]; e < A.start[static_cast<size_t>(c) + 1]; ++e)
        Lj(position_in[static_cast<size_t>(A.row[static_cast<size_t>(e)])], c - first) += A.value[static_cast<size_t>(e)];

    for (int d = head[static_cast<size_t>(j)]; d != -1;) {
      const int following = next[static_cast<size_t>(d)];
      const int d_height = pi[d + 1] - pi[d], d_width = super[d + 1] - super[d];
      const int* d_rows = s + pi[d];
      const int p = unused[static_cast<size_t>(d)];
      int q = p;
      while (q < d_height && d_rows[q] < first + width) ++q;  // rows p..q-1: in j's columns
      const int m = d_height - p, m1 = q - p;
      const Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> Ld(x + px[d] + p, m, d_width,
                                                                         Eigen::OuterStride<>(d_height));
      auto update = scratch_block(scratch, m, m1);
      update.noalias() = Ld * Ld.topRows(m1).transpose();
      for (int k = 0; k < m1; ++k) {
        const int column = d_rows[p + k] - first;
        for (int i = k; i < m; ++i) Lj(position_in[static_cast<size_t>(d_rows[p + i])], column) -= update(i, k);
      }
      if (q < d_height) wait_for(d, q);
      d = following;
    }

    auto diagonal = Lj.topRows(width);
    // Eigen's blocked in-place Cholesky, the kernel behind Eigen::LLT, called directly: it
    // works on this strided block of L without a copy and says whether a pivot failed.
    if (Eigen::internal::llt_inplace<double, Eigen::Lower>::blocked(diagonal) >= 0) return false;
    if (height > width) {
      auto below = Lj.bottomRows(height - width);
      diagonal.triangularView<Eigen::Lower>().transpose().solveInPlace<Eigen::OnTheRight>(below);  // below L^{-T}
      wait_for(j, width);
    }
  }
  return true;
}

}  // namespace ffeti
