// The modes only bounded blocks hold and their rigid-plastic balance (qp/held_modes.h), and
// what it is for: a floating block held along the floor by Coulomb friction alone, pulled
// just under mu W, converges in a bounded number of multiplications (SMALBE's plain
// multiplier update crawled there for thousands, docs/log.md 2026-12-06).
#include "constraints/contact/obstacle.h"
#include "constraints/problem_input.h"
#include "feti/feti_problem.h"
#include "qp/held_modes.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <cmath>

namespace ffeti {
namespace {

/// Components: 0 free, 1 half-line, then discs on (2, 3) and (4, 5). Rows of C: one on the
/// half-line and a disc, one on the discs' first components alone (a slide along it), one on
/// the discs' second components and the free one.
struct Small {
  qp::ConstraintSet set;
  Eigen::MatrixXd C;
  Small() : C(Eigen::MatrixXd::Zero(3, 6)) {
    set.add_free(1);
    set.add_half_line(Vec::Zero(1));
    set.add_disc((Vec(4) << 0.5, 0, -0.25, 0).finished(), (Vec(2) << 1, 2).finished());
    C(0, 1) = 1, C(0, 2) = 2;
    C(1, 2) = 1, C(1, 4) = 1;
    C(2, 0) = 1, C(2, 3) = 1, C(2, 5) = 1;
  }
};

TEST(HeldModes, OnlyTheModesThatMoveBoundedBlocksAloneAreHeld) {
  const Small s;
  const qp::HeldModes held(s.C, s.set);
  ASSERT_EQ(held.basis().cols(), 1);
  const Vec u = held.basis().col(0);
  EXPECT_NEAR(u.norm(), 1, 1e-12);
  EXPECT_NEAR(std::abs(u[2]), std::sqrt(0.5), 1e-12);  // the slide: components 2 and 4 alike
  EXPECT_NEAR(u[2], u[4], 1e-12);
  for (const int i : {0, 1, 3, 5}) EXPECT_NEAR(u[i], 0, 1e-12) << i;
  qp::ConstraintSet free_only;
  free_only.add_free(6);
  EXPECT_TRUE(qp::HeldModes(s.C, free_only).empty());
}

TEST(HeldModes, TheBalanceTurnsTheSlipsUntilTheDiscsForcesCancelAlongTheMode) {
  // Two discs slipping across the mode and along it: the slide d along u must turn them so
  // that their forces, c - g (g_i + d_i) / ||g_i + d_i||, sum to zero along u.
  const Small s;
  const qp::HeldModes held(s.C, s.set);
  const Vec g = (Vec(6) << 0, 0, -0.3, 1, 0.1, -2).finished();
  Vec d;
  ASSERT_TRUE(held.balance(g, d));
  const Vec u = held.basis().col(0);
  EXPECT_NEAR((d - d.dot(u) * u).norm(), 0, 1e-14);  // along the mode only
  Vec x = Vec::Zero(6);
  s.set.linear_minimum(g + d, x);
  EXPECT_NEAR(u.dot(x), 0, 1e-10);
  EXPECT_GT(std::abs(d.dot(u)), 0.1);  // the plain gradient step would not get there: the forces lean far off
}

TEST(HeldModes, OnBoxesTheBalanceSlidesToTheRowThatSticks) {
  // Three boxes |x_i| <= 1 on one slide mode, the centres' pull 0.5 against them (as a
  // shifted dual's bounds: [-1.5, 0.5] etc.): piecewise linear, its maximum where a row's
  // slip changes sign, the row that sticks.
  qp::ConstraintSet set;
  set.add_box((Vec(3) << -1.5, -1, -1).finished(), (Vec(3) << 0.5, 1, 1).finished());
  const Eigen::MatrixXd C = Eigen::MatrixXd::Ones(1, 3);
  const qp::HeldModes held(C, set);
  ASSERT_FALSE(held.empty());
  const Vec g = (Vec(3) << -0.2, -0.5, -0.9).finished();  // all three slipping the same way
  Vec d;
  ASSERT_TRUE(held.balance(g, d));
  // Its maximum: row 0 reverses first (the forces 2.5 -> 0.5, still pulling), then row 1
  // stops at zero slip and sticks between rows 0 and 2's -1.5 + 1 = -0.5, within its box.
  const Vec y = g + d;
  EXPECT_NEAR(y[1], 0, 1e-9);
  EXPECT_GT(y[0], 0);
  EXPECT_LT(y[2], 0);
}

TEST(HeldModes, NothingHoldsTheModeWhenTheBoundsCannot) {
  // The centres pull harder than the discs can hold: Phi rises without end.
  qp::ConstraintSet set;
  set.add_box((Vec(2) << 2, 2).finished(), (Vec(2) << 3, 3).finished());  // 0 outside both boxes
  const qp::HeldModes held(Eigen::MatrixXd::Ones(1, 2), set);
  Vec d;
  EXPECT_FALSE(held.balance(Vec::Constant(2, 0.1), d));
}

/// The block [0, 1] x [0, 0.5] x [0, 0.25] in two halves, free, on the plane z = -0.001, every
/// node loaded by its weight and a pull of q mu times it at 30 degrees from x.
FetiResult pulled_block(double q, double mu) {
  std::vector<SubdomainInput> blocks;
  for (const double x0 : {0.0, 0.5}) {
    SubdomainInput block = solid_block(x0, {0.5, 0.5, 0.25}, {2, 2, 1}, {0, 0, 0});
    block.dirichlet_dofs.clear();
    block.dirichlet_values.clear();
    for (Eigen::Index dof = 0; dof < block.K.rows(); dof += 3) {
      block.f[dof] = q * mu * std::cos(M_PI / 6), block.f[dof + 1] = q * mu * std::sin(M_PI / 6);
      block.f[dof + 2] = -1;
    }
    blocks.push_back(std::move(block));
  }
  ContactInput contact;
  contact.slave_dofs = bottom_dofs(blocks);
  ObstacleInput& floor = contact.input_of<ObstacleInput>();
  floor.given = true;
  floor.point = {0, 0, -0.001};
  floor.normal = {0, 0, 1};
  contact.friction = mu;
  FetiSetupSettings setup;
  setup.variant = FetiVariant::tfeti;
  const FetiProblem problem(blocks, contact, setup);
  DualSolveSettings settings;
  settings.tolerance = 1e-6;
  return problem.solve(settings);
}

TEST(HeldModes, ABlockPulledJustUnderMuWConvergesInBoundedMultiplications) {
  const FetiResult held = pulled_block(0, 0.4);  // unpulled
  ASSERT_EQ(held.status, SolveStatus::converged);
  for (const double q : {0.99, 0.999}) {
    SCOPED_TRACE("q = " + std::to_string(q));
    const FetiResult r = pulled_block(q, 0.4);
    ASSERT_EQ(r.status, SolveStatus::converged) << to_string(r.status);
    EXPECT_LT(r.kkt.max(), 1e-5);
    EXPECT_GT(r.slipping_contact, 0);
    // 92 and 95 against 19 unpulled; SMALBE's plain multiplier updates alone: 184 and 807.
    EXPECT_LE(r.counts.hessian, 8 * held.counts.hessian) << "the held modes' balance did not take over SMALBE's crawl";
  }
}

}  // namespace
}  // namespace ffeti
