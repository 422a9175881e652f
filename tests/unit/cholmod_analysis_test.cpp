// The analysis choices of factor/cholmod_analysis: the ordering that stores the fewest
// values, and supernodes without the padding of relaxed amalgamation.
#include "factor/cholmod_analysis.h"
#include "factor/cholmod_factor.h"
#include "solid_block.h"

#include <Eigen/CholmodSupport>
#include <gtest/gtest.h>

namespace ffeti {
namespace {

/// What a supernodal analysis of A stores and counts, under CHOLMOD's defaults or the
/// project's choices, with CHOLMOD's ordering or the one given.
struct Analysis {
  double values = -1, flops = -1, nonzeros = -1;  ///< L->xsize, Common->fl, Common->lnz
};
Analysis analysis_of(const SparseMatrix& A, bool project_choices, int ordering = -1) {
  cholmod_common common;
  cholmod_start(&common);
  common.print = 0;
  common.supernodal = CHOLMOD_SUPERNODAL;
  if (project_choices) set_analysis_choices(common);
  if (ordering >= 0) common.nmethods = 1, common.method[0].ordering = ordering;
  cholmod_sparse view = Eigen::viewAsCholmod(A.selfadjointView<Eigen::Lower>());
  cholmod_factor* L = cholmod_analyze(&view, &common);
  Analysis result;
  if (L) result = {static_cast<double>(L->xsize), common.fl, common.lnz};
  cholmod_free_factor(&L, &common);
  cholmod_finish(&common);
  return result;
}

TEST(CholmodAnalysis, SupernodesHoldFewerValuesThanUnderCholmodsDefaults) {
  const SparseMatrix K = clamped_block_stiffness(10);
  const double defaults = analysis_of(K, false, CHOLMOD_AMD).values, ours = analysis_of(K, true, CHOLMOD_AMD).values;
  ASSERT_GT(ours, 0);
  EXPECT_LT(ours, 0.97 * defaults) << "the relaxed amalgamation's padding is gone";
}

TEST(CholmodAnalysis, ASupernodalFactorTakesTheOrderingThatStoresFewerValues) {
  const SparseMatrix K = clamped_block_stiffness(10);
  const Analysis amd = analysis_of(K, true, CHOLMOD_AMD), metis = analysis_of(K, true, CHOLMOD_METIS);
  ASSERT_GT(amd.values, 0);
  ASSERT_LT(metis.values, amd.values) << "METIS must win here, or the test cannot tell that it was tried";
  CholmodFactor factor(FactorKind::supernodal);
  ASSERT_LT(factor.factorize(K), 0);
  ASSERT_TRUE(factor.supernodal());
  ASSERT_GE(factor.analysis_flops(), kLeastFlopsPerColumnForMetis * static_cast<double>(K.rows()))
      << "above the threshold";
  EXPECT_EQ(static_cast<double>(factor.cholmod()->xsize), metis.values);
  // CHOLMOD's statistics are those of the analysis kept, not of CHOLMOD's own first choice.
  EXPECT_EQ(factor.analysis_flops(), metis.flops);
  EXPECT_EQ(factor.analysis_nonzeros(), metis.nonzeros);
  const Vec b = Vec::LinSpaced(K.rows(), -1, 2);
  Vec x;
  factor.solve(b, x);
  EXPECT_LT((K * x - b).norm(), 1e-10 * b.norm());
}

/// The 5-point Laplacian of a cells x cells grid plus the identity: a 2D pattern, few flops
/// per column.
SparseMatrix grid_laplacian(int cells) {
  std::vector<Eigen::Triplet<double>> entries;
  const auto id = [cells](int i, int j) { return i * cells + j; };
  for (int i = 0; i < cells; ++i)
    for (int j = 0; j < cells; ++j) {
      entries.emplace_back(id(i, j), id(i, j), 5.0);
      for (const int neighbour : {i + 1 < cells ? id(i + 1, j) : -1, j + 1 < cells ? id(i, j + 1) : -1})
        if (neighbour >= 0)
          entries.emplace_back(id(i, j), neighbour, -1.0), entries.emplace_back(neighbour, id(i, j), -1.0);
    }
  SparseMatrix A(cells * cells, cells * cells);
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  return A;
}

TEST(CholmodAnalysis, AFactorOfFewFlopsPerColumnKeepsCholmodsOrderingWithoutTryingMetis) {
  const SparseMatrix A = grid_laplacian(120);
  const Analysis amd = analysis_of(A, true, CHOLMOD_AMD), metis = analysis_of(A, true, CHOLMOD_METIS);
  ASSERT_GT(amd.values, 0);
  ASSERT_GT(metis.values, 0);
  ASSERT_LT(metis.values, amd.values) << "METIS would store fewer here: the test tells whether it was tried";
  CholmodFactor factor(FactorKind::supernodal);
  ASSERT_LT(factor.factorize(A), 0);
  ASSERT_TRUE(factor.supernodal());
  ASSERT_LT(factor.analysis_flops(), kLeastFlopsPerColumnForMetis * static_cast<double>(A.rows()))
      << "below the threshold";
  EXPECT_EQ(static_cast<double>(factor.cholmod()->xsize), amd.values);
  EXPECT_EQ(factor.analysis_nonzeros(), amd.nonzeros);
}

}  // namespace
}  // namespace ffeti
