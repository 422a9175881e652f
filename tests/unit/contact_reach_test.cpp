// A contact radius so small that most slaves get no row (issue 37, item 6): the solve
// converged with slaves passing through the master surface, without a word. The slaves
// left without a row are now checked after the solve: counted, their deepest penetration
// reported, and none reported when the radius reaches every slave.
#include "feti/feti_problem.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/node_to_segment.h"
#include "service/statistics.h"
#include "membrane_model.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <string>
#include <utility>

namespace ffeti {
namespace {

constexpr int kCells = 2;

/// Body 0: the block [0, 1]^2 x [0, 0.5], its top pushed down by 0.01; body 1: a block
/// below whose top face (fixed) falls from z = -0.001 at x = 0 to -0.003 at x = 1, the
/// master surface (normals +z up to the tilt). The upper block's bottom nodes are slaves.
std::pair<std::vector<SubdomainInput>, ContactInput> pressed_on_a_slope() {
  SubdomainInput upper = solid_block(0, {1, 1, 0.5}, {kCells, kCells, 1}, {0, 0, -0.01});
  SubdomainInput lower = solid_block(0, {1, 1, 0.5}, {kCells, kCells, 1}, {0, 0, 0});
  for (size_t k = 0; k < lower.z.size(); ++k) lower.z[k] -= 0.501 + (lower.z[k] > 0.25 ? 0.002 * lower.x[k] : 0.0);
  lower.body = 1;
  ContactInput contact;
  contact.slave_dofs = {{}, {}};
  for (int k = 0; k < static_cast<int>(upper.z.size()); ++k)
    if (upper.z[static_cast<size_t>(k)] == 0) contact.slave_dofs[0].push_back(k);
  const auto node = [](int i, int j) { return i + (kCells + 1) * (j + (kCells + 1)); };  // top layer
  std::vector<std::array<int, 9>> faces;
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i)
      for (const std::array<int, 3>& t : {std::array<int, 3>{node(i, j), node(i + 1, j), node(i + 1, j + 1)},
                                          std::array<int, 3>{node(i, j), node(i + 1, j + 1), node(i, j + 1)}}) {
        std::array<int, 9> face{};
        for (size_t corner = 0; corner < 3; ++corner)
          for (int c = 0; c < 3; ++c) face[3 * corner + static_cast<size_t>(c)] = 3 * t[corner] + c;
        faces.push_back(face);
      }
  contact.input_of<NodeToFaceInput>().faces = {{}, faces};
  return {{std::move(upper), std::move(lower)}, contact};
}

double statistic(const FetiProblem& problem, const FetiResult& result, const std::string& key) {
  for (const auto& [name, value] : statistics(problem, &result))
    if (name == key) return value;
  ADD_FAILURE() << "no statistic " << key;
  return 0;
}

TEST(ContactReach, SlavesLeftWithoutARowAreCheckedForPenetration) {
  auto [subs, contact] = pressed_on_a_slope();
  // Every slave within reach: no slave is watched, and none passes through.
  const FetiProblem all(subs, contact, FetiSetupSettings{});
  const FetiResult reached = all.solve();
  ASSERT_EQ(reached.status, SolveStatus::converged);
  EXPECT_EQ(statistic(all, reached, "beyond_reach"), 0);
  EXPECT_EQ(reached.beyond_reach.penetrating, 0);
  EXPECT_EQ(reached.beyond_reach.warning(), "");
  double pushed = 0;
  for (const ContactMultiplier& row : contact_multipliers(all, &reached)) pushed += row.lambda;
  EXPECT_GT(pushed, 0) << "fetiContact's forces of the rows that carry the block";
  // A radius of 0.0015 reaches the column x = 0 only (gap 0.001; 0.002 and 0.003 beyond):
  // the 6 others get no row and are pushed 0.01 down onto a master 0.002-0.003 below.
  contact.search_distance = 0.0015;
  const FetiProblem near(subs, contact, FetiSetupSettings{});
  const FetiResult result = near.solve();
  ASSERT_EQ(result.status, SolveStatus::converged);  // the QP without those rows is solved
  EXPECT_EQ(near.constraints().count(RowKind::contact), kCells + 1);
  EXPECT_EQ(statistic(near, result, "beyond_reach"), 2 * (kCells + 1));
  EXPECT_EQ(statistic(near, result, "beyond_reach_penetrating"), 2 * (kCells + 1));
  // The deepest: the slave at x = 1 moves down by about the top's 0.01 less the block's
  // squeeze, its master 0.003 below: several millimetres, recomputed from u here.
  double deepest = 0;
  for (size_t k = 0; k < subs[0].z.size(); k += 3)
    if (subs[0].z[k] == 0) {
      const double below = -(result.u[0][static_cast<Eigen::Index>(k) + 2]) - (0.001 + 0.002 * subs[0].x[k]);
      deepest = std::max(deepest, below);
    }
  EXPECT_GT(deepest, 0.003);
  EXPECT_NEAR(result.beyond_reach.depth, deepest, 1e-3 * deepest);
  EXPECT_NEAR(statistic(near, result, "beyond_reach_depth"), deepest, 1e-3 * deepest);
  const std::string warning = result.beyond_reach.warning();
  EXPECT_NE(warning.find("6 of the 6 slave nodes"), std::string::npos) << warning;
  EXPECT_NE(warning.find("contactRadius"), std::string::npos) << warning;
}

TEST(ContactReach, NodeToSegmentSlavesBeyondTheRadiusToo) {
  // The plane: a 2-component field on two rectangles (8 x 8 cells below, 5 x 7 above it,
  // non-matching), the lower one's top edge the master, tilted so that its gap to the
  // slaves falls from 0.02 at x = 0 to 0.01 at x = 1; the upper body's top pushed down by
  // 0.05. A radius of 0.015 reaches the slaves at x > 0.5 only.
  const auto zero = [](double, double) { return 0.0; };
  std::vector<SubdomainInput> subs = {test::two_components(test::p1_rectangle(0, 0, 1, 1, 8, 8, 1.0, zero, 0)),
                                      test::two_components(test::p1_rectangle(0.05, 1.02, 0.9, 1, 5, 7, 1.0, zero, 1))};
  for (size_t k = 0; k < subs[0].y.size(); ++k) subs[0].y[k] += 0.01 * subs[0].x[k] * subs[0].y[k];
  ContactInput contact;
  contact.slave_dofs.resize(2), contact.input_of<NodeToSegmentInput>().segments.resize(2);
  for (size_t s = 0; s < 2; ++s)
    for (int k = 0; k < static_cast<int>(subs[s].x.size()); ++k) {
      const bool bottom = s == 0 && subs[s].y[static_cast<size_t>(k)] < 1e-12;
      const bool top = s == 1 && subs[s].y[static_cast<size_t>(k)] > 2.02 - 1e-12;
      if (bottom || top) {
        subs[s].dirichlet_dofs.push_back(k);
        subs[s].dirichlet_values.push_back(top && subs[s].component[static_cast<size_t>(k)] == 1 ? -0.05 : 0.0);
      }
      if (s == 1 && subs[s].y[static_cast<size_t>(k)] < 1.02 + 1e-12) contact.slave_dofs[1].push_back(k);
    }
  for (int i = 8; i > 0; --i)  // the lower body's top edge (nodes 72 + i), right to left: the body on the left
    contact.input_of<NodeToSegmentInput>().segments[0].push_back({2 * (72 + i), 2 * (72 + i) + 1, 2 * (71 + i), 2 * (71 + i) + 1});
  contact.search_distance = 0.015;
  const FetiProblem problem(subs, contact, FetiSetupSettings{});
  const FetiResult result = problem.solve();
  ASSERT_EQ(result.status, SolveStatus::converged);
  const int rows = problem.constraints().count(RowKind::contact), watched = result.beyond_reach.watched;
  EXPECT_GT(rows, 0);
  EXPECT_GT(watched, 0);
  EXPECT_EQ(rows + watched, 6);  // the upper body's 6 bottom nodes, all over the master edge
  // The watched slaves' depth behind the master edge, recomputed here from u: how far the
  // moved slave lies below the moved edge between nodes a (right) and b (left) under it,
  // along the edge's upward normal n = (dy, -dx) / length.
  const auto displaced = [&](size_t s, size_t node) {
    return std::array<double, 2>{subs[s].x[2 * node] + result.u[s][static_cast<Eigen::Index>(2 * node)],
                                 subs[s].y[2 * node] + result.u[s][static_cast<Eigen::Index>(2 * node + 1)]};
  };
  double deepest = 0;
  int below = 0;
  for (size_t node = 0; 2 * node < subs[1].x.size(); ++node) {
    const double x = subs[1].x[2 * node];
    if (subs[1].y[2 * node] > 1.02 + 1e-12 || x > 0.5) continue;  // not a watched slave
    const auto i = static_cast<size_t>(std::floor(x * 8));   // the lower edge's cell under it
    const std::array<double, 2> a = displaced(0, 72 + i + 1), b = displaced(0, 72 + i), q = displaced(1, node);
    const double dx = b[0] - a[0], dy = b[1] - a[1], length = std::hypot(dx, dy);
    const double depth = -(dy * (q[0] - a[0]) - dx * (q[1] - a[1])) / length;  // n = (dy, -dx) / length
    below += depth > 0, deepest = std::max(deepest, depth);
  }
  EXPECT_EQ(result.beyond_reach.penetrating, below);
  EXPECT_GT(below, 0);
  // The rows are linearized about the set-up (their normal does not turn with the edge):
  // the same depth to the edge's small rotation.
  EXPECT_NEAR(result.beyond_reach.depth, deepest, 0.02 * deepest);
}

}  // namespace
}  // namespace ffeti
