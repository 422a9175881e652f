#include "qp/conjugate_gradient.h"
#include "qp_test_problems.h"

#include <gtest/gtest.h>

namespace ffeti {
namespace {

TEST(ConjugateGradient, SolvesAnSpdSystem) {
  const Eigen::MatrixXd A = test::random_spd(50, 100, 3);
  const Vec x_star = Vec::LinSpaced(50, -1, 1);
  const Vec b = A * x_star;
  Vec x = Vec::Zero(50);
  const CgResult result = conjugate_gradient(test::free_problem(test::dense_operator(A), b), CgSettings{}, x, test::large_budget(),
      [&](const Vec&, const Vec&, double norm) { return norm <= 1e-12 * b.norm(); });
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_LT((x - x_star).norm(), 1e-9 * x_star.norm());
  EXPECT_LE(result.counts.cg, 2 * 50);  // n steps in exact arithmetic, a few more in rounding
  // The initial gradient, one per step, and the true gradient checked at the end.
  EXPECT_EQ(result.counts.hessian, result.counts.cg + 2);
  EXPECT_LE((A * x - b).norm(), 1e-12 * b.norm());
}

TEST(ConjugateGradient, ToleranceBelowRoundOffIsStagnationNotConvergence) {
  const Eigen::MatrixXd A = test::random_spd(50, 1e8, 5);
  const Vec b = A * Vec::LinSpaced(50, -1, 1);
  Vec x = Vec::Zero(50);
  const CgResult result = conjugate_gradient(test::free_problem(test::dense_operator(A), b), CgSettings{}, x, test::large_budget(),
      [&](const Vec&, const Vec&, double norm) { return norm <= 1e-20 * b.norm(); });
  EXPECT_EQ(result.status, SolveStatus::stagnated);
  EXPECT_NEAR(result.gradient_norm, (A * x - b).norm(), 1e-12 * b.norm());  // the true gradient
}

TEST(ConjugateGradient, ProjectedOperatorStaysInTheSubspace) {
  // A = P M P with P the projector onto Ker C: CG from 0 on b in Ker C stays in Ker C.
  const Eigen::MatrixXd M = test::random_spd(40, 50, 4);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2, 40);
  C.row(0).head(20).setOnes();
  C.row(1).tail(20).setOnes();
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(40, 40) -
                            C.transpose() * (C * C.transpose()).inverse() * C;
  const Eigen::MatrixXd A = P * M * P;
  const Vec b = P * Vec::LinSpaced(40, 0, 3);
  Vec x = Vec::Zero(40);
  const CgResult result = conjugate_gradient(test::free_problem(test::dense_operator(A), b), CgSettings{}, x, test::large_budget(),
      [&](const Vec&, const Vec&, double norm) { return norm <= 1e-11 * b.norm(); });
  ASSERT_EQ(result.status, SolveStatus::converged);
  EXPECT_LT((C * x).norm(), 1e-10);
  EXPECT_LT((P * (M * x) - b).norm(), 1e-9 * b.norm());
}

TEST(ConjugateGradient, IndefiniteOperatorIsReported) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Identity(3, 3);
  A(1, 1) = -2;
  const Vec b = Vec::Ones(3);
  Vec x = Vec::Zero(3);
  const CgResult result = conjugate_gradient(test::free_problem(test::dense_operator(A), b), CgSettings{}, x, test::large_budget(),
      [](const Vec&, const Vec&, double norm) { return norm <= 1e-14; });
  EXPECT_EQ(result.status, SolveStatus::not_positive_definite);
}

TEST(ConjugateGradient, BlockRunsEachSystemAsOnItsOwn) {
  // Three systems with the same A finishing at different steps (different tolerances and
  // one below round-off): each column repeats the single run's iterates and counts.
  const Eigen::MatrixXd A = test::random_spd(60, 1e4, 6);
  const std::vector<Vec> b = {A * Vec::LinSpaced(60, -1, 1), Vec::Ones(60), A * Vec::LinSpaced(60, 2, 0)};
  const std::vector<double> tolerance = {1e-10, 1e-4, 1e-20};
  std::vector<StopTest> stop;
  for (size_t j = 0; j < b.size(); ++j)
    stop.push_back([&, j](const Vec&, const Vec&, double norm) { return norm <= tolerance[j] * b[j].norm(); });
  std::vector<Vec> x(b.size(), Vec::Zero(60));
  int applications = 0, block_columns = 0;
  const std::vector<CgResult> block = conjugate_gradient_block(
      [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) {
        ++applications;
        block_columns += static_cast<int>(X.cols());
        Y = A * X;
      },
      b, x, CgSettings{}, test::large_budget(), stop);
  int longest = 0, total = 0;
  for (size_t j = 0; j < b.size(); ++j) {
    Vec alone = Vec::Zero(60);
    const CgResult single = conjugate_gradient(test::free_problem(test::dense_operator(A), b[j]), CgSettings{}, alone, test::large_budget(),
      stop[j]);
    EXPECT_EQ(block[j].status, single.status) << "system " << j;
    EXPECT_EQ(block[j].counts.hessian, single.counts.hessian) << "system " << j;
    EXPECT_EQ(block[j].counts.cg, single.counts.cg) << "system " << j;
    EXPECT_LT((x[j] - alone).norm(), 1e-12 * alone.norm()) << "system " << j;
    longest = std::max(longest, single.counts.hessian);
    total += single.counts.hessian;
  }
  EXPECT_EQ(block[0].status, SolveStatus::converged);
  EXPECT_EQ(block[2].status, SolveStatus::stagnated);
  EXPECT_LT(block[1].counts.hessian, block[0].counts.hessian);  // finished early, left the block
  EXPECT_EQ(applications, longest);  // one application per step of the longest run
  EXPECT_EQ(block_columns, total);   // finished runs are not multiplied any more
}

TEST(ConjugateGradient, PreconditionedBlockRunsEachSystemAsOnItsOwn) {
  // The same with a preconditioner (Jacobi of an operator with a wide diagonal): each column
  // repeats the preconditioned single run, and takes fewer steps than unpreconditioned.
  Eigen::MatrixXd A = test::random_spd(60, 1e2, 7);
  for (int i = 0; i < 60; ++i) A(i, i) *= 1 + 100.0 * i / 59;
  const Vec inverse_diagonal = A.diagonal().cwiseInverse();
  const LinearOperator jacobi = [&](const Vec& g, Vec& z) { z = inverse_diagonal.cwiseProduct(g); };
  const std::vector<Vec> b = {A * Vec::LinSpaced(60, -1, 1), Vec::Ones(60)};
  const std::vector<StopTest> stop(2, [&](const Vec&, const Vec&, double norm) { return norm <= 1e-10 * 60; });
  std::vector<Vec> x(b.size(), Vec::Zero(60));
  const std::vector<CgResult> block = conjugate_gradient_block(
      [&](const Eigen::MatrixXd& X, Eigen::MatrixXd& Y) { Y = A * X; }, b, x, CgSettings{}, test::large_budget(), stop,
      jacobi);
  for (size_t j = 0; j < b.size(); ++j) {
    qp::Problem preconditioned = test::free_problem(test::dense_operator(A), b[j]);
    preconditioned.preconditioner = jacobi;
    Vec alone = Vec::Zero(60), plain = Vec::Zero(60);
    const CgResult single = conjugate_gradient(preconditioned, CgSettings{}, alone, test::large_budget(), stop[j]);
    const CgResult unpreconditioned = conjugate_gradient(test::free_problem(test::dense_operator(A), b[j]), CgSettings{},
                                                         plain, test::large_budget(), stop[j]);
    EXPECT_EQ(block[j].status, SolveStatus::converged) << "system " << j;
    EXPECT_EQ(block[j].counts.hessian, single.counts.hessian) << "system " << j;
    EXPECT_EQ(block[j].counts.preconditioner, single.counts.preconditioner) << "system " << j;
    EXPECT_LT((x[j] - alone).norm(), 1e-12 * alone.norm()) << "system " << j;
    EXPECT_LT(single.counts.hessian, unpreconditioned.counts.hessian) << "system " << j;
  }
}

}  // namespace
}  // namespace ffeti
