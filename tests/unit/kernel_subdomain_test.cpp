#include "feti/dirichlet.h"
#include "base/errors.h"
#include "feti/kernel.h"
#include "feti/subdomain.h"
#include "membrane_model.h"
#include "solid_block.h"

#include <gtest/gtest.h>

namespace ffeti {
namespace {

SubdomainInput unit_square(int cells) {
  return test::p1_rectangle(0, 0, 1, 1, cells, cells, 1.0, [](double, double) { return 1.0; }, 0);
}

/// Two decoupled copies of a scalar Laplacian as a 2-component field: its kernel is the
/// two translations, not the rotation the candidate rigid modes also contain.
SubdomainInput vector_laplacian(int cells) { return test::two_components(unit_square(cells)); }

TEST(Kernel, FloatingScalarSubdomainHasTheConstants) {
  const SubdomainInput s = unit_square(6);
  const Eigen::MatrixXd R = kernel_in_span(s.K, candidate_kernel(s.x, s.y, s.component));
  ASSERT_EQ(R.cols(), 1);
  EXPECT_LT((s.K.get() * R).norm(), 1e-12);
  EXPECT_NEAR(R.norm(), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(R(0, 0)), 1.0 / std::sqrt(R.rows()), 1e-12);
}

TEST(Kernel, AFloatingBodysBasisIsTheCandidatesOwnNotTurnedByRounding) {
  // Every candidate a rigid motion of the floating block: K Q is rounding alone, and its
  // singular vectors would turn the basis by a rotation only that rounding decides.
  const SubdomainInput block = solid_block(0, {1, 1, 1}, {2, 2, 2}, {0, 0, 0});
  const Eigen::MatrixXd candidates = candidate_kernel(block.x, block.y, block.component, block.z);
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(candidates);
  const Eigen::MatrixXd Q = qr.householderQ() * Eigen::MatrixXd::Identity(candidates.rows(), candidates.cols());
  const Eigen::MatrixXd R = kernel_in_span(block.K, candidates);
  ASSERT_EQ(R.cols(), 6);
  EXPECT_EQ(R, Q);  // bit for bit
  EXPECT_LT((block.K.get() * R).norm(), 1e-10 * block.K.get().norm());
}

TEST(Kernel, DirichletEliminationLeavesNoKernel) {
  const SubdomainInput s = unit_square(6);
  const SparseMatrix K = eliminate_dirichlet(s.K, {0, 7, 14});
  EXPECT_EQ(kernel_in_span(K, candidate_kernel(s.x, s.y, s.component)).cols(), 0);
}

TEST(Kernel, ComputedNotAssumedForPartialConstraints) {
  const SubdomainInput v = vector_laplacian(5);
  const Eigen::MatrixXd candidates = candidate_kernel(v.x, v.y, v.component);
  ASSERT_EQ(candidates.cols(), 3);
  EXPECT_EQ(kernel_in_span(v.K, candidates).cols(), 2);  // rotation is not in Ker K
  // Fix component 0 of one node: only the translation along component 1 remains.
  const SparseMatrix K = eliminate_dirichlet(v.K, {0});
  const Eigen::MatrixXd R = kernel_in_span(K, candidates);
  ASSERT_EQ(R.cols(), 1);
  EXPECT_LT((K * R).norm(), 1e-12);
  for (Eigen::Index i = 0; i < R.rows(); i += 2) EXPECT_NEAR(R(i, 0), 0.0, 1e-12);
}

TEST(Subdomain, GeneralizedInverseSatisfiesKKplusKEqualsK) {
  const SubdomainInput s = unit_square(5);
  const Subdomain sub(0, s.K, candidate_kernel(s.x, s.y, s.component), FactorKind::simplicial);
  ASSERT_TRUE(sub.floating());
  const Eigen::MatrixXd K = Eigen::MatrixXd(s.K.get());
  Eigen::MatrixXd Kplus(K.rows(), K.cols());
  for (Eigen::Index j = 0; j < K.cols(); ++j) {
    Vec column;
    sub.apply_pseudo_inverse(Vec::Unit(K.rows(), j), column);
    Kplus.col(j) = column;
  }
  EXPECT_LT((K * Kplus * K - K).norm(), 1e-10 * K.norm());
  EXPECT_LT((Kplus - Kplus.transpose()).norm(), 1e-10 * Kplus.norm());
  EXPECT_LT(sub.pseudo_inverse_residual(s.K), 1e-12);
}

TEST(Subdomain, RegularSubdomainInverseMatchesDense) {
  const SubdomainInput s = unit_square(4);
  const SparseMatrix K = eliminate_dirichlet(s.K, {0, 1, 2});
  for (FactorKind kind : {FactorKind::simplicial, FactorKind::supernodal}) {
    const Subdomain sub(0, K, candidate_kernel(s.x, s.y, s.component), kind);
    EXPECT_FALSE(sub.floating());
    const Vec b = Vec::LinSpaced(K.rows(), -1, 2);
    Vec x;
    sub.apply_pseudo_inverse(b, x);
    EXPECT_LT((Eigen::MatrixXd(K) * x - b).norm(), 1e-11 * b.norm());
  }
}

TEST(Subdomain, AKernelOutsideTheCandidatesIsAnInputError) {
  // Two disconnected squares in one "subdomain": two constants in the kernel, one candidate.
  SubdomainInput a = unit_square(3);
  const auto n = a.K.rows();
  SparseMatrix K(2 * n, 2 * n);
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int j = 0; j < n; ++j)
    for (SparseMatrix::InnerIterator it(a.K, j); it; ++it) {
      entries.emplace_back(it.row(), j, it.value());
      entries.emplace_back(n + it.row(), n + j, it.value());
    }
  K.setFromTriplets(entries.begin(), entries.end());
  try {
    Subdomain sub(3, K, Eigen::MatrixXd::Ones(2 * n, 1), FactorKind::simplicial);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("K[3]"), std::string::npos) << error.what();
  }
}

TEST(Dirichlet, EliminatedLoadReproducesPrescribedValues) {
  const SubdomainInput s = unit_square(4);
  const std::vector<int> dofs = {0, 5, 10};
  const std::vector<double> values = {1.0, -2.0, 0.5};
  const SparseMatrix K = eliminate_dirichlet(s.K, dofs);
  const Vec f = eliminated_load(s.K, s.f, dofs, values);
  const Vec u = Eigen::MatrixXd(K).ldlt().solve(f);
  for (size_t k = 0; k < dofs.size(); ++k) EXPECT_NEAR(u[dofs[k]], values[k], 1e-12);
  // Equilibrium holds with the original K away from the Dirichlet dofs.
  Vec residual = s.K.get() * u - s.f;
  for (int dof : dofs) residual[dof] = 0;
  EXPECT_LT(residual.norm(), 1e-10);
}

}  // namespace
}  // namespace ffeti
