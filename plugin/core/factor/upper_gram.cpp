#include "factor/upper_gram.h"

#include "base/parallel_for.h"

#include <algorithm>
#include <vector>

namespace ffeti {

Eigen::SparseMatrix<double> upper_gram(const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& G) {
  const Eigen::SparseMatrix<double> by_column = G;  // the rows b that meet a column r
  const auto n = static_cast<int>(G.rows());
  std::vector<std::vector<int>> rows(static_cast<size_t>(n));
  std::vector<std::vector<double>> values(static_cast<size_t>(n));
  // A few chunks per thread balance the rows' uneven work; each holds an n-long accumulator.
  const int chunk = std::max(64, (n + 4 * available_threads() - 1) / (4 * available_threads()));
  const int chunks = (n + chunk - 1) / chunk;
  parallel_for_each(chunks, 0, [&](int c) {
    std::vector<double> sum(static_cast<size_t>(n), 0.0);
    std::vector<char> met(static_cast<size_t>(n), 0);
    for (int a = c * chunk; a < std::min(n, (c + 1) * chunk); ++a) {
      std::vector<int>& b_list = rows[static_cast<size_t>(a)];
      for (Eigen::SparseMatrix<double, Eigen::RowMajor, int>::InnerIterator g(G, a); g; ++g)
        for (Eigen::SparseMatrix<double>::InnerIterator h(by_column, g.col()); h && h.row() <= a; ++h) {
          const auto b = static_cast<size_t>(h.row());
          if (!met[b]) met[b] = 1, b_list.push_back(static_cast<int>(b));
          sum[b] += g.value() * h.value();
        }
      std::sort(b_list.begin(), b_list.end());
      for (int b : b_list) {
        values[static_cast<size_t>(a)].push_back(sum[static_cast<size_t>(b)]);
        sum[static_cast<size_t>(b)] = 0, met[static_cast<size_t>(b)] = 0;
      }
    }
  });
  Eigen::SparseMatrix<double> upper(n, n);
  long nonzeros = 0;
  for (const auto& list : rows) nonzeros += static_cast<long>(list.size());
  upper.resizeNonZeros(nonzeros);
  for (int a = 0; a < n; ++a) {
    const int start = upper.outerIndexPtr()[a];
    std::copy(rows[static_cast<size_t>(a)].begin(), rows[static_cast<size_t>(a)].end(), upper.innerIndexPtr() + start);
    std::copy(values[static_cast<size_t>(a)].begin(), values[static_cast<size_t>(a)].end(), upper.valuePtr() + start);
    upper.outerIndexPtr()[a + 1] = start + static_cast<int>(rows[static_cast<size_t>(a)].size());
  }
  return upper;
}

}  // namespace ffeti
