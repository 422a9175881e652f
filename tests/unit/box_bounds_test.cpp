// Box bounds l <= x <= u in MPRGP and SMALBE (the tangential rows of friction bound their
// multipliers on both sides), against an independent dense reference: every assignment of
// each component to its lower bound, its upper bound or the free set, the one whose solution
// meets all KKT conditions.
#include "qp/mprgp.h"
#include "qp/smalbe.h"
#include "qp_test_problems.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ffeti {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct BoxQp {
  Eigen::MatrixXd A;
  Vec b, lower, upper;
};

/// A random strictly convex QP on a box that cuts through its unconstrained minimum, so
/// that components end at both bounds and inside.
BoxQp random_box_qp(int n, double condition, unsigned seed) {
  BoxQp qp;
  qp.A = test::random_spd(n, condition, seed);
  std::mt19937 random(seed + 17);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  qp.b.resize(n), qp.lower.resize(n), qp.upper.resize(n);
  for (int i = 0; i < n; ++i) qp.b[i] = 3 * condition * unit(random);
  const Vec free_minimum = qp.A.ldlt().solve(qp.b);
  for (int i = 0; i < n; ++i) {
    const double width = 0.3 + std::abs(unit(random)) * std::abs(free_minimum[i]);
    qp.lower[i] = -width + 0.3 * unit(random);
    qp.upper[i] = qp.lower[i] + 2 * width;
  }
  qp.upper[n - 1] = kInfinity;  // one component bounded below only
  return qp;
}

/// The solution by enumeration (3^n assignments): x_i = l_i, u_i or free, the free part from
/// the reduced system, accepted when x lies in the box and the gradient g = Ax - b has the
/// signs of the KKT conditions (g >= 0 at l, g <= 0 at u, g = 0 free). Optionally with C x = 0.
Vec reference_solution(const BoxQp& qp, const Eigen::MatrixXd& C = Eigen::MatrixXd()) {
  const int n = static_cast<int>(qp.b.size());
  const int k = static_cast<int>(C.rows());
  int assignments = 1;
  for (int i = 0; i < n; ++i) assignments *= 3;
  for (int code = 0; code < assignments; ++code) {
    std::vector<int> state(n);  // 0 lower, 1 upper, 2 free
    bool possible = true;
    for (int i = 0, c = code; i < n; ++i, c /= 3) {
      state[i] = c % 3;
      if (state[i] == 1 && std::isinf(qp.upper[i])) possible = false;
    }
    if (!possible) continue;
    std::vector<int> free;
    Vec x = Vec::Zero(n);
    for (int i = 0; i < n; ++i) {
      if (state[i] == 0) x[i] = qp.lower[i];
      else if (state[i] == 1) x[i] = qp.upper[i];
      else free.push_back(i);
    }
    const int m = static_cast<int>(free.size());
    // [A_FF C_F'; C_F 0] [x_F; mu] = [b_F - A_F,fixed x_fixed; -C_fixed x_fixed]
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m + k, m + k);
    Vec rhs = Vec::Zero(m + k);
    const Vec Ax_fixed = qp.A * x;
    for (int a = 0; a < m; ++a) {
      for (int c = 0; c < m; ++c) K(a, c) = qp.A(free[a], free[c]);
      for (int r = 0; r < k; ++r) K(a, m + r) = K(m + r, a) = C(r, free[a]);
      rhs[a] = qp.b[free[a]] - Ax_fixed[free[a]];
    }
    if (k > 0) rhs.tail(k) = -(C * x);
    Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
    if (m + k > 0 && lu.rank() < m + k) continue;
    const Vec solution = m + k > 0 ? Vec(lu.solve(rhs)) : Vec();
    for (int a = 0; a < m; ++a) x[free[a]] = solution[a];
    Vec g = qp.A * x - qp.b;
    if (k > 0) g += C.transpose() * solution.tail(k);
    bool kkt = true;
    for (int i = 0; i < n && kkt; ++i) {
      if (x[i] < qp.lower[i] - 1e-12 || x[i] > qp.upper[i] + 1e-12) kkt = false;
      if (state[i] == 0 && g[i] < -1e-9) kkt = false;
      if (state[i] == 1 && g[i] > 1e-9) kkt = false;
    }
    if (kkt) return x;
  }
  ADD_FAILURE() << "no assignment meets the KKT conditions";
  return Vec::Zero(n);
}

TEST(BoxBounds, MprgpFindsTheEnumeratedSolution) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const BoxQp qp = random_box_qp(7, 50.0, seed);
    const Vec reference = reference_solution(qp);
    for (MprgpExpansion expansion :
         {MprgpExpansion::fixed_step, MprgpExpansion::projected_cg_restart, MprgpExpansion::projected_cg}) {
      Vec x = Vec::Zero(7), g;
      MprgpSettings settings;
      settings.expansion = expansion;
      const double tol = 1e-12 * qp.b.norm();
      const MprgpResult r = mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 1.05 * 50.0, qp.upper), settings, x, g, false,
                                  test::large_budget(), [&](const Vec&, const Vec&, double norm) { return norm <= tol; });
      ASSERT_EQ(r.status, SolveStatus::converged) << "seed " << seed;
      EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm()) << "seed " << seed;
      for (int i = 0; i < 7; ++i) {
        EXPECT_GE(x[i], qp.lower[i]);
        EXPECT_LE(x[i], qp.upper[i]);
      }
    }
  }
}

TEST(BoxBounds, PinnedComponentsStayAndTheRestIsSolved) {
  // l_i = u_i (a friction row whose bound is 0: an open contact). Before pinned components
  // counted as at-the-lower-bound, their chopped gradient pointed past the upper one, and
  // proportioning took zero steps until maxit (a Cattaneo-Mindlin solve did 9974).
  for (unsigned seed = 1; seed <= 4; ++seed) {
    BoxQp qp = random_box_qp(7, 50.0, seed);
    for (int i : {1, 4}) qp.upper[i] = qp.lower[i] = 0.0;
    const Vec reference = reference_solution(qp);
    Vec x = Vec::Zero(7), g;
    const double tol = 1e-12 * qp.b.norm();
    const MprgpResult r = mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 1.05 * 50.0, qp.upper), MprgpSettings{}, x, g, false,
                                  test::large_budget(), [&](const Vec&, const Vec&, double norm) { return norm <= tol; });
    ASSERT_EQ(r.status, SolveStatus::converged) << "seed " << seed;
    EXPECT_LT(r.counts.hessian, 200) << "seed " << seed;
    EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm()) << "seed " << seed;
    EXPECT_EQ(x[1], 0.0);
    EXPECT_EQ(x[4], 0.0);
  }
}

TEST(BoxBounds, EveryBoundIsReachedSomewhere) {
  // The test problems do exercise both bounds (else the test above proves little).
  int at_lower = 0, at_upper = 0;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const BoxQp qp = random_box_qp(7, 50.0, seed);
    const Vec x = reference_solution(qp);
    for (int i = 0; i < 7; ++i) {
      at_lower += x[i] == qp.lower[i];
      at_upper += x[i] == qp.upper[i];
    }
  }
  EXPECT_GT(at_lower, 3);
  EXPECT_GT(at_upper, 3);
}

TEST(BoxBounds, PreconditionedMprgpAgrees) {
  const BoxQp qp = random_box_qp(7, 100.0, 9);
  const Vec reference = reference_solution(qp);
  const Eigen::MatrixXd jacobi = qp.A.diagonal().cwiseInverse().asDiagonal();
  Vec x = Vec::Zero(7), g;
  const double tol = 1e-12 * qp.b.norm();
  const MprgpResult r = mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 105.0, qp.upper,
                                                                test::dense_operator(jacobi)),
                            MprgpSettings{}, x, g, false, test::large_budget(),
                            [&](const Vec&, const Vec&, double norm) { return norm <= tol; });
  ASSERT_EQ(r.status, SolveStatus::converged);
  EXPECT_GT(r.counts.preconditioner, 0);
  EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm());
}

TEST(BoxBounds, InfiniteUpperBoundsChangeNoIterate) {
  // A scene without friction must run exactly as before: +infinity everywhere is the
  // lower-bounded call, bit for bit.
  const test::BoundQp qp = test::manufactured_bound_qp(40, 1e3, 5, true);
  const Vec upper = Vec::Constant(40, kInfinity);
  const double tol = 1e-10 * qp.b.norm();
  const auto stop = [&](const Vec&, const Vec&, double norm) { return norm <= tol; };
  Vec x1 = Vec::Zero(40), g1, x2 = Vec::Zero(40), g2;
  const MprgpResult a = mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 1.05e3), MprgpSettings{}, x1, g1, false, test::large_budget(), stop);
  const MprgpResult b =
      mprgp_with_gradient(test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 1.05e3, upper), MprgpSettings{}, x2, g2, false, test::large_budget(), stop);
  EXPECT_EQ(a.counts.hessian, b.counts.hessian);
  EXPECT_EQ(a.counts.expansion, b.counts.expansion);
  EXPECT_EQ(a.counts.proportioning, b.counts.proportioning);
  EXPECT_TRUE(x1 == x2);
  EXPECT_TRUE(g1 == g2);
}

TEST(BoxBounds, SmalbeWithAnEqualityFindsTheEnumeratedSolution) {
  const int n = 7;
  BoxQp qp = random_box_qp(n, 30.0, 4);
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(1, n);
  C(0, 0) = 1, C(0, 1) = 1, C(0, 2) = -1;  // x0 + x1 = x2
  qp.lower.head(3).setConstant(-5), qp.upper.head(3).setConstant(5);  // the equality can be met inside the box
  const Vec reference = reference_solution(qp, C);
  const Eigen::MatrixXd Q = C.transpose() * (C * C.transpose()).inverse() * C;
  qp::Problem problem = test::bound_problem(test::dense_operator(qp.A), qp.b, qp.lower, 31.5, qp.upper);
  problem.range_projector = test::dense_operator(Q);
  Vec x = Vec::Zero(n);
  const double tol = 1e-11 * qp.b.norm();
  const SmalbeResult r = smalbe(problem, SmalbeSettings{}, x, test::large_budget(), [&](const Vec& xi, const Vec&, double gP) {
    return gP <= tol && (Q * xi).norm() <= tol;
  });
  ASSERT_EQ(r.status, SolveStatus::converged);
  EXPECT_LT((x - reference).norm(), 1e-8 * reference.norm());
  EXPECT_LT(std::abs((C * x)[0]), 1e-9);
}

}  // namespace
}  // namespace ffeti
