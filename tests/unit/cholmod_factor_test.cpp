// CHOLMOD factors: the automatic kind follows the measured switch, and an analysis shared
// between matrices of one pattern gives bitwise the factor of their own analyses.
#include "feti/cholmod_factor.h"
#include "feti/dirichlet.h"
#include "feti/shared_analyses.h"
#include "solid_block.h"

#include <gtest/gtest.h>

namespace ffeti {
namespace {

/// A regular 3D elastic block (its top face's dofs eliminated) of cells^3 cubes at x0.
SparseMatrix block(int cells, double x0 = 0) {
  const SubdomainInput s = solid_block(x0, {1, 1, 1}, {cells, cells, cells}, {0, 0, 0});
  SparseMatrix K = eliminate_dirichlet(s.K, s.dirichlet_dofs);
  K.makeCompressed();
  return K;
}

TEST(CholmodFactor, AutomaticKindFollowsTheSwitchOnFlopsPerFactorNonzero) {
  int supernodal = 0, simplicial = 0;
  for (int cells : {2, 4, 8}) {
    const SparseMatrix K = block(cells);
    CholmodFactor factor(FactorKind::automatic);
    ASSERT_LT(factor.factorize(K), 0);
    const double density = factor.analysis_flops() / factor.analysis_nonzeros();
    EXPECT_EQ(factor.supernodal(), density >= supernodal_switch()) << "cells " << cells << ", flops/nnz " << density;
    (factor.supernodal() ? supernodal : simplicial) += 1;
    const Vec b = Vec::LinSpaced(K.rows(), -1, 2);
    Vec x;
    factor.solve(b, x);
    EXPECT_LT((K * x - b).norm(), 1e-10 * b.norm());
  }
  // Both sides of the switch were seen, or the test says nothing about the choice.
  EXPECT_GT(simplicial, 0);
  EXPECT_GT(supernodal, 0);
}

TEST(CholmodFactor, SharedAnalysisGivesBitwiseTheSameFactor) {
  const SparseMatrix first = block(4), translated = block(4, 5.0), finer = block(5);
  const Vec b = Vec::LinSpaced(first.rows(), -1, 2);
  for (FactorKind kind : {FactorKind::simplicial, FactorKind::supernodal}) {
    SharedAnalyses shared;
    CholmodFactor a(kind), b_shared(kind), b_own(kind), c(kind);
    ASSERT_LT(a.factorize(first, &shared), 0);
    ASSERT_LT(b_shared.factorize(translated, &shared), 0);
    ASSERT_LT(b_own.factorize(translated), 0);
    ASSERT_LT(c.factorize(finer, &shared), 0);
    EXPECT_EQ(shared.analyses(), 2);  // first and finer
    EXPECT_EQ(shared.reuses(), 1);    // translated: the same pattern as first
    Vec x_shared, x_own;
    b_shared.solve(b, x_shared);
    b_own.solve(b, x_own);
    EXPECT_TRUE(x_shared == x_own);
    EXPECT_EQ(b_shared.factor_nonzeros(), b_own.factor_nonzeros());
    EXPECT_EQ(b_shared.analysis_flops(), b_own.analysis_flops());
  }
}

}  // namespace
}  // namespace ffeti
