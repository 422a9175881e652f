#include "factor/lower_triangle.h"

namespace ffeti {

SparseMatrix lower_triangle(const SparseMatrix& K) {
  SparseMatrix lower = K.triangularView<Eigen::Lower>();
  lower.makeCompressed();
  return lower;
}

SparseMatrix lower_block(const SparseMatrix& K, const std::vector<int>& kept) {
  std::vector<int> position(static_cast<size_t>(K.rows()), -1);
  for (size_t k = 0; k < kept.size(); ++k) position[static_cast<size_t>(kept[k])] = static_cast<int>(k);
  const auto m = static_cast<Eigen::Index>(kept.size());
  // The entries of kept rows on or below the diagonal (the upper triangle, where K is given
  // in full, is skipped): counted first, so that a block kept for long holds no spare room.
  const auto kept_entry = [&](const SparseMatrix::InnerIterator& it, int column) {
    return it.row() >= column && position[static_cast<size_t>(it.row())] >= 0;
  };
  Eigen::Index entries = 0;
  for (int column : kept)
    for (SparseMatrix::InnerIterator it(K, column); it; ++it) entries += kept_entry(it, column);
  SparseMatrix block(m, m);
  block.reserve(entries);
  // `kept` ascends, so the renumbering keeps each column's rows sorted and the lower
  // triangle lower: entries are appended in order.
  for (Eigen::Index j = 0; j < m; ++j) {
    block.startVec(j);
    const int column = kept[static_cast<size_t>(j)];
    for (SparseMatrix::InnerIterator it(K, column); it; ++it)
      if (kept_entry(it, column)) block.insertBack(position[static_cast<size_t>(it.row())], j) = it.value();
  }
  block.finalize();
  block.makeCompressed();  // CHOLMOD reads compressed columns
  return block;
}

}  // namespace ffeti
