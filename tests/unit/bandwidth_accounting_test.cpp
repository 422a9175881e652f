// What the memory-bandwidth bound of a Hessian multiplication is computed from
// (scripts/bandwidth_bound.py): the bytes a pass over a factor reads, counted by hand on
// factors whose structure is known, and the solve's split of its time into Hessian
// multiplications, F and the triangular solves inside F, with F's application count.
#include "factor/cholmod_factor.h"
#include "feti/feti_problem.h"
#include "membrane_model.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace ffeti {
namespace {

TEST(BandwidthAccounting, SimplicialFactorBytesOfATridiagonalMatrix) {
  // The 1D Laplacian has no fill: L has n diagonal and n - 1 subdiagonal entries, each a
  // value (8 bytes) and a row index (4), and every column a start and a count (4 + 4).
  const int n = 1000;
  SparseMatrix A(n, n);
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0);
    if (i + 1 < n) entries.emplace_back(i + 1, i, -1.0);
  }
  A.setFromTriplets(entries.begin(), entries.end());
  A.makeCompressed();
  CholmodFactor factor(FactorKind::simplicial);
  ASSERT_LT(factor.factorize(A), 0);
  EXPECT_EQ(factor.factor_nonzeros(), 2 * n - 1);
  EXPECT_EQ(factor.factor_bytes(), (2 * n - 1) * 12.0 + n * 8.0);
}

TEST(BandwidthAccounting, SupernodalFactorBytesOfADenseMatrix) {
  // A dense matrix is one supernode: its n x n block of values (the upper triangle's
  // padding included: the solve walks it), n row indices and the supernode's pointers
  // (super, pi and px, two entries each).
  const int n = 60;
  const Eigen::MatrixXd M = Eigen::MatrixXd::Random(n, n);
  const Eigen::MatrixXd dense = M * M.transpose() + n * Eigen::MatrixXd::Identity(n, n);
  const SparseMatrix A = dense.sparseView();
  CholmodFactor factor(FactorKind::supernodal);
  ASSERT_LT(factor.factorize(A), 0);
  ASSERT_TRUE(factor.supernodal());
  EXPECT_EQ(factor.factor_bytes(), n * n * 8.0 + n * 4.0 + 3 * 2 * 4.0);
}

TEST(BandwidthAccounting, SolveTimeSplitsIntoHessianOperatorAndSolves) {
  // The membranes with contact (SMALBE-M, free-rows coarse constraints: a projection and
  // T around F) and glued without contact (projected CG), on one thread so that the
  // solves' thread-seconds are wall-clock seconds.
  for (bool contact : {true, false}) {
    test::MembraneOptions o = test::membrane_options(64, 4);
    o.with_contact = contact;
    o.fix_right_body = !contact;
    std::vector<SubdomainInput> subdomains = test::membrane_subdomains(o);
    const ContactInput input = contact ? test::membrane_contact(subdomains) : ContactInput{};
    FetiSetupSettings setup;
    setup.threads = 1;
    const FetiProblem problem(std::move(subdomains), input, setup);
    // Every factor's values and indices: more than its values alone, less than 8 + 4 bytes a
    // nonzero plus 8 per unknown (simplicial's worst case with its column starts and counts).
    EXPECT_GT(problem.factor_bytes(), 8 * problem.factor_nonzeros());
    EXPECT_LT(problem.factor_bytes(), 12 * problem.factor_nonzeros() + 8.0 * problem.primal_dimension());
    const FetiResult r = problem.solve();
    ASSERT_EQ(r.status, SolveStatus::converged);
    EXPECT_EQ(r.path, contact ? DualPath::smalbe : DualPath::projected_cg);
    // One application of F per multiplication, the norm estimate's left out of both.
    EXPECT_GT(r.counts.hessian, 0);
    EXPECT_EQ(r.dual_operator_applications, r.counts.hessian);
    EXPECT_GT(r.times.factor_solves, 0.0);
    EXPECT_LE(r.times.factor_solves, r.times.dual_operator);
    EXPECT_LE(r.times.dual_operator, r.times.hessian);
    EXPECT_LE(r.times.hessian, r.times.solve);
  }
}

}  // namespace
}  // namespace ffeti
