// The null space of G_F G_F' by the dense rank-revealing factorization and by sparse block
// inverse iteration: chains of subdomains glued end to end (weighted rows), some bodies held
// by a Dirichlet row; the null space is one constant vector per free body, known here.
#include "factor/semidefinite_kernel.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <random>
#include <vector>

namespace ffeti {
namespace {

struct Chains {
  SparseMatrix A;            // G_F G_F'
  Eigen::MatrixXd expected;  // orthonormal basis of the known null space
};

/// `bodies` chains of `length` subdomains; every third body has a Dirichlet row at its start.
Chains chains(int bodies, int length) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> weight(0.5, 2.0);
  const int r = bodies * length;
  std::vector<Eigen::Triplet<double, int>> entries;
  int column = 0;
  std::vector<int> free_bodies;
  for (int b = 0; b < bodies; ++b) {
    const int first = b * length;
    for (int s = first; s + 1 < first + length; ++s, ++column) {
      const double w = weight(random);
      entries.emplace_back(s, column, w);
      entries.emplace_back(s + 1, column, -w);
    }
    if (b % 3 == 0) entries.emplace_back(first, column++, weight(random));
    else free_bodies.push_back(b);
  }
  SparseMatrix G_F(r, column);
  G_F.setFromTriplets(entries.begin(), entries.end());
  Chains out;
  out.A = G_F * SparseMatrix(G_F.transpose());
  out.expected = Eigen::MatrixXd::Zero(r, static_cast<Eigen::Index>(free_bodies.size()));
  for (size_t j = 0; j < free_bodies.size(); ++j)
    out.expected.block(free_bodies[j] * length, static_cast<Eigen::Index>(j), length, 1).setConstant(1 / std::sqrt(length));
  return out;
}

void expect_kernel(const Chains& c, const SemidefiniteKernel& kernel) {
  ASSERT_EQ(kernel.basis.cols(), c.expected.cols());
  ASSERT_EQ(kernel.deleted_rows.size(), static_cast<size_t>(c.expected.cols()));
  const Eigen::MatrixXd difference = kernel.basis * kernel.basis.transpose() - c.expected * c.expected.transpose();
  EXPECT_LT(difference.cwiseAbs().maxCoeff(), 1e-10);  // the same subspace
  // The rest after deleting those rows and columns is regular.
  std::vector<char> kept(static_cast<size_t>(c.A.rows()), 1);
  for (int i : kernel.deleted_rows) kept[static_cast<size_t>(i)] = 0;
  std::vector<int> rows;
  for (int i = 0; i < c.A.rows(); ++i)
    if (kept[static_cast<size_t>(i)]) rows.push_back(i);
  const Eigen::MatrixXd dense(c.A);
  Eigen::MatrixXd block(rows.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i)
    for (size_t j = 0; j < rows.size(); ++j) block(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = dense(rows[i], rows[j]);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(block);
  EXPECT_GT(spectrum.eigenvalues().minCoeff(), 1e-6 * spectrum.eigenvalues().maxCoeff());
}

TEST(SemidefiniteKernel, DenseFindsTheFreeBodiesConstants) {
  const Chains c = chains(6, 10);
  expect_kernel(c, semidefinite_kernel(c.A, 1e-10));
}

TEST(SemidefiniteKernel, SparseInverseIterationFindsTheSameSubspace) {
  const Chains c = chains(6, 10);
  expect_kernel(c, semidefinite_kernel(c.A, 1e-10, /*dense_limit=*/0));
}

TEST(SemidefiniteKernel, SparseGrowsItsBlockPastLargeNullSpaces) {
  const Chains c = chains(30, 12);  // 20 free bodies: more than the first block of 8
  ASSERT_EQ(c.expected.cols(), 20);
  expect_kernel(c, semidefinite_kernel(c.A, 1e-10, 0));
}

TEST(SemidefiniteKernel, DenseInverseIterationFindsTheSameSubspaceAndGrowsItsBlock) {
  for (const auto& [chain_count, length] : std::vector<std::pair<int, int>>{{6, 10}, {30, 12}}) {
    const Chains c = chains(chain_count, length);
    expect_kernel(c, semidefinite_kernel_by_iteration(Eigen::MatrixXd(c.A), 1e-10));
  }
}

TEST(SemidefiniteKernel, ARegularMatrixHasNoNullSpaceEitherWay) {
  const Chains c = chains(3, 5);  // bodies 0: held; 1, 2 free
  SparseMatrix regular = c.A;
  for (int i = 0; i < regular.rows(); ++i) regular.coeffRef(i, i) += 1.0;
  for (Eigen::Index limit : {kDenseKernelLimit, Eigen::Index(0)}) {
    const SemidefiniteKernel kernel = semidefinite_kernel(regular, 1e-10, limit);
    EXPECT_EQ(kernel.basis.cols(), 0);
    EXPECT_TRUE(kernel.deleted_rows.empty());
  }
  EXPECT_EQ(semidefinite_kernel_by_iteration(Eigen::MatrixXd(regular), 1e-10).basis.cols(), 0);
}

}  // namespace
}  // namespace ffeti
