// K_s held as its lower triangle (factor/lower_triangle): blocks cut from it equal the
// blocks of the full matrix, and a set-up keeps each distinct K_s once, as its lower
// triangle, while the caller's full copy stays as it was.
#include "factor/lower_triangle.h"
#include "feti/feti_problem.h"
#include "membrane_model.h"

#include <gtest/gtest.h>

#include <vector>

namespace ffeti {
namespace {

Eigen::MatrixXd dense(const SparseMatrix& A) { return Eigen::MatrixXd(A); }

long upper_entries(const SparseMatrix& A) {
  long count = 0;
  for (int j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) count += it.row() < j;
  return count;
}

TEST(LowerTriangle, BlocksOfTheLowerTriangleAreThoseOfTheFullMatrix) {
  const SparseMatrix K = test::membrane_subdomains(test::membrane_options(8, 2))[0].K;
  ASSERT_GT(upper_entries(K), 0);  // given in full
  std::vector<int> kept;
  for (int i = 0; i < K.rows(); i += 3) kept.push_back(i);
  const auto m = static_cast<Eigen::Index>(kept.size());
  Eigen::MatrixXd expected(m, m);
  for (Eigen::Index i = 0; i < m; ++i)
    for (Eigen::Index j = 0; j < m; ++j) expected(i, j) = i >= j ? K.coeff(kept[size_t(i)], kept[size_t(j)]) : 0.0;
  const SparseMatrix lower = lower_triangle(K);
  EXPECT_EQ(upper_entries(lower), 0);
  EXPECT_EQ(lower.nonZeros(), (K.nonZeros() + K.diagonal().size()) / 2);  // the membranes' diagonal has no zero
  EXPECT_EQ(dense(lower_block(K, kept)), expected);
  EXPECT_EQ(dense(lower_block(lower, kept)), expected);
  const Vec v = Vec::LinSpaced(K.rows(), -1.0, 2.0);
  EXPECT_LE((lower.selfadjointView<Eigen::Lower>() * v - K * v).norm(), 1e-14 * (K * v).norm());
}

TEST(LowerTriangle, TheSetUpKeepsEachStiffnessOnceAsItsLowerTriangle) {
  std::vector<SubdomainInput> inputs = test::membrane_subdomains(test::membrane_options(8, 2));
  // Subdomains 2 and 3 of the first body are alike but for their coordinates: give them one K.
  ASSERT_EQ(dense(inputs[2].K), dense(inputs[3].K));
  inputs[3].K = inputs[2].K;
  const SharedMatrix callers = inputs[0].K;
  const long full_entries = callers.get().nonZeros();
  const ContactInput contact = test::membrane_contact(inputs);
  const FetiProblem problem(inputs, contact, FetiSetupSettings{});
  for (size_t k = 0; k < inputs.size(); ++k) {
    const SparseMatrix& held = problem.inputs()[k].K;
    EXPECT_EQ(upper_entries(held), 0) << "K[" << k << "]";
    EXPECT_EQ(dense(held), Eigen::MatrixXd(dense(inputs[k].K).triangularView<Eigen::Lower>())) << "K[" << k << "]";
  }
  EXPECT_EQ(&problem.inputs()[2].K.get(), &problem.inputs()[3].K.get());
  EXPECT_EQ(callers.get().nonZeros(), full_entries);  // the caller's copy is not touched
}

}  // namespace
}  // namespace ffeti
