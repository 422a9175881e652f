// qp::Problem as the solvers read it: its constraint set's blocks and bounds, and each
// solver's refusal of a problem it does not solve.
#include "qp/conjugate_gradient.h"
#include "qp/mprgp.h"
#include "qp/smalbe.h"
#include "qp_test_problems.h"

#include <gtest/gtest.h>

#include <limits>

namespace ffeti {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ConstraintSet, BlocksKeepTheirOrderAndBounds) {
  qp::ConstraintSet set;
  set.add_free(2);
  set.add_half_line(Vec::Zero(3));
  set.add_box(Vec::Constant(2, -1.0), Vec::Constant(2, 1.0));
  ASSERT_EQ(set.blocks().size(), 3u);
  EXPECT_EQ(set.blocks()[1].first, 2);
  EXPECT_EQ(set.blocks()[1].kind, qp::BlockKind::half_line);
  EXPECT_EQ(set.blocks()[2].first, 5);
  EXPECT_EQ(set.size(), 7);
  EXPECT_EQ(set.lower(), (Vec(7) << kUnbounded, kUnbounded, 0, 0, 0, -1, -1).finished());
  EXPECT_EQ(set.upper(), (Vec(7) << kInf, kInf, kInf, kInf, kInf, 1, 1).finished());
  EXPECT_TRUE(set.bounded());
  // Free where strictly inside: the free block everywhere, a half-line above 0, a box inside.
  const Vec x = (Vec(7) << -1e300, 0, 0, 2, 0, 0.5, 1).finished();
  EXPECT_EQ(set.free_components(x), (std::vector<char>{1, 1, 0, 1, 0, 1, 0}));
}

TEST(ConstraintSet, PinnedComponentsHaveNoFeasibleDirection) {
  qp::ConstraintSet set;
  set.add_box((Vec(3) << 0, -1, -1).finished(), (Vec(3) << 0, 1, 1).finished());  // l = u = 0: pinned
  const Vec x = (Vec(3) << 0, -1, 1).finished();  // pinned, at the lower bound, at the upper bound
  const Vec g = (Vec(3) << 5, 2, 2).finished();
  EXPECT_EQ(set.projected_gradient(x, g), (Vec(3) << 0, 0, 2).finished());
  EXPECT_EQ(set.projected_gradient(x, -g), (Vec(3) << 0, -2, 0).finished());
  EXPECT_EQ(set.feasible_step(x, (Vec(3) << 1, 0, 0).finished(), false), 0.0);
}

TEST(ConstraintSet, FromBoundsGroupsRunsOfOneKind) {
  const Vec lower = (Vec(5) << kUnbounded, 0, 0, -2, kUnbounded).finished();
  const Vec upper = (Vec(5) << kInf, kInf, kInf, 2, kInf).finished();
  const qp::ConstraintSet set = qp::ConstraintSet::from_bounds(lower, upper);
  ASSERT_EQ(set.blocks().size(), 4u);
  EXPECT_EQ(set.blocks()[1].size, 2);
  EXPECT_EQ(set.blocks()[2].kind, qp::BlockKind::box);
  EXPECT_EQ(set.lower(), lower);
  EXPECT_EQ(set.upper(), upper);
}

TEST(ConstraintSet, ShiftedMovesTheBoundsNotTheBlocks) {
  qp::ConstraintSet set;
  set.add_free(1);
  set.add_box(Vec::Constant(1, -1.0), Vec::Constant(1, 1.0));
  const qp::ConstraintSet moved = set.shifted((Vec(2) << 5, 0.5).finished());
  EXPECT_EQ(moved.lower()[0], kUnbounded);
  EXPECT_EQ(moved.lower()[1], -1.5);
  EXPECT_EQ(moved.upper()[1], 0.5);
  EXPECT_EQ(moved.blocks().size(), 2u);
}

TEST(QpProblem, EachSolverRefusesWhatItDoesNotSolve) {
  const test::BoundQp bqp = test::manufactured_bound_qp(10, 10, 1, false);
  const qp::Problem bounded = test::bound_problem(test::dense_operator(bqp.A), bqp.b, bqp.lower, 11);
  const StopTest never = [](const Vec&, const Vec&, double) { return false; };
  Vec x = Vec::Zero(10);
  EXPECT_THROW(conjugate_gradient(bounded, CgSettings{}, x, test::large_budget(), never), std::invalid_argument);
  qp::Problem with_equality = bounded;
  with_equality.range_projector = test::dense_operator(Eigen::MatrixXd::Identity(10, 10));
  EXPECT_THROW(mprgp(with_equality, MprgpSettings{}, x, test::large_budget(), never), std::invalid_argument);
  EXPECT_THROW(smalbe(bounded, SmalbeSettings{}, x, test::large_budget(), never), std::invalid_argument);
  EXPECT_THROW(qp::Budget(0), std::invalid_argument);
}

TEST(QpProblem, SmalbeReturnsItsMultiplierAndStartsFromIt) {
  // A second solve started from the first one's x and multiplier term is already there.
  const test::BoundEqualityQp eqp = test::manufactured_bound_equality_qp(30, 3, 100, 7);
  qp::Problem problem = test::bound_problem(test::dense_operator(eqp.H), eqp.b, eqp.lower, 105);
  problem.range_projector = test::dense_operator(eqp.Q);
  const double tol = 1e-9 * eqp.b.norm();
  const StopTest stop = [&](const Vec& x, const Vec&, double gp) { return gp <= tol && (eqp.Q * x).norm() <= tol; };
  Vec x = Vec::Zero(30);
  const SmalbeResult cold = smalbe(problem, SmalbeSettings{}, x, test::large_budget(), stop);
  ASSERT_EQ(cold.status, SolveStatus::converged);
  ASSERT_EQ(cold.multiplier.size(), 30);
  problem.equality_multiplier = cold.multiplier;
  const SmalbeResult warm = smalbe(problem, SmalbeSettings{}, x, test::large_budget(), stop);
  EXPECT_EQ(warm.status, SolveStatus::converged);
  EXPECT_LE(warm.counts.hessian, 2);
  EXPECT_LT(warm.counts.hessian, cold.counts.hessian);
}

}  // namespace
}  // namespace ffeti
