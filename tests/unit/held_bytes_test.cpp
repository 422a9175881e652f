// The report's memory keys (feti/held_bytes): bytes counted from the containers' sizes, a
// stiffness shared by identical subdomains counted once, against sums worked out by hand;
// and the dense rate the factorizations' rate is read against (factor/dense_rate).
#include "factor/dense_rate.h"
#include "feti/held_bytes.h"
#include "membrane_model.h"

#include <gtest/gtest.h>

#include <vector>

namespace ffeti {
namespace {

SparseMatrix tridiagonal(int n) {
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0);
    if (i > 0) entries.emplace_back(i, i - 1, -1.0), entries.emplace_back(i - 1, i, -1.0);
  }
  SparseMatrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  return K;
}

SubdomainInput plane_input(const SharedMatrix& K) {
  SubdomainInput in;
  in.K = K;
  const auto n = static_cast<size_t>(K.rows());
  in.f = Vec::Zero(K.rows());
  in.x.assign(n, 0.0);
  in.y.assign(n, 0.0);
  in.dirichlet_dofs = {0};
  return in;
}

TEST(HeldBytes, InputCountsEachStiffnessOnceAndEveryVector) {
  const int n = 10;
  const SharedMatrix K(tridiagonal(n));
  // K: 28 values and row indices, 11 column starts; f, x, y: 10 doubles each; one Dirichlet dof.
  const double matrix = 28 * (8 + 4) + 11 * 4, vectors = 3 * 10 * 8 + 4;
  EXPECT_DOUBLE_EQ(input_bytes({plane_input(K)}), matrix + vectors);
  // A second subdomain sharing the matrix (stiffnessOf=) adds its vectors only; one of its own adds both.
  EXPECT_DOUBLE_EQ(input_bytes({plane_input(K), plane_input(K)}), matrix + 2 * vectors);
  EXPECT_DOUBLE_EQ(input_bytes({plane_input(K), plane_input(SharedMatrix(tridiagonal(n)))}), 2 * (matrix + vectors));
}

TEST(HeldBytes, ConstraintsCountTheirRowsEntriesRightHandSidesAndKinds) {
  Constraints c;
  c.entries = {{0, 1, 1.0}, {1, 2, -1.0}, {0, 3, 1.0}};
  c.row_start = {0, 2, 3};
  c.rhs = {0.0, 0.5};
  c.kind = {RowKind::gluing, RowKind::contact};
  const double expected = 3 * sizeof(ConstraintEntry) + 3 * sizeof(int) + 2 * sizeof(double) + 2 * sizeof(RowKind);
  EXPECT_DOUBLE_EQ(constraint_bytes(c), expected);
}

TEST(HeldBytes, TheDualSystemCountsItsRowsCoarseProblemAndPreconditioner) {
  // The seed's membranes (2 x 2 subdomains per body, Total FETI: every subdomain floats).
  // The rows hold at least the blocks B_s; the lumped preconditioner at least each K_bb (K's
  // lower triangle on the dofs the rows touch), and nothing without one; the coarse problem at least G's
  // values (one row per rigid mode, an entry per row it meets).
  const test::MembraneOptions o = test::membrane_options(16, 2);
  const FetiProblem none = test::membrane_problem(o, FetiVariant::tfeti);
  const FetiProblem lumped = test::membrane_problem(o, FetiVariant::tfeti, 0, DualPreconditioner::lumped);
  double blocks = 0, boundary_blocks = 0;
  for (size_t k = 0; k < lumped.inputs().size(); ++k) {
    const SparseMatrix& B = lumped.dual().local()[k].B;
    blocks += sparse_bytes(B);
    const std::vector<int> touched = touched_dofs(B);
    const SparseMatrix& K = lumped.inputs()[k].K;
    for (int i : touched)  // K_bb is held as its lower triangle
      for (int j : touched)
        if (i >= j && K.coeff(i, j) != 0) boundary_blocks += sizeof(double) + sizeof(SparseMatrix::StorageIndex);
  }
  EXPECT_GE(lumped.dual_bytes().rows, blocks);
  EXPECT_GE(lumped.dual_bytes().preconditioner, boundary_blocks);
  EXPECT_GT(boundary_blocks, 0);
  EXPECT_EQ(none.dual_bytes().preconditioner, 0);
  EXPECT_EQ(none.dual_bytes().rows, lumped.dual_bytes().rows);
  ASSERT_NE(lumped.dual().coarse(), nullptr);
  EXPECT_GE(lumped.dual_bytes().coarse, sparse_bytes(lumped.dual().coarse()->G()));
  EXPECT_GT(sparse_bytes(lumped.dual().coarse()->G()), 0);
}

// The yardstick of the factorizations' rate: a measured rate a core can reach (between a
// tenth of a GFlop/s and the tens of a modern core's vector units, with room), the same
// number on every call (measured once).
TEST(DenseRate, IsMeasuredOnceAndPlausible) {
  const double rate = dense_gflops_one_thread();
  EXPECT_GT(rate, 0.1);
  EXPECT_LT(rate, 1000.0);
  EXPECT_EQ(dense_gflops_one_thread(), rate);
}

}  // namespace
}  // namespace ffeti
