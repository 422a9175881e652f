// Disc blocks (isotropic friction, ALGORITHMS.md section 11) in MPGP and SMALBE, against an
// independent dense answer (accelerated projected gradient, disc_reference.h) and the KKT
// conditions recomputed here.
#include "disc_reference.h"
#include "qp/mprgp.h"
#include "qp/smalbe.h"
#include "qp_test_problems.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ffeti {
namespace {

constexpr double kCondition = 30.0;

qp::Problem problem_of(const test::DiscQp& qp, const LinearOperator& preconditioner = {}) {
  qp::Problem problem;
  problem.hessian = test::dense_operator(qp.H);
  problem.b = qp.b;
  problem.hessian_norm = 1.05 * kCondition;
  problem.preconditioner = preconditioner;
  problem.constraints = qp.set();
  return problem;
}

/// MPGP from x to ||gP|| <= 1e-12 ||b||; x is the answer on return.
MprgpResult solve(const test::DiscQp& qp, Vec& x, const MprgpSettings& settings = {},
                  const LinearOperator& preconditioner = {}) {
  const double tol = 1e-12 * qp.b.norm();
  return mprgp(problem_of(qp, preconditioner), settings, x, test::large_budget(),
               [&](const Vec&, const Vec&, double norm) { return norm <= tol; });
}

/// SMALBE with qp.C from x to ||gP(x, nu, 0)|| <= 1e-12 ||b|| and ||Q x|| <= 1e-12 ||b|| / ||H||.
SmalbeResult solve_with_equality(const test::DiscQp& qp, Vec& x) {
  const Eigen::MatrixXd Q = qp.C.transpose() * (qp.C * qp.C.transpose()).inverse() * qp.C;
  qp::Problem problem = problem_of(qp);
  problem.range_projector = test::dense_operator(Q);
  const double tol = 1e-12 * qp.b.norm();
  return smalbe(problem, SmalbeSettings{}, x, test::large_budget(), [&](const Vec& xi, const Vec&, double gP) {
    return gP <= tol && (Q * xi).norm() <= tol / kCondition;
  });
}

TEST(DiscConstraints, BlocksKeepTheirCentresAndRadii) {
  qp::ConstraintSet set;
  set.add_free(1);
  set.add_disc((Vec(4) << 1, 2, 3, 4).finished(), (Vec(2) << 0.5, 0).finished());
  set.add_half_line(Vec::Zero(1));
  ASSERT_EQ(set.blocks().size(), 3u);
  EXPECT_EQ(set.blocks()[1].kind, qp::BlockKind::disc);
  EXPECT_EQ(set.blocks()[1].first, 1);
  EXPECT_EQ(set.blocks()[1].size, 4);
  EXPECT_EQ(set.lower(), (Vec(6) << kUnbounded, kUnbounded, kUnbounded, kUnbounded, kUnbounded, 0).finished());
  EXPECT_TRUE(set.bounded());
  // Projected: the free component stays, pair 1 goes onto its circle about (1, 2), pair 2
  // (radius 0) to its centre, the half-line to 0.
  Vec x = (Vec(6) << 7, 1, 12, 9, 9, -5).finished();
  EXPECT_EQ(set.project(x), 3);
  EXPECT_LT((x - (Vec(6) << 7, 1, 2.5, 3, 4, 0).finished()).norm(), 1e-15);
  EXPECT_TRUE(set.contains(x));
  // Shifted by 1: centres and the bound move by -1, the radii stay.
  const qp::ConstraintSet moved = set.shifted(Vec::Constant(6, 1.0));
  Vec y = (Vec(6) << 7, 0, 11, 9, 9, -5).finished();
  EXPECT_EQ(moved.project(y), 3);
  EXPECT_LT((y - (Vec(6) << 7, 0, 1.5, 2, 3, -1).finished()).norm(), 1e-15);
  EXPECT_FALSE(set.contains(y));
  EXPECT_THROW(set.add_disc(Vec::Zero(3), Vec::Zero(1)), std::invalid_argument);
  EXPECT_THROW(set.add_disc(Vec::Zero(2), Vec::Constant(1, -1.0)), std::invalid_argument);
}

TEST(DiscConstraints, ProjectedGradientOnTheCircle) {
  qp::ConstraintSet set;
  set.add_disc(Vec::Zero(2), Vec::Constant(1, 2.0));
  const Vec x = (Vec(2) << 2, 0).finished();  // on the circle, outward normal (1, 0)
  // -g pointing out: held, gP 0; pointing in: all of g; tangential: all of it; a mix: its tangential part.
  EXPECT_EQ(set.projected_gradient(x, (Vec(2) << -3, 0).finished()), Vec::Zero(2));
  EXPECT_EQ(set.projected_gradient(x, (Vec(2) << 3, 0).finished()), (Vec(2) << 3, 0).finished());
  EXPECT_EQ(set.projected_gradient(x, (Vec(2) << 0, 1).finished()), (Vec(2) << 0, 1).finished());
  EXPECT_EQ(set.projected_gradient(x, (Vec(2) << -3, 1).finished()), (Vec(2) << 0, 1).finished());
  EXPECT_EQ(set.projected_gradient_max(x, (Vec(2) << -3, 1).finished()), 1.0);
  Vec outside = (Vec(2) << 0, -8).finished();
  EXPECT_EQ(set.project(outside), 1);
  EXPECT_EQ(outside, (Vec(2) << 0, -2).finished());
}

TEST(DiscQp, MpgpMatchesTheAcceleratedProjectedGradient) {
  int on_circle = 0, inside = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    const test::DiscQp qp = test::random_disc_qp(kCondition, seed);
    const Vec reference = test::accelerated_projected_gradient(qp);
    ASSERT_LT(test::kkt_violation(qp, reference), 1e-9) << "seed " << seed;
    for (int j = 1; j < 5; ++j) {
      const double distance = (reference.segment<2>(5 + 2 * j) - qp.centre.segment<2>(2 * j)).norm();
      (distance < 0.999 * qp.radius[j] ? inside : on_circle) += 1;
    }
    for (MprgpExpansion expansion :
         {MprgpExpansion::fixed_step, MprgpExpansion::projected_cg_restart, MprgpExpansion::projected_cg}) {
      MprgpSettings settings;
      settings.expansion = expansion;
      Vec x = Vec::Zero(15);
      const MprgpResult r = solve(qp, x, settings);
      ASSERT_EQ(r.status, SolveStatus::converged) << "seed " << seed;
      EXPECT_LT(r.counts.hessian, 500) << "seed " << seed;
      EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm()) << "seed " << seed;
      EXPECT_LT(test::kkt_violation(qp, x), 1e-10) << "seed " << seed;
      EXPECT_EQ(x.segment<2>(5), qp.centre.segment<2>(0));  // radius 0: pinned at the centre
    }
  }
  EXPECT_GT(on_circle, 3);  // the problems do have discs of both states
  EXPECT_GT(inside, 3);
}

TEST(DiscQp, PairsSlippingHardOnSmallCirclesAgree) {
  // Radii 1e-3 of the random ones: every disc pair ends on its circle with -n'g / radius, the
  // curvature the circle adds round it, far above ||H|| (rows slipping fast under small
  // bounds). CG round the circles needs that curvature in its steps and its preconditioner.
  for (unsigned seed = 1; seed <= 3; ++seed) {
    test::DiscQp qp = test::random_disc_qp(kCondition, seed);
    qp.radius *= 1e-3;  // 0 on the pinned pair: unchanged
    const Vec reference = test::accelerated_projected_gradient(qp);
    ASSERT_LT(test::kkt_violation(qp, reference), 1e-9) << "seed " << seed;
    Vec x = Vec::Zero(15);
    const MprgpResult r = solve(qp, x);
    ASSERT_EQ(r.status, SolveStatus::converged) << "seed " << seed;
    EXPECT_LT(r.counts.hessian, 200) << "seed " << seed;
    EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm()) << "seed " << seed;
    EXPECT_LT(test::kkt_violation(qp, x), 1e-10) << "seed " << seed;
    for (int j = 1; j < 5; ++j)  // on its circle, with the circle's curvature above ||H||
      EXPECT_NEAR((x.segment<2>(5 + 2 * j) - qp.centre.segment<2>(2 * j)).norm(), qp.radius[j], 1e-12) << "seed " << seed << " pair " << j;
  }
}

TEST(DiscQp, StiffAndSoftCirclesTogetherAgree) {
  // Pairs 1 and 3 on small circles (their tangent held, turned by the projected step), pairs
  // 2 and 4 of the random radii (CG round their circles where they reach them): both rules
  // in one solve.
  for (unsigned seed = 1; seed <= 3; ++seed) {
    test::DiscQp qp = test::random_disc_qp(kCondition, seed);
    for (const int j : {1, 3}) qp.radius[j] *= 1e-3;
    const Vec reference = test::accelerated_projected_gradient(qp);
    ASSERT_LT(test::kkt_violation(qp, reference), 1e-9) << "seed " << seed;
    Vec x = Vec::Zero(15);
    const MprgpResult r = solve(qp, x);
    ASSERT_EQ(r.status, SolveStatus::converged) << "seed " << seed;
    EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm()) << "seed " << seed;
    EXPECT_LT(test::kkt_violation(qp, x), 1e-10) << "seed " << seed;
  }
}

TEST(DiscQp, PreconditionedMpgpAgrees) {
  const test::DiscQp qp = test::random_disc_qp(kCondition, 7);
  const Vec reference = test::accelerated_projected_gradient(qp);
  const Eigen::MatrixXd jacobi = qp.H.diagonal().cwiseInverse().asDiagonal();
  Vec x = Vec::Zero(15);
  const MprgpResult r = solve(qp, x, MprgpSettings{}, test::dense_operator(jacobi));
  ASSERT_EQ(r.status, SolveStatus::converged);
  EXPECT_GT(r.counts.preconditioner, 0);
  EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm());
}

TEST(DiscQp, AllDiscsOfRadiusZeroPinTheirPairs) {
  test::DiscQp qp = test::random_disc_qp(kCondition, 3);
  const Vec centre = qp.centre;
  qp.free = 5;  // the half-lines dropped: the rest is a linear solve
  qp.lower = Vec();
  qp.radius = Vec::Zero(5);
  Vec x = Vec::Constant(15, 1.0);
  ASSERT_EQ(solve(qp, x).status, SolveStatus::converged);
  EXPECT_EQ(x.tail(10), centre);
  const Vec rest = qp.H.topLeftCorner(5, 5).ldlt().solve(qp.b.head(5) - qp.H.topRightCorner(5, 10) * centre);
  EXPECT_LT((x.head(5) - rest).norm(), 1e-9 * rest.norm());
}

TEST(DiscQp, AStartOutsideTheDiscsIsProjectedFirst) {
  const test::DiscQp qp = test::random_disc_qp(kCondition, 2);
  const Vec reference = test::accelerated_projected_gradient(qp);
  std::mt19937 random(5);
  std::normal_distribution<double> normal;
  Vec x(15);
  for (Eigen::Index i = 0; i < 15; ++i) x[i] = 100 * normal(random);  // far outside every disc
  ASSERT_EQ(solve(qp, x).status, SolveStatus::converged);
  EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm());
}

TEST(DiscQp, RotatingAPairsDataRotatesItsAnswer) {
  // Isotropy: with T turning every disc pair by its own angle, the problem (T H T', T b,
  // T c) has the answer T x. A box in place of the disc would fail this.
  const test::DiscQp qp = test::random_disc_qp(kCondition, 4);
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(15, 15);
  for (int j = 0; j < 5; ++j) T.block<2, 2>(5 + 2 * j, 5 + 2 * j) = Eigen::Rotation2Dd(0.4 + 0.7 * j).toRotationMatrix();
  test::DiscQp turned = qp;
  turned.H = T * qp.H * T.transpose();
  turned.b = T * qp.b;
  turned.centre = T.bottomRightCorner(10, 10) * qp.centre;
  Vec x = Vec::Zero(15), x_turned = Vec::Zero(15);
  ASSERT_EQ(solve(qp, x).status, SolveStatus::converged);
  ASSERT_EQ(solve(turned, x_turned).status, SolveStatus::converged);
  EXPECT_LT((x_turned - T * x).norm(), 1e-8 * x.norm());
}

TEST(DiscQp, SmalbeWithAnEqualityMatchesTheAcceleratedProjectedGradient) {
  test::DiscQp qp = test::random_disc_qp(kCondition, 6);
  qp.C = Eigen::MatrixXd::Zero(1, 15);
  qp.C(0, 0) = 1, qp.C(0, 1) = 2;  // on the free components: the reference's projection stays exact
  const Vec reference = test::accelerated_projected_gradient(qp);
  ASSERT_LT(test::kkt_violation(qp, reference), 1e-9);
  Vec x = Vec::Zero(15);
  ASSERT_EQ(solve_with_equality(qp, x).status, SolveStatus::converged);
  EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm());
  EXPECT_LT(test::kkt_violation(qp, x), 1e-10);
}

TEST(DiscQp, SmalbeWithAnEqualityThroughTheDiscsMeetsTheKktConditions) {
  // C couples a free component, a half-line and two discs' components: no exact projection
  // for a reference, so the KKT conditions (C'mu by least squares) are the check.
  test::DiscQp qp = test::random_disc_qp(kCondition, 8);
  qp.C = Eigen::MatrixXd::Zero(1, 15);
  qp.C(0, 0) = 1, qp.C(0, 3) = -1, qp.C(0, 9) = 0.5, qp.C(0, 12) = 1;
  Vec x = Vec::Zero(15);
  ASSERT_EQ(solve_with_equality(qp, x).status, SolveStatus::converged);
  EXPECT_LT(test::kkt_violation(qp, x), 1e-10);
  Vec along_the_kernel = Vec::Zero(15);  // C'd = 0, every bound and circle kept: only stationarity can fail
  along_the_kernel[1] = 1e-4;
  EXPECT_GT(test::kkt_violation(qp, x + along_the_kernel), 1e-7);  // the check is not vacuous
}

}  // namespace
}  // namespace ffeti
