#include "constraints/constraints.h"
#include "constraints/contact/node_to_node.h"
#include "constraints/contact/node_to_segment.h"
#include "base/errors.h"
#include "constraints/contact/obstacle.h"
#include "membrane_model.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace ffeti {
namespace {

/// B as a dense matrix over the concatenated subdomain dofs.
Eigen::MatrixXd dense_B(const Constraints& c, const std::vector<SubdomainInput>& subs) {
  std::vector<int> offset{0};
  for (const auto& s : subs) offset.push_back(offset.back() + static_cast<int>(s.K.rows()));
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(c.rows(), offset.back());
  for (int i = 0; i < c.rows(); ++i)
    for (int k = c.row_start[i]; k < c.row_start[i + 1]; ++k)
      B(i, offset[c.entries[k].subdomain] + c.entries[k].dof) += c.entries[k].coefficient;
  return B;
}

TEST(Constraints, SeedCountsForFeti1) {
  // n = 8, N = 2 per body: per body 1 interior vertical + 1 horizontal line of 9 nodes,
  // 1 cross point: 9 + 9 - 1 = 17 interface nodes, 16 with 2 copies and 1 with 4 -> 19 rows.
  // FETI-1 drops the row on x = 0 of body 0 (both copies fixed): 18 + 19 gluing rows,
  // plus one contact row per physical node on x = 1: 9.
  const auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
  const Constraints c = build_constraints(subs, test::membrane_contact(subs), FetiVariant::feti1);
  EXPECT_EQ(c.count(RowKind::gluing), 18 + 19);
  EXPECT_EQ(c.count(RowKind::contact), 9);
  EXPECT_EQ(c.count(RowKind::dirichlet), 0);
  EXPECT_EQ(c.equality_rows, 37);
  const Eigen::MatrixXd B = dense_B(c, subs);
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(B).rank(), c.rows());  // full row rank
}

TEST(Constraints, TotalFetiAddsDirichletRowsAndStaysFullRank) {
  const auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
  const Constraints c = build_constraints(subs, test::membrane_contact(subs), FetiVariant::tfeti);
  EXPECT_EQ(c.count(RowKind::dirichlet), 10);  // 9 nodes on x = 0: two subdomains of 5
  EXPECT_EQ(c.count(RowKind::gluing), 18 + 19);
  const Eigen::MatrixXd B = dense_B(c, subs);
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(B).rank(), c.rows());
}

TEST(Constraints, GluingRowsVanishOnContinuousFields) {
  const auto subs = test::membrane_subdomains(test::membrane_options(12, 3));
  const Constraints c = build_constraints(subs, test::membrane_contact(subs), FetiVariant::tfeti);
  // u = x + 2y on every subdomain: every gluing row is satisfied exactly.
  std::vector<LocalConstraints> local;
  std::vector<Eigen::Index> sizes;
  for (const auto& s : subs) sizes.push_back(s.K.rows());
  local = split_by_subdomain(c, sizes);
  for (int i = 0; i < c.rows(); ++i) {
    if (c.kind[i] != RowKind::gluing) continue;
    double value = 0;
    for (int k = c.row_start[i]; k < c.row_start[i + 1]; ++k) {
      const auto& e = c.entries[k];
      value += e.coefficient * (subs[e.subdomain].x[e.dof] + 2 * subs[e.subdomain].y[e.dof]);
    }
    EXPECT_NEAR(value, 0.0, 1e-12);
  }
}

TEST(Constraints, ContactSlaveWithoutMasterIsAnInputError) {
  auto subs = test::membrane_subdomains(test::membrane_options(4, 1));
  ContactInput contact = test::membrane_contact(subs);
  contact.input_of<NodeToNodeInput>().masters[1].pop_back();  // one slave loses its partner
  try {
    build_constraints(subs, contact, FetiVariant::feti1);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contactSlave[0]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ffeti

namespace ffeti {
namespace {

/// A 2D vector-field subdomain whose nodes are given; K is irrelevant to the constraints.
SubdomainInput vector_nodes(std::vector<std::array<double, 2>> nodes, int body) {
  SubdomainInput s;
  for (const auto& node : nodes)
    for (int c = 0; c < 2; ++c) s.x.push_back(node[0]), s.y.push_back(node[1]), s.component.push_back(c);
  const auto n = static_cast<Eigen::Index>(s.x.size());
  s.K.edit().resize(n, n);
  s.K.edit().setIdentity();
  s.f = Vec::Zero(n);
  s.body = body;
  return s;
}

double entry(const Constraints& c, int row, int subdomain, int dof) {
  for (int k = c.row_start[row]; k < c.row_start[row + 1]; ++k)
    if (c.entries[k].subdomain == subdomain && c.entries[k].dof == dof) return c.entries[k].coefficient;
  return 0.0;
}

TEST(Constraints, NodeToSegmentRowHasProjectionWeightsNormalAndGap) {
  // Master segment from a = (2, 0) to b = (0, 0), its body below (on the left of a -> b), so
  // the outward normal is +y; a slave node of another body at (0.5, 0.1) projects at
  // xi = 0.75 with a gap of 0.1.
  const std::vector<SubdomainInput> subs = {vector_nodes({{0, 0}, {2, 0}}, 0), vector_nodes({{0.5, 0.1}}, 1)};
  ContactInput contact;
  contact.slave_dofs = {{}, {0, 1}};
  contact.input_of<NodeToSegmentInput>().segments = {{{2, 3, 0, 1}}, {}};
  const Constraints c = build_constraints(subs, contact, FetiVariant::tfeti);
  ASSERT_EQ(c.rows(), 1);
  EXPECT_EQ(c.kind[0], RowKind::contact);
  EXPECT_NEAR(c.rhs[0], 0.1, 1e-14);
  EXPECT_NEAR(entry(c, 0, 1, 1), -1.0, 1e-14);  // -n.u_slave
  EXPECT_NEAR(entry(c, 0, 1, 0), 0.0, 1e-14);
  EXPECT_NEAR(entry(c, 0, 0, 3), 0.25, 1e-14);  // (1 - xi) n.u_a
  EXPECT_NEAR(entry(c, 0, 0, 1), 0.75, 1e-14);  // xi n.u_b
  EXPECT_NEAR(entry(c, 0, 0, 0) + entry(c, 0, 0, 2), 0.0, 1e-14);

  // Its only slave beyond contactRadius: no contact row at all, an error naming the radius.
  contact.search_distance = 0.05;
  EXPECT_THROW(build_constraints(subs, contact, FetiVariant::tfeti), InputError);
}

TEST(Constraints, NodeToSegmentPicksTheNearestSegmentAsAFullSearchWould) {
  // A wavy master polyline of 400 segments on body 0, 300 slaves of body 1 scattered around
  // it (some far away, some exactly on its vertices), with and without a reach: the grid
  // search finds a segment as near as a search over all segments does, and no row beyond
  // the reach.
  std::vector<std::array<double, 2>> polyline, slaves;
  for (int i = 0; i <= 400; ++i) polyline.push_back({0.01 * i, 0.05 * std::sin(0.3 * i)});
  unsigned state = 7;
  const auto random = [&] { state = state * 1103515245u + 12345u; return (state >> 8) % 100000 / 100000.0; };
  for (int i = 0; i < 300; ++i) {
    if (i % 10 == 0) slaves.push_back(polyline[static_cast<size_t>(4 * i / 3)]);
    else slaves.push_back({-0.5 + 5 * random(), -1 + 2 * random() * (i % 7 == 0 ? 5 : 0.2)});
  }
  const std::vector<SubdomainInput> subs = {vector_nodes(polyline, 0), vector_nodes(slaves, 1)};
  ContactInput contact;
  contact.input_of<NodeToSegmentInput>().segments.resize(2), contact.slave_dofs.resize(2);
  for (int i = 0; i < 400; ++i) contact.input_of<NodeToSegmentInput>().segments[0].push_back({2 * (i + 1), 2 * (i + 1) + 1, 2 * i, 2 * i + 1});
  for (int k = 0; k < static_cast<int>(slaves.size()); ++k) contact.slave_dofs[1].insert(contact.slave_dofs[1].end(), {2 * k, 2 * k + 1});
  for (const double reach : {1e300, 0.07}) {
    contact.search_distance = reach;
    const Constraints c = build_constraints(subs, contact, FetiVariant::tfeti);
    std::map<int, int> master_of_slave;  // slave node -> the first node of its segment's b end
    for (const auto& row : c.geometry) {
      const auto& g = dynamic_cast<const NodeToSegmentGeometry&>(*row);
      master_of_slave[g.slave[0][1] / 2] = g.master[2][1] / 2;
    }
    int rows = 0;
    for (size_t k = 0; k < slaves.size(); ++k) {
      // Segment i runs from node i + 1 to node i.
      const auto distance = [&](int i) {
        const auto& a = polyline[static_cast<size_t>(i + 1)];
        const auto& b = polyline[static_cast<size_t>(i)];
        const double dx = b[0] - a[0], dy = b[1] - a[1];
        const double xi = std::clamp(((slaves[k][0] - a[0]) * dx + (slaves[k][1] - a[1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
        return std::hypot(slaves[k][0] - a[0] - xi * dx, slaves[k][1] - a[1] - xi * dy);
      };
      double best_distance = reach;
      for (int i = 0; i < 400; ++i) best_distance = std::min(best_distance, distance(i));  // the full search
      if (best_distance >= reach) continue;
      ASSERT_EQ(master_of_slave.count(static_cast<int>(k)), 1u) << "slave " << k;
      // The same distance (two segments meeting at the nearest vertex are equally near).
      EXPECT_NEAR(distance(master_of_slave[static_cast<int>(k)]), best_distance, 1e-12) << "slave " << k;
      ++rows;
    }
    EXPECT_EQ(rows, c.rows());
    EXPECT_GT(rows, reach < 1 ? 30 : 299);
  }
}

TEST(Constraints, RigidObstacleRowUsesTheUnitNormal) {
  const std::vector<SubdomainInput> subs = {vector_nodes({{0.5, 0.1}, {1.0, 0.3}}, 0)};
  ContactInput contact;
  contact.slave_dofs = {{0, 1, 2, 3}};
  contact.input_of<ObstacleInput>().given = true;
  contact.input_of<ObstacleInput>().point = {0.0, -1.0};
  contact.input_of<ObstacleInput>().normal = {0.0, 2.0};  // not unit: normalized
  const Constraints c = build_constraints(subs, contact, FetiVariant::tfeti);
  ASSERT_EQ(c.rows(), 2);
  EXPECT_NEAR(c.rhs[0], 1.1, 1e-14);
  EXPECT_NEAR(c.rhs[1], 1.3, 1e-14);
  EXPECT_NEAR(entry(c, 0, 0, 1), -1.0, 1e-14);
  EXPECT_NEAR(entry(c, 1, 0, 3), -1.0, 1e-14);
}

TEST(Constraints, SlaveNodeNeedsBothComponents) {
  const std::vector<SubdomainInput> subs = {vector_nodes({{0.5, 0.1}}, 0)};
  ContactInput contact;
  contact.slave_dofs = {{0}};
  contact.input_of<ObstacleInput>().given = true;
  EXPECT_THROW(build_constraints(subs, contact, FetiVariant::tfeti), InputError);
}

}  // namespace
}  // namespace ffeti
