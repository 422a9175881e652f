// Symmetric matrices held as their lower triangle, as CHOLMOD reads them (stype -1). After
// its input checks the core keeps only K_s's lower triangle (half the entries of full
// storage) and every reader takes K_s as selfadjointView<Eigen::Lower>(): a full matrix
// given by a test reads the same.
#pragma once

#include "base/linear_algebra.h"

#include <vector>

namespace ffeti {

/// The lower triangle of K (entries on and below the diagonal), compressed.
SparseMatrix lower_triangle(const SparseMatrix& K);

/// The lower triangle of K restricted to the rows and columns `kept` (ascending),
/// renumbered 0..kept.size()-1 and compressed: the lower triangle of the symmetric block.
SparseMatrix lower_block(const SparseMatrix& K, const std::vector<int>& kept);

}  // namespace ffeti
