// CHOLMOD factors: the automatic kind follows the measured switch, and an analysis shared
// between matrices of one pattern gives bitwise the factor of their own analyses.
#include "factor/cholmod_analysis.h"
#include "factor/cholmod_factor.h"
#include "factor/shared_analyses.h"
#include "solid_block.h"

#include <gtest/gtest.h>

namespace ffeti {
namespace {

TEST(CholmodFactor, AutomaticKindFollowsTheSwitchOnFlopsPerFactorNonzero) {
  int supernodal = 0, simplicial = 0;
  for (int cells : {2, 4, 8}) {
    const SparseMatrix K = clamped_block_stiffness(cells);
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
  const SparseMatrix first = clamped_block_stiffness(4), translated = clamped_block_stiffness(4, 5.0);
  const SparseMatrix finer = clamped_block_stiffness(5);
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


/// A P1-like stiffness on a nodes x nodes grid cut into triangles by one diagonal per cell
/// (the model problem's pattern: each node coupled to six neighbours), plus `shift` on the
/// diagonal (regular), and its boundary nodes: a 2D subdomain and its interface.
SparseMatrix grid_laplacian(int nodes, double shift, std::vector<int>* boundary) {
  std::vector<Eigen::Triplet<double, int>> entries;
  const auto id = [nodes](int i, int j) { return i * nodes + j; };
  for (int i = 0; i < nodes; ++i)
    for (int j = 0; j < nodes; ++j) {
      entries.emplace_back(id(i, j), id(i, j), 5.0 + shift);
      const auto couple = [&](int a, int b, double v) { entries.emplace_back(a, b, v), entries.emplace_back(b, a, v); };
      if (i + 1 < nodes) couple(id(i + 1, j), id(i, j), -1.0);
      if (j + 1 < nodes) couple(id(i, j + 1), id(i, j), -1.0);
      if (i + 1 < nodes && j + 1 < nodes) couple(id(i + 1, j + 1), id(i, j), -0.5);
      if (i == 0 || j == 0 || i == nodes - 1 || j == nodes - 1) boundary->push_back(id(i, j));
    }
  SparseMatrix K(nodes * nodes, nodes * nodes);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  return K;
}

/// Boundary dofs of an eliminated 3D block: those on its four lateral faces (any component).
std::vector<int> block_faces(const SparseMatrix& K, int cells) {
  std::vector<int> faces;
  const int side = cells + 1;
  for (int dof = 0; dof < K.rows(); ++dof) {
    const int node = dof / 3, i = node % side, j = (node / side) % side;
    if (i == 0 || j == 0 || i == cells || j == cells) faces.push_back(dof);
  }
  return faces;
}

/// x(interface) of a solve on the interface against the whole solve of the same right-hand side.
double interface_solve_error(const CholmodFactor& factor, const SparseMatrix& K, const std::vector<int>& interface) {
  const auto t = static_cast<Eigen::Index>(interface.size());
  const Vec b_on = Vec::LinSpaced(t, -1, 2);
  Vec b = Vec::Zero(K.rows()), x, x_on;
  for (Eigen::Index k = 0; k < t; ++k) b[interface[static_cast<size_t>(k)]] = b_on[k];
  factor.solve(b, x);
  factor.solve_on_interface(b_on, x_on);
  double error = 0;
  for (Eigen::Index k = 0; k < t; ++k) error = std::max(error, std::abs(x_on[k] - x[interface[static_cast<size_t>(k)]]));
  return error / x.lpNorm<Eigen::Infinity>();
}

TEST(CholmodFactor, SolvesOnTheInterfaceAloneWhereItIsOrderedLast) {
  std::vector<int> boundary;
  const SparseMatrix K = grid_laplacian(65, 0.01, &boundary);  // the seed's subdomain: H/h = 64
  CholmodFactor fill(FactorKind::simplicial, InterfaceOrdering::fill_reducing);
  ASSERT_LT(fill.factorize(K, nullptr, boundary), 0);
  EXPECT_FALSE(fill.interface_solves());
  CholmodFactor automatic(FactorKind::automatic, InterfaceOrdering::automatic);
  ASSERT_LT(automatic.factorize(K, nullptr, boundary), 0);
  ASSERT_TRUE(automatic.interface_solves());  // a 2D grid: the boundary block is small against L
  EXPECT_LT(interface_solve_error(automatic, K, boundary), 1e-13);
  // The whole solve still holds on the reordered factor.
  const Vec b = Vec::LinSpaced(K.rows(), -1, 2);
  Vec x;
  automatic.solve(b, x);
  EXPECT_LT((K * x - b).norm(), 1e-12 * b.norm());
  // The price: a larger factor than the fill-reducing one (the interface's Schur complement).
  EXPECT_GT(automatic.factor_nonzeros(), fill.factor_nonzeros());
}

TEST(CholmodFactor, AutomaticKeepsTheFillReducingOrderingWhereTheInterfaceBlockIsLarge) {
  // A 3D elastic block with its lateral faces as interface: their dense block would be more
  // than half of the fill-reducing factor.
  const int cells = 4;
  const SparseMatrix K = clamped_block_stiffness(cells);
  const std::vector<int> faces = block_faces(K, cells);
  CholmodFactor automatic(FactorKind::simplicial, InterfaceOrdering::automatic);
  ASSERT_LT(automatic.factorize(K, nullptr, faces), 0);
  EXPECT_FALSE(automatic.interface_solves());
  CholmodFactor forced(FactorKind::simplicial, InterfaceOrdering::interface_last);
  ASSERT_LT(forced.factorize(K, nullptr, faces), 0);
  ASSERT_TRUE(forced.interface_solves());
  EXPECT_LT(interface_solve_error(forced, K, faces), 1e-12);
  // A supernodal factor keeps the fill-reducing ordering whatever is asked.
  CholmodFactor supernodal(FactorKind::supernodal, InterfaceOrdering::interface_last);
  ASSERT_LT(supernodal.factorize(K, nullptr, faces), 0);
  EXPECT_FALSE(supernodal.interface_solves());
}

TEST(CholmodFactor, TheInterfaceOrderingPaysWhereAPassSkipsMuchOfTheFactorForFewFlops) {
  // Figures of real subdomains (fill-reducing factor entries, entries a pass of F skips with
  // the interface last, the factorization's extra flops).
  EXPECT_TRUE(interface_ordering_pays(99325, 91069, 5.88e6));   // model problem, H/h = 64
  EXPECT_TRUE(interface_ordering_pays(99325, 80986, 9.95e6));   // the same with a contact side
  EXPECT_FALSE(interface_ordering_pays(12495, 113, 0));         // large contact zone: 92 % interface
  EXPECT_FALSE(interface_ordering_pays(20852, 81, 0));
  EXPECT_FALSE(interface_ordering_pays(1000, 600, 390 * 600));  // 3D box: too many flops per saved entry
  EXPECT_FALSE(interface_ordering_pays(1000, 0, 0));
  EXPECT_FALSE(interface_ordering_pays(1000, -50, 0));          // CAMD's factor larger
}

TEST(CholmodFactor, SharedAnalysisKeepsTheInterfaceOrdering) {
  std::vector<int> boundary, same;
  const SparseMatrix K = grid_laplacian(65, 0.01, &boundary);
  const SparseMatrix K2 = 2.0 * grid_laplacian(65, 0.02, &same);
  SharedAnalyses shared;
  CholmodFactor first(FactorKind::simplicial, InterfaceOrdering::automatic);
  CholmodFactor second(FactorKind::simplicial, InterfaceOrdering::automatic);
  CholmodFactor other_interface(FactorKind::simplicial, InterfaceOrdering::automatic);
  ASSERT_LT(first.factorize(K, &shared, boundary), 0);
  ASSERT_LT(second.factorize(K2, &shared, boundary), 0);
  const std::vector<int> half(boundary.begin(), boundary.begin() + static_cast<long>(boundary.size() / 2));
  ASSERT_LT(other_interface.factorize(K, &shared, half), 0);
  EXPECT_EQ(shared.reuses(), 1);  // the interface is part of the key
  EXPECT_TRUE(second.interface_solves());
  EXPECT_LT(interface_solve_error(second, K2, boundary), 1e-13);
  EXPECT_LT(interface_solve_error(other_interface, K, half), 1e-13);
}

TEST(CholmodFactor, DistinctWorkspacesSolveOneFactorFromSeveralThreadsAtOnce) {
  std::vector<int> boundary;
  const SparseMatrix K = grid_laplacian(65, 0.01, &boundary);
  CholmodFactor factor(FactorKind::simplicial, InterfaceOrdering::interface_last);
  ASSERT_LT(factor.factorize(K, nullptr, boundary), 0);
  ASSERT_TRUE(factor.interface_solves());
  constexpr int kRightHandSides = 16;
  std::vector<Vec> b(kRightHandSides), b_on(kRightHandSides);
  for (int k = 0; k < kRightHandSides; ++k) {
    b[k] = Vec::LinSpaced(K.rows(), -1.0 - k, 2.0 + k);
    b_on[k] = Vec::LinSpaced(static_cast<Eigen::Index>(boundary.size()), 1.0, -1.0 - k);
  }
  // The concurrent solves come first, right after the factorization: a solve that wrote
  // into the factor on its first call (CHOLMOD's subset solve builds L's inverse
  // permutation) would race here.
  std::vector<Vec> x(kRightHandSides), x_on(kRightHandSides);
#pragma omp parallel num_threads(2)
  {
    CholmodSolveWorkspace workspace;  // one per thread, the factor shared
#pragma omp for schedule(static, 1)
    for (int k = 0; k < kRightHandSides; ++k) {
      factor.solve_on_interface(b_on[k], x_on[k], workspace);
      factor.solve(b[k], x[k], workspace);
    }
  }
  for (int k = 0; k < kRightHandSides; ++k) {
    Vec expected, expected_on;
    factor.solve(b[k], expected);
    factor.solve_on_interface(b_on[k], expected_on);
    EXPECT_EQ(x[k], expected) << "right-hand side " << k;  // bitwise: the same operations
    EXPECT_EQ(x_on[k], expected_on) << "right-hand side " << k;
  }
}

TEST(CholmodFactor, SupernodalSolvesMatchTheSimplicialFactorsSolves) {
  // The supernodal factor (supernodal_factorize.cpp) and its triangles (supernodal_solve.cpp)
  // run through Eigen, the simplicial one through CHOLMOD: two factorizations and two solve
  // codes of one matrix.
  const SparseMatrix K = clamped_block_stiffness(6);
  CholmodFactor supernodal(FactorKind::supernodal), simplicial(FactorKind::simplicial);
  ASSERT_LT(supernodal.factorize(K), 0);
  ASSERT_LT(simplicial.factorize(K), 0);
  ASSERT_TRUE(supernodal.supernodal());
  ASSERT_FALSE(simplicial.supernodal());
  Eigen::MatrixXd B(K.rows(), 5);
  for (Eigen::Index j = 0; j < B.cols(); ++j) B.col(j) = Vec::LinSpaced(K.rows(), -1.0 - double(j), 2.0 + double(j) * j);
  Vec x, expected;
  supernodal.solve(Vec(B.col(0)), x);
  simplicial.solve(Vec(B.col(0)), expected);
  EXPECT_LT((x - expected).norm(), 1e-11 * expected.norm());
  EXPECT_LT((K * x - B.col(0)).norm(), 1e-10 * B.col(0).norm());
  Eigen::MatrixXd X, expected_block;
  supernodal.solve(B, X);
  simplicial.solve(B, expected_block);
  EXPECT_LT((X - expected_block).norm(), 1e-11 * expected_block.norm());
  for (Eigen::Index j = 0; j < B.cols(); ++j) {  // a column of the block (Eigen's GEMM) as the column alone (GEMV)
    Vec column;
    supernodal.solve(Vec(B.col(j)), column);
    EXPECT_LT((X.col(j) - column).norm(), 1e-13 * column.norm()) << "column " << j;
  }
}

TEST(CholmodFactor, SupernodalFactorizationRefusesAnIndefiniteMatrixAndRefactorizesAfterwards) {
  // The supernodal values come from supernodal_factorize.cpp; an indefinite block there hands
  // the matrix to CHOLMOD's own factorization, which names the column.
  const SparseMatrix K = clamped_block_stiffness(6);
  SparseMatrix indefinite = K;
  const int middle = static_cast<int>(K.rows() / 2);
  indefinite.coeffRef(middle, middle) = -indefinite.coeff(middle, middle);
  CholmodFactor factor(FactorKind::supernodal);
  EXPECT_GE(factor.factorize(indefinite), 0);
  ASSERT_LT(factor.factorize(K), 0);  // the same analysis, values written again
  ASSERT_TRUE(factor.supernodal());
  const Vec b = Vec::LinSpaced(K.rows(), -2, 1);
  Vec x;
  factor.solve(b, x);
  EXPECT_LT((K * x - b).norm(), 1e-10 * b.norm());
}

TEST(CholmodFactor, SupernodalSolvesFromSeveralThreadsAtOnceWithDistinctWorkspaces) {
  const SparseMatrix K = clamped_block_stiffness(6);
  CholmodFactor factor(FactorKind::supernodal);
  ASSERT_LT(factor.factorize(K), 0);
  ASSERT_TRUE(factor.supernodal());
  constexpr int kRightHandSides = 16;
  std::vector<Vec> b(kRightHandSides), x(kRightHandSides);
  for (int k = 0; k < kRightHandSides; ++k) b[k] = Vec::LinSpaced(K.rows(), -1.0 - k, 2.0 + k);
#pragma omp parallel num_threads(2)
  {
    CholmodSolveWorkspace workspace;  // the supernodal solve's permuted columns and scratch live here
#pragma omp for schedule(static, 1)
    for (int k = 0; k < kRightHandSides; ++k) factor.solve(b[k], x[k], workspace);
  }
  for (int k = 0; k < kRightHandSides; ++k) {
    Vec expected;
    factor.solve(b[k], expected);
    EXPECT_EQ(x[k], expected) << "right-hand side " << k;
  }
}

TEST(CholmodFactor, SupernodalForwardAndBackwardHalvesComposeToTheSolve) {
  const SparseMatrix K = clamped_block_stiffness(6);
  CholmodFactor factor(FactorKind::supernodal);
  ASSERT_LT(factor.factorize(K), 0);
  ASSERT_TRUE(factor.supernodal());
  const Vec b = Vec::LinSpaced(K.rows(), 3, -1);
  Vec y, x, whole;
  factor.forward(b, y);
  factor.backward(y, x);
  factor.solve(b, whole);
  EXPECT_LT((x - whole).norm(), 1e-12 * whole.norm());
  // y = L^{-1} P b: ||y||^2 = b' A^{-1} b, whatever L's layout.
  EXPECT_NEAR(y.squaredNorm(), b.dot(whole), 1e-10 * std::abs(b.dot(whole)));
}

TEST(CholmodFactor, FactorizationsOnSeveralThreadsAtOnceGiveTheSerialFactorBitwise) {
  // Large enough for CHOLMOD to try METIS beside AMD, whose random generator is global:
  // concurrent analyses drew from one stream and ordered (hence rounded) differently from
  // run to run.
  const SparseMatrix K = clamped_block_stiffness(12);
  const Vec b = Vec::LinSpaced(K.rows(), -1, 2);
  Vec serial;
  {
    CholmodFactor factor(FactorKind::supernodal);
    ASSERT_LT(factor.factorize(K), 0);
    factor.solve(b, serial);
  }
  constexpr int kFactors = 8;
  std::vector<Vec> concurrent(kFactors);
#pragma omp parallel for num_threads(4) schedule(static, 1)
  for (int k = 0; k < kFactors; ++k) {
    CholmodFactor factor(FactorKind::supernodal);
    if (factor.factorize(K) < 0) factor.solve(b, concurrent[static_cast<size_t>(k)]);
  }
  for (int k = 0; k < kFactors; ++k) EXPECT_TRUE(concurrent[static_cast<size_t>(k)] == serial) << "factor " << k;
}

}  // namespace
}  // namespace ffeti
