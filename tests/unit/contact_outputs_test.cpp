// What fetiContact reports per contact row (normal, tangents, slip, state) checked against
// answers found without it: the normal of a known plane or face, the slip recomputed from
// the displacements, the balance of forces of a body held by its contact alone; and the
// friction laws' edge cases: Tresca rows without normal contact, a zero coefficient or bound
// (exactly frictionless, refusals included).
#include "base/errors.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/node_to_segment.h"
#include "constraints/contact/obstacle.h"
#include "feti/feti_problem.h"
#include "service/statistics.h"
#include "solid_block.h"
#include "input_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace ffeti {
namespace {

constexpr double kGap = 0.001;

Point3 unit(const Point3& v) {
  const double length = std::sqrt(dot(v, v));
  return {v[0] / length, v[1] / length, v[2] / length};
}

DualSolveSettings tight() {
  DualSolveSettings s;
  s.tolerance = 1e-12;
  s.max_hessian = 200000;
  return s;
}

/// One block [0, 1] x [0, 1] x [0, 0.5] whose top face is moved by `top`, its bottom nodes
/// (every component) slaves against the plane through (0, 0, -kGap) with normal `normal`.
struct BlockOnPlane {
  std::vector<SubdomainInput> subdomains;
  ContactInput contact;
};
BlockOnPlane block_on_plane(const std::array<double, 3>& top, const Point3& normal = {0, 0, 1}) {
  BlockOnPlane b;
  b.subdomains = {solid_block(0, {1, 1, 0.5}, {2, 2, 1}, top)};
  b.contact.slave_dofs.emplace_back();
  for (int k = 0; k < static_cast<int>(b.subdomains[0].z.size()); ++k)
    if (b.subdomains[0].z[static_cast<size_t>(k)] == 0) b.contact.slave_dofs.back().push_back(k);
  b.contact.input_of<ObstacleInput>().given = true;
  b.contact.input_of<ObstacleInput>().point = {0, 0, -kGap};
  b.contact.input_of<ObstacleInput>().normal = normal;
  return b;
}

/// The displacement of the node at `at` (dofs 3k + c of solid_block).
Point3 displacement_at(const SubdomainInput& s, const Vec& u, const Point3& at) {
  for (size_t d = 0; d < s.x.size(); d += 3)
    if (std::hypot(s.x[d] - at[0], s.y[d] - at[1], s.z[d] - at[2]) < 1e-12)
      return {u[static_cast<Eigen::Index>(d)], u[static_cast<Eigen::Index>(d + 1)], u[static_cast<Eigen::Index>(d + 2)]};
  throw std::logic_error("no node there");
}

TEST(ContactOutputs, APlaneGivesItsNormalItsTangentsAndTheSlipOfItsNodes) {
  // Pressed and dragged along (1, -0.5) with a Tresca bound some rows reach: the slip of
  // each row is t_k.u of its node (the plane does not move), recomputed here from u.
  BlockOnPlane b = block_on_plane({0.004, -0.002, -0.01});
  b.contact.slip_bound = 0.4;
  const FetiProblem p(b.subdomains, b.contact);
  const FetiResult r = p.solve(tight());
  ASSERT_EQ(r.status, SolveStatus::converged);
  const std::vector<ContactMultiplier> rows = contact_multipliers(p, &r);
  ASSERT_EQ(rows.size(), 9u);
  int slipping = 0;
  for (const ContactMultiplier& row : rows) {
    EXPECT_EQ(row.normal, (Point3{0, 0, 1}));
    EXPECT_EQ(row.tangents[0], (Point3{1, 0, 0}));
    EXPECT_EQ(row.tangents[1], (Point3{0, 1, 0}));
    const Point3 u = displacement_at(p.inputs()[0], r.u[0], {row.x, row.y, row.z});
    EXPECT_NEAR(row.slip, u[0], 1e-12);
    EXPECT_NEAR(row.second_slip, u[1], 1e-12);
    if (row.state == ContactState::slip) {
      ++slipping;
      // It slips along its friction force: lambda_t = g s/|s|.
      const double s = std::hypot(row.slip, row.second_slip);
      ASSERT_GT(s, 0);
      EXPECT_NEAR(row.tangential, 0.4 * row.slip / s, 1e-6);
      EXPECT_NEAR(row.second_tangential, 0.4 * row.second_slip / s, 1e-6);
    } else {
      EXPECT_LT(std::hypot(row.slip, row.second_slip), 1e-10);
    }
  }
  EXPECT_GT(slipping, 0);
  EXPECT_EQ(slipping, r.slipping_contact);
}

TEST(ContactOutputs, TheForcesOnABodyHeldByItsContactAloneBalanceItsLoad) {
  // A floating block on a tilted plane, loaded straight down (a block on a slope of 10
  // degrees), held by Tresca friction (a bound of 1 per row, 9 in all against 3.3 of load
  // along the slope): the forces on it, lambda_n n - lambda_t1 t1 - lambda_t2 t2 per row with
  // the normals and tangents reported, sum to minus its load.
  const Point3 n = unit({0.1, -0.15, 1});
  BlockOnPlane b = block_on_plane({0, 0, 0}, n);
  SubdomainInput& s = b.subdomains[0];
  s.dirichlet_dofs.clear(), s.dirichlet_values.clear();
  for (size_t d = 2; d < s.x.size(); d += 3) s.f[static_cast<Eigen::Index>(d)] = -1;
  b.contact.slip_bound = 1;
  b.contact.input_of<ObstacleInput>().point = {0, 0, -0.2};  // below every node: the block falls onto it
  FetiSetupSettings setup;
  setup.variant = FetiVariant::tfeti;
  const FetiProblem p(b.subdomains, b.contact, setup);
  const FetiResult r = p.solve(tight());
  ASSERT_EQ(r.status, SolveStatus::converged);
  Point3 sum{0, 0, 0};
  for (const ContactMultiplier& row : contact_multipliers(p, &r)) {
    EXPECT_NEAR(dot(row.normal, n), 1, 1e-15);
    for (size_t i = 0; i < 3; ++i)
      sum[i] += row.lambda * row.normal[i] - row.tangential * row.tangents[0][i] - row.second_tangential * row.tangents[1][i];
  }
  const double load = -static_cast<double>(s.x.size() / 3);
  EXPECT_NEAR(sum[0], 0, 1e-9 * std::abs(load));
  EXPECT_NEAR(sum[1], 0, 1e-9 * std::abs(load));
  EXPECT_NEAR(sum[2], -load, 1e-9 * std::abs(load));
}

TEST(ContactOutputs, AFaceAndASegmentGiveTheirOutwardNormalsAndTheTangentsTheirSlipRowsUse) {
  // A master triangle tilted out of z = 0: its normal (b - a) x (c - a) normalized.
  const std::array<Point3, 3> corners{{{0, 0, 0}, {1, 0, 0.2}, {0, 1, -0.1}}};
  std::array<DofRef, 9> face;
  for (int k = 0; k < 9; ++k) face[static_cast<size_t>(k)] = {1, k};
  const FaceGeometry f({{{0, 0}, {0, 1}, {0, 2}}}, {0.2, 0.2, 0.5}, face, corners);
  const Point3 expected = unit({-0.2, 0.1, 1});  // (1, 0, 0.2) x (0, 1, -0.1)
  for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(f.normal()[i], expected[i], 1e-15);
  const auto rows = f.slip_rows();
  for (size_t k = 0; k < 2; ++k)
    for (size_t i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(rows[k].coefficients[i], f.tangents()[k][i]);
  // A segment from (1, 0) to (0, 1), its body on its left (below): outward (1, 1)/sqrt 2,
  // and the slip row's slave coefficients are t1 = (b - a)/|b - a| = (-n_y, n_x).
  const NodeToSegmentGeometry g({{{0, 0}, {0, 1}}}, {{{1, 0}, {1, 1}, {1, 2}, {1, 3}}}, {0.6, 0.6}, {1, 0}, {0, 1});
  EXPECT_NEAR(g.normal()[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(g.normal()[1], std::sqrt(0.5), 1e-15);
  const RowAt contact = g.row_at({}, 0), slip = g.slip_rows()[0];
  for (size_t i = 0; i < 2; ++i) {
    EXPECT_DOUBLE_EQ(contact.coefficients[i], -g.normal()[i]);  // n.(u_p - u_s) <= gap
    EXPECT_DOUBLE_EQ(slip.coefficients[i], g.tangents()[0][i]);
  }
}

TEST(ContactOutputs, ATrescaRowThatCarriesAFrictionForceIsNeverOpen) {
  // The top face lifted by 0.002 and dragged along x: the bottom leaves the plane (every
  // lambda_n = 0), but Tresca's bound acts on every row, closed or not. A large bound holds
  // the bottom (stick, no slip); a small one lets it slide at the bound (slip).
  for (const double bound : {10.0, 0.05}) {
    BlockOnPlane b = block_on_plane({0.004, 0, 0.002});
    b.contact.slip_bound = bound;
    const FetiProblem p(b.subdomains, b.contact);
    const FetiResult r = p.solve(tight());
    ASSERT_EQ(r.status, SolveStatus::converged);
    EXPECT_EQ(r.active_contact, 0);
    int carrying = 0;
    EXPECT_EQ(p.constraints().friction_rows, 18);
    for (const ContactMultiplier& row : contact_multipliers(p, &r)) {
      EXPECT_EQ(row.lambda, 0);
      const double force = std::hypot(row.tangential, row.second_tangential);
      if (force == 0) continue;
      ++carrying;
      EXPECT_NE(row.state, ContactState::open);
      if (bound == 10.0) {
        EXPECT_EQ(row.state, ContactState::stick);
        EXPECT_LT(std::hypot(row.slip, row.second_slip), 1e-10);
      } else {
        EXPECT_EQ(row.state, ContactState::slip);
        EXPECT_NEAR(force, bound, 1e-10);
      }
    }
    EXPECT_GT(carrying, 0);
    EXPECT_EQ(r.slipping_contact, bound == 10.0 ? 0 : carrying);
  }
}

TEST(ContactOutputs, AZeroCoefficientOrBoundIsExactlyFrictionless) {
  // The pressed block: a zero friction law builds no friction row and gives the frictionless
  // answer bit for bit.
  const BlockOnPlane b = block_on_plane({0.004, -0.002, -0.01});
  ASSERT_EQ(b.subdomains[0].x.size(), 54u);  // the fields below: one value per dof
  const FetiResult frictionless = FetiProblem(b.subdomains, b.contact).solve(tight());
  const std::vector<std::function<void(ContactInput&)>> zero_laws = {
      [](ContactInput& c) { c.friction = 0; },
      [](ContactInput& c) { c.slip_bound = 0; },
      [](ContactInput& c) { c.friction = 0.3, c.friction_field = {std::vector<double>(54, 0.0)}; },
      [](ContactInput& c) { c.slip_bound = 1, c.slip_bound_field = {std::vector<double>(54, 0.0)}; }};
  for (const auto& law : zero_laws) {
    BlockOnPlane with = b;
    law(with.contact);
    const FetiProblem p(with.subdomains, with.contact);
    EXPECT_EQ(p.constraints().friction_rows, 0);
    const FetiResult r = p.solve(tight());
    EXPECT_EQ(r.status, SolveStatus::converged);
    EXPECT_EQ(r.u[0], frictionless.u[0]);
  }
  // A floating block on the plane that only friction could hold sideways: with a zero law it
  // is refused as the frictionless one is, the message naming friction.
  BlockOnPlane floating = block_on_plane({0, 0, 0});
  floating.subdomains[0].dirichlet_dofs.clear(), floating.subdomains[0].dirichlet_values.clear();
  FetiSetupSettings setup;
  setup.variant = FetiVariant::tfeti;
  expect_input_error([&] { FetiProblem(floating.subdomains, floating.contact, setup); }, "meets no Dirichlet, gluing or contact row");
  for (const auto& law : zero_laws) {
    BlockOnPlane with = floating;
    law(with.contact);
    expect_input_error([&] { FetiProblem(with.subdomains, with.contact, setup); }, "friction=0, slipBound=0");
  }
}

}  // namespace
}  // namespace ffeti
