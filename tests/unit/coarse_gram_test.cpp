#include "feti/coarse_gram.h"
#include "factor/upper_gram.h"

#include "random_vector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace ffeti {
namespace {

using RowMatrix = CoarseGram::RowMatrix;

/// A coarse matrix shaped like a decomposition's: 40 rigid modes over 120 multipliers, the
/// first 90 free (gluing, each between neighbouring modes), the last 30 bounded (contact) and
/// meeting modes 28..39 only. Mode 39's free part is the sum of modes 30..38's: without the
/// contact columns G_F G_F' is singular (a floating body's rigid mode).
RowMatrix decomposition_like_coarse_matrix() {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(40, 120);
  for (int j = 0; j < 90; ++j) {
    const int mode = (j * 7) % 39;
    G(mode, j) = value(random);
    G((mode + 1) % 39, j) = value(random);
  }
  G.row(39).head(90) = G.middleRows(30, 9).leftCols(90).colwise().sum();
  for (int j = 90; j < 120; ++j) {
    G(28 + (j % 12), j) = value(random);
    G(28 + ((j + 5) % 12), j) = value(random);
  }
  return G.sparseView();
}

/// Kept columns: every free one, and each bounded one with probability `share`.
Vec kept_columns(double share, unsigned seed) {
  std::mt19937 random(seed);
  std::bernoulli_distribution keep(share);
  Vec kept = Vec::Ones(120);
  for (int j = 90; j < 120; ++j) kept[j] = keep(random) ? 1.0 : 0.0;
  return kept;
}

class CoarseGramLayouts : public ::testing::TestWithParam<GramLayout> {};

TEST_P(CoarseGramLayouts, SolvesEachGramMatrixOverFewerColumnsAndFindsItsNullSpace) {
  const RowMatrix G = decomposition_like_coarse_matrix();
  const CoarseGram gram(G, 90, upper_gram(G), GetParam());
  ASSERT_TRUE(gram.factored());
  EXPECT_EQ(gram.contact_last(), GetParam() == GramLayout::contact_last);
  const Eigen::MatrixXd Gd(G);
  Vec x;
  gram.solve(Gd * random_vector(120, 1), x);
  EXPECT_LT((Gd * Gd.transpose() * x - Gd * random_vector(120, 1)).norm(), 1e-10 * x.norm());
  int singular = 0;
  for (const RankDecision rank : {RankDecision::search, RankDecision::factor_first}) {
    for (const auto& [share, seed] : std::vector<std::pair<double, unsigned>>{{1.0, 2}, {0.5, 3}, {0.2, 4}, {0.0, 5}}) {
      const Vec kept = kept_columns(share, seed);
      const Eigen::MatrixXd GX = Gd * kept.asDiagonal();
      const Eigen::MatrixXd A = GX * GX.transpose();
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(A);
      const Eigen::Index nullity = (spectrum.eigenvalues().array() < 1e-10 * spectrum.eigenvalues().maxCoeff()).count();
      const std::unique_ptr<PartialGram> part = gram.over_columns(kept, rank);
      const Eigen::MatrixXd& W = part->kernel();
      ASSERT_EQ(W.cols(), nullity) << "share " << share;
      singular += nullity > 0;
      if (nullity > 0) {
        EXPECT_LT((A * W).norm(), 1e-10 * A.norm());
        EXPECT_LT((W.transpose() * W - Eigen::MatrixXd::Identity(nullity, nullity)).norm(), 1e-12);
      }
      // y in the range of A: the solution orthogonal to Ker A is A^+ y, the least-norm one.
      const Vec y = A * random_vector(40, seed + 10);
      const Vec solution = part->solve(y);
      const Vec least_norm = spectrum.eigenvectors() *
                             (spectrum.eigenvalues().array() > 1e-10 * spectrum.eigenvalues().maxCoeff())
                                 .select(spectrum.eigenvalues().cwiseInverse(), 0.0)
                                 .matrix()
                                 .asDiagonal() *
                             spectrum.eigenvectors().transpose() * y;
      EXPECT_LT((solution - least_norm).norm(), 1e-9 * least_norm.norm()) << "share " << share;
    }
  }
  EXPECT_GE(singular, 2) << "the test should meet a singular Gram matrix";
  EXPECT_LE(singular, 6) << "and regular ones";
}

INSTANTIATE_TEST_SUITE_P(Layouts, CoarseGramLayouts, ::testing::Values(GramLayout::separate, GramLayout::contact_last));

TEST(CholmodFactorWithLast, ItsTrailingBlockFactorsTheSchurComplementOnTheLastColumns) {
  const RowMatrix G = decomposition_like_coarse_matrix();
  const SparseMatrix A = Eigen::SparseMatrix<double>(upper_gram(G).selfadjointView<Eigen::Upper>());
  const std::vector<int> last = {35, 28, 39, 31, 30};  // in this order
  CholmodFactor factor;
  ASSERT_LT(factor.factorize_with_last(A, last), 0);
  std::vector<int> first;
  for (int j = 0; j < 40; ++j)
    if (std::find(last.begin(), last.end(), j) == last.end()) first.push_back(j);
  const Eigen::MatrixXd Ad(A);
  const auto block = [&](const std::vector<int>& rows, const std::vector<int>& columns) {
    Eigen::MatrixXd b(rows.size(), columns.size());
    for (size_t i = 0; i < rows.size(); ++i)
      for (size_t j = 0; j < columns.size(); ++j) b(i, j) = Ad(rows[i], columns[j]);
    return b;
  };
  const Eigen::MatrixXd schur =
      block(last, last) - block(last, first) * block(first, first).llt().solve(block(first, last));
  const Eigen::MatrixXd L = factor.trailing_block();
  EXPECT_TRUE(L.isLowerTriangular());
  EXPECT_LT((L * L.transpose() - schur).norm(), 1e-10 * schur.norm());
  // The halves of a solve make a solve.
  const Vec b = random_vector(40, 9);
  Vec y, x;
  factor.forward(b, y);
  factor.backward(y, x);
  EXPECT_LT((Ad * x - b).norm(), 1e-10 * b.norm());
}

}  // namespace
}  // namespace ffeti
