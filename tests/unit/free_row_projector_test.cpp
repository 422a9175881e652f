#include "feti/free_row_projector.h"
#include "factor/upper_gram.h"

#include "random_vector.h"

#include <gtest/gtest.h>

#include <random>

namespace ffeti {
namespace {

using RowMatrix = FreeRowProjector::RowMatrix;

/// A coarse matrix like a floating body's: 6 rows over 40 multipliers, the first 30 free.
/// Row 5's free part is the sum of rows 0..4's (a whole-body rigid mode that gluing cannot
/// hold); its bounded part differs, so G keeps full row rank.
RowMatrix coarse_with_one_body_mode() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(6, 40);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 30; ++j)
      if ((i + j) % 3 == 0) G(i, j) = value(random);
  G.row(5).head(30) = G.topRows(5).leftCols(30).colwise().sum();
  for (int j = 30; j < 40; ++j) G(5, j) = value(random);
  for (int j = 30; j < 34; ++j) G(0, j) = value(random);
  return G.sparseView();
}

/// Either way of factorizing G_F G_F': on its own, or from GG' with the contact modes last.
class FreeRowProjectorLayouts : public ::testing::TestWithParam<GramLayout> {};

TEST_P(FreeRowProjectorLayouts, MapsOntoKerGByMovingFreeMultipliersOnly) {
  const RowMatrix G = coarse_with_one_body_mode();
  const CoarseGram gram(G, 30, upper_gram(G), GetParam());
  const FreeRowProjector T(gram, 30);
  EXPECT_EQ(T.remaining(), 1);  // the body mode
  const Vec x = random_vector(40, 1);
  Vec Tx, TTx, Cx;
  T.apply(x, Tx);
  EXPECT_EQ((Tx - x).tail(10).norm(), 0.0) << "bounded multipliers changed";
  T.apply(Tx, TTx);
  EXPECT_LT((TTx - Tx).norm(), 1e-12 * x.norm()) << "not a projector";
  // G T x lies in the span of the remaining rows only: removing C's part leaves G T x = 0
  // wherever the constraint C T x = 0 holds.
  T.project_remaining_range(Tx, Cx);
  Vec y = Tx - Cx, Ty;  // C y = 0
  T.apply(y, Ty);
  EXPECT_LT((G * Ty).norm(), 1e-12 * x.norm());
}

TEST_P(FreeRowProjectorLayouts, IsTheIdentityOnKerGAndItsTransposeIsConsistent) {
  const RowMatrix G = coarse_with_one_body_mode();
  const CoarseGram gram(G, 30, upper_gram(G), GetParam());
  const FreeRowProjector T(gram, 30);
  // A vector of Ker G: x minus its component in Im G'.
  const Eigen::MatrixXd Gd(G);
  const Vec x0 = random_vector(40, 2);
  const Vec x = x0 - Gd.transpose() * (Gd * Gd.transpose()).llt().solve(Gd * x0);
  Vec Tx;
  T.apply(x, Tx);
  EXPECT_LT((Tx - x).norm(), 1e-12 * x.norm());
  Vec r;
  T.project_remaining_range(x, r);
  EXPECT_LT(r.norm(), 1e-12 * x.norm()) << "C x = 0 on Ker G";
  const Vec a = random_vector(40, 3), b = random_vector(40, 4);
  Vec Ta, Ttb;
  T.apply(a, Ta);
  T.apply_transpose(b, Ttb);
  EXPECT_NEAR(b.dot(Ta), a.dot(Ttb), 1e-12);
}

TEST_P(FreeRowProjectorLayouts, ProjectingOutItsKernelChangesNeitherTNorTheBoundedMultipliers) {
  // A start of the free-rows path is projected this way: T x must not change, nor the
  // bounded part, and what is removed is Ker T = Im E_F G_F' (so G_F y_F = 0 after it).
  const RowMatrix G = coarse_with_one_body_mode();
  const CoarseGram gram(G, 30, upper_gram(G), GetParam());
  const FreeRowProjector T(gram, 30);
  const Vec x = random_vector(40, 6);
  Vec y, yy, Tx, Ty;
  T.project_out_kernel(x, y);
  EXPECT_EQ((y - x).tail(10).norm(), 0.0) << "bounded multipliers changed";
  const RowMatrix G_F = G.leftCols(30);
  EXPECT_LT((G_F * y.head(30)).norm(), 1e-12 * x.norm());
  T.project_out_kernel(y, yy);
  EXPECT_LT((yy - y).norm(), 1e-12 * x.norm()) << "not a projector";
  T.apply(x, Tx);
  T.apply(y, Ty);
  EXPECT_LT((Tx - Ty).norm(), 1e-12 * x.norm()) << "T sees the removed part";
}

TEST_P(FreeRowProjectorLayouts, NothingRemainsWhenTheFreeColumnsSpanTheRowSpace) {
  RowMatrix G = coarse_with_one_body_mode();
  G = G.topRows(5);
  const CoarseGram gram(G, 30, upper_gram(G), GetParam());
  const FreeRowProjector T(gram, 30);
  EXPECT_EQ(T.remaining(), 0);
  Vec Tx;
  T.apply(random_vector(40, 5), Tx);
  EXPECT_LT((G * Tx).norm(), 1e-12);
}

/// P = I - G'(GG')^{-1} G formed densely: the projector the Hessian's P T and T'P spare.
Vec dense_coarse_projection(const RowMatrix& G, const Vec& x) {
  const Eigen::MatrixXd Gd(G);
  return x - Gd.transpose() * (Gd * Gd.transpose()).llt().solve(Gd * x);
}

TEST_P(FreeRowProjectorLayouts, PTAndTPWithoutACoarseSolveMatchTheDenseProjector) {
  for (const int rows : {6, 5}) {  // one floating body mode (k = 1), none (k = 0: P T = T)
    const RowMatrix G = coarse_with_one_body_mode().topRows(rows);
    const CoarseGram gram(G, 30, upper_gram(G), GetParam());
    const FreeRowProjector T(gram, 30);
    EXPECT_EQ(T.remaining(), rows - 5);
    const Vec x = random_vector(40, 8), v = random_vector(40, 9);
    Vec Tx, PTx, TtPv, Ttv;
    T.apply(x, Tx);
    T.apply_projected(x, PTx);
    EXPECT_LT((PTx - dense_coarse_projection(G, Tx)).norm(), 1e-12 * x.norm()) << rows << " rows";
    T.apply_transpose(dense_coarse_projection(G, v), Ttv);
    T.apply_projected_transpose(v, TtPv);
    EXPECT_LT((TtPv - Ttv).norm(), 1e-12 * v.norm()) << rows << " rows";
  }
}

TEST_P(FreeRowProjectorLayouts, RemainingNormIsTheNormOfGTx) {
  // The stopping test's ||G mu|| at every iteration, mu = T x, read as ||C x||.
  for (const int rows : {6, 5}) {
    const RowMatrix G = coarse_with_one_body_mode().topRows(rows);
    const CoarseGram gram(G, 30, upper_gram(G), GetParam());
    const FreeRowProjector T(gram, 30);
    const Vec x = random_vector(40, 10);
    Vec Tx;
    T.apply(x, Tx);
    EXPECT_NEAR(T.remaining_norm(x), (G * Tx).norm(), 1e-12 * x.norm()) << rows << " rows";
    if (rows == 6) EXPECT_GT(T.remaining_norm(x), 1e-3);  // not the trivial 0
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, FreeRowProjectorLayouts,
                         ::testing::Values(GramLayout::separate, GramLayout::contact_last));

}  // namespace
}  // namespace ffeti
