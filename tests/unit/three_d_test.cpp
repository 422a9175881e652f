// Three dimensions: the rigid modes of 3D elasticity, and constraints that tell nodes apart
// by their third coordinate.
#include "base/errors.h"
#include "constraints/constraints.h"
#include "constraints/contact/contact_linearization.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/mortar.h"
#include "feti/kernel.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <functional>
#include <string>

namespace ffeti {
namespace {

TEST(ThreeDimensions, CandidateRigidModesSpanTheElasticKernel) {
  const std::array<Eigen::Vector3d, 4> p = {Eigen::Vector3d(0.1, 0.2, 0.0), Eigen::Vector3d(1.3, 0.1, 0.2),
                                            Eigen::Vector3d(0.2, 1.1, 0.1), Eigen::Vector3d(0.3, 0.2, 0.9)};
  std::vector<double> x, y, z;
  std::vector<int> component;
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) x.push_back(p[k][0]), y.push_back(p[k][1]), z.push_back(p[k][2]), component.push_back(c);
  const Eigen::MatrixXd K = tetrahedron_stiffness(p);
  const Eigen::MatrixXd R = candidate_kernel(x, y, component, z);
  ASSERT_EQ(R.cols(), 6);
  EXPECT_LT((K * R).norm(), 1e-12 * K.norm() * R.norm());  // every candidate is a rigid motion
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(R).rank(), 6);  // six independent ones
  // And the element has no other zero-energy mode: its kernel is exactly these six.
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(K);
  EXPECT_GT(spectrum.eigenvalues()[6], 1e-6 * spectrum.eigenvalues()[11]);
  // A plane field keeps the 2D modes.
  EXPECT_EQ(candidate_kernel(x, y, std::vector<int>(12, 1)).cols(), 3);
}

/// A "subdomain" whose dofs sit at the corners of the unit box [x0, x0+1] x [0,1]^2: four
/// corners share x and y with another four and differ only in z.
SubdomainInput box_corners(double x0) {
  SubdomainInput s;
  for (int k = 0; k < 8; ++k) s.x.push_back(x0 + (k & 1)), s.y.push_back((k >> 1) & 1), s.z.push_back((k >> 2) & 1);
  s.K = SparseMatrix(8, 8);
  s.K.edit().setIdentity();
  s.f = Vec::Zero(8);
  return s;
}

TEST(ThreeDimensions, GluingTellsNodesApartByZ) {
  // Two boxes of one body side by side: their face x = 1 shares four nodes, glued by four
  // rows. Read in the plane, the nodes (1, y, 0) and (1, y, 1) would coincide.
  const Constraints c = build_constraints({box_corners(0), box_corners(1)}, ContactInput{}, FetiVariant::feti1);
  EXPECT_EQ(c.count(RowKind::gluing), 4);
  std::vector<SubdomainInput> plane = {box_corners(0), box_corners(1)};
  for (SubdomainInput& s : plane) s.z.clear();
  EXPECT_THROW(build_constraints(plane, ContactInput{}, FetiVariant::feti1), InputError);
}

TEST(ThreeDimensions, ClosestPointOfATriangleInEveryRegion) {
  // Against a brute-force search over a fine barycentric grid, for points beyond each corner,
  // each edge and above the face.
  const Point3 a{0, 0, 0}, b{2, 0, 0.5}, c{0.3, 1.5, -0.2};
  const Point3 points[] = {{-1, -1, 0.3}, {3, -0.5, 1}, {0, 3, 0}, {1, -1, 0.2}, {-1, 0.7, 0}, {1.5, 1.5, 0.1},
                           {0.6, 0.4, 2}, {0.6, 0.4, -2}};
  for (const Point3& s : points) {
    const std::array<double, 3> w = closest_point_weights(s, a, b, c);
    const auto at = [&](double wa, double wb, double wc) {
      return Point3{wa * a[0] + wb * b[0] + wc * c[0], wa * a[1] + wb * b[1] + wc * c[1], wa * a[2] + wb * b[2] + wc * c[2]};
    };
    const auto distance = [&](const Point3& p) {
      return std::sqrt((p[0] - s[0]) * (p[0] - s[0]) + (p[1] - s[1]) * (p[1] - s[1]) + (p[2] - s[2]) * (p[2] - s[2]));
    };
    double best = INFINITY;
    constexpr int kSteps = 400;
    for (int i = 0; i <= kSteps; ++i)
      for (int j = 0; i + j <= kSteps; ++j)
        best = std::min(best, distance(at(1.0 * (kSteps - i - j) / kSteps, 1.0 * i / kSteps, 1.0 * j / kSteps)));
    EXPECT_NEAR(w[0] + w[1] + w[2], 1.0, 1e-14);
    for (double weight : w) EXPECT_GE(weight, -1e-14);
    EXPECT_LE(distance(at(w[0], w[1], w[2])), best + 1e-12);       // no grid point is nearer
    EXPECT_GE(distance(at(w[0], w[1], w[2])), best - 1e-2);         // and it is the grid's optimum, to its spacing
  }
}

/// A 3D vector-field subdomain of the given nodes (dofs 3k + c); K is irrelevant to the
/// constraints.
SubdomainInput vector_nodes3(const std::vector<std::array<double, 3>>& nodes, int body) {
  SubdomainInput s;
  for (const auto& node : nodes)
    for (int c = 0; c < 3; ++c)
      s.x.push_back(node[0]), s.y.push_back(node[1]), s.z.push_back(node[2]), s.component.push_back(c);
  const auto n = static_cast<Eigen::Index>(s.x.size());
  s.K = SparseMatrix(n, n);
  s.K.edit().setIdentity();
  s.f = Vec::Zero(n);
  s.body = body;
  return s;
}

TEST(ThreeDimensions, MortarRowsSeeTheNearestMasterLayerOnly) {
  // A slave triangle (body 0, edges 1 and 1.4) on the top face of body 1, with body 2's top
  // face three units further down, facing it too, and no search distance given: the rows take body 1's face
  // alone (they once averaged both layers' constraints), with the gap 0 of touching faces.
  const std::vector<SubdomainInput> subs = {vector_nodes3({{0, 0, 1}, {0, 1, 1}, {1, 0, 1}}, 0),
                                            vector_nodes3({{-1, -1, 1}, {3, -1, 1}, {-1, 3, 1}}, 1),
                                            vector_nodes3({{-1, -1, -2}, {3, -1, -2}, {-1, 3, -2}}, 2)};
  ContactInput contact;
  contact.input_of<MortarInput>().slave_faces = {{{0, 1, 2, 3, 4, 5, 6, 7, 8}}, {}, {}};  // (b - a) x (c - a) = -z: out of body 0
  contact.input_of<NodeToFaceInput>().faces = {{}, {{0, 1, 2, 3, 4, 5, 6, 7, 8}}, {{0, 1, 2, 3, 4, 5, 6, 7, 8}}};
  const Constraints c = build_constraints(subs, contact, FetiVariant::tfeti);
  ASSERT_EQ(c.count(RowKind::contact), 3);
  for (int row = 0; row < c.rows(); ++row) {
    if (c.kind[static_cast<size_t>(row)] != RowKind::contact) continue;
    EXPECT_NEAR(c.rhs[static_cast<size_t>(row)], 0.0, 1e-14);
    for (int k = c.row_start[static_cast<size_t>(row)]; k < c.row_start[static_cast<size_t>(row) + 1]; ++k)
      EXPECT_NE(c.entries[static_cast<size_t>(k)].subdomain, 2) << "row " << row << " reaches the far layer";
  }
}

TEST(ThreeDimensions, NodeToFaceSlaveOutOfReachGetsNoRow) {
  // As node to segment in the plane: a slave node farther than contactRadius from every
  // master face of another body gets no row (no contact possible there), not an error;
  // but no row for any slave is one.
  // Master face (0,0,0), (2,0,0), (0,2,0) of body 0, normal +z; slaves of body 1 at
  // height 0.1 above it and at (5, 5, 0.1), 4.95 from its nearest point (1, 1, 0).
  const std::vector<SubdomainInput> subs = {vector_nodes3({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, 0),
                                            vector_nodes3({{0.5, 0.5, 0.1}, {5, 5, 0.1}}, 1)};
  ContactInput contact;
  contact.slave_dofs = {{}, {0, 1, 2, 3, 4, 5}};
  contact.input_of<NodeToFaceInput>().faces = {{{0, 1, 2, 3, 4, 5, 6, 7, 8}}, {}};
  const Constraints all = build_constraints(subs, contact, FetiVariant::tfeti);
  ASSERT_EQ(all.count(RowKind::contact), 2);  // no reach given: every slave has a row
  contact.search_distance = 1;
  const Constraints near = build_constraints(subs, contact, FetiVariant::tfeti);
  ASSERT_EQ(near.count(RowKind::contact), 1);
  int row = 0;
  while (near.kind[static_cast<size_t>(row)] != RowKind::contact) ++row;
  EXPECT_NEAR(near.rhs[static_cast<size_t>(row)], 0.1, 1e-14);  // the near slave's gap
  bool near_slave = false;
  for (int k = near.row_start[static_cast<size_t>(row)]; k < near.row_start[static_cast<size_t>(row) + 1]; ++k)
    near_slave |= near.entries[static_cast<size_t>(k)].subdomain == 1 && near.entries[static_cast<size_t>(k)].dof == 2;
  EXPECT_TRUE(near_slave) << "the row is the near slave's (its z dof, 2)";
  // Both beyond: no contact row at all, the contact asked for cannot happen: an error that
  // names the faces and the radius.
  contact.search_distance = 0.05;
  try {
    build_constraints(subs, contact, FetiVariant::tfeti);
    ADD_FAILURE() << "no error for a contact without any row";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contactFaces"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("contactRadius"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ffeti
