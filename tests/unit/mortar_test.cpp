// The mortar integrals of one slave and one master triangle (feti/mortar_integration.h)
// against closed forms: the mass matrix, linear fields reproduced, clipped areas.
#include "constraints/contact/mortar_integration.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ffeti {
namespace {

constexpr double kTight = 1e-14;

// The slave in the plane z = 0, its outward normal +z; masters above it face down.
const Triangle3 kSlave{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};

TEST(Mortar, SlaveInsideAParallelMasterGivesTheMassMatrixAndTheGap) {
  const double h = 0.1;
  const Triangle3 master{{{-1, -1, h}, {-1, 3, h}, {3, -1, h}}};  // (b - a) x (c - a) points down
  const MortarIntegrals in = integrate_mortar_pair(kSlave, master);
  const double area = 0.5;
  EXPECT_NEAR(in.area, area, kTight);
  for (size_t j = 0; j < 3; ++j) {
    double row = 0, master_row = 0;
    for (size_t k = 0; k < 3; ++k) {
      EXPECT_NEAR(in.D[j][k], area / 12 * (j == k ? 2 : 1), kTight);  // the P1 mass matrix
      row += in.D[j][k], master_row += in.M[j][k];
    }
    EXPECT_NEAR(master_row, row, kTight);  // both sides' shape functions sum to 1
    // The master's shape functions reproduce its points: sum_m M_jm x_m = int phi_j x_m(x),
    // and x_m(x) = x + h e_z.
    for (size_t d = 0; d < 3; ++d) {
      double interpolated = 0, expected = 0;
      for (size_t m = 0; m < 3; ++m) interpolated += in.M[j][m] * master[m][d];
      for (size_t k = 0; k < 3; ++k) expected += in.D[j][k] * kSlave[k][d];
      if (d == 2) expected += h * area / 3;
      EXPECT_NEAR(interpolated, expected, kTight);
      EXPECT_NEAR(in.G[j][d], d == 2 ? -h * area / 3 : 0.0, kTight);
    }
  }
}

TEST(Mortar, PartialOverlapIsClippedOnTheMastersPlane) {
  // A tilted master whose edge x = 0.5, z = 0.2 runs across the slave; the slave is
  // projected on the master's plane along its normal (0.2, 0, 3.5)/|.| (pointing down), so
  // the slave's covered part is x <= 0.5 - 0.2 * 0.2 / 3.5 and it counts with the cosine
  // of the tilt, the plane's area.
  const Triangle3 master{{{0.5, -1, 0.2}, {-3, -1, 0.4}, {0.5, 3, 0.2}}};
  const MortarIntegrals in = integrate_mortar_pair(kSlave, master);
  const double x0 = 0.5 - 0.04 / 3.5, cosine = 3.5 / std::hypot(3.5, 0.2);
  const double covered = (0.5 - (1 - x0) * (1 - x0) / 2) * cosine;
  EXPECT_NEAR(in.area, covered, kTight);
  EXPECT_NEAR(in.normal[0], -0.2 / std::hypot(3.5, 0.2), kTight);
  EXPECT_NEAR(in.normal[2], -cosine, kTight);
  double total = 0, master_total = 0;
  for (size_t j = 0; j < 3; ++j)
    for (size_t k = 0; k < 3; ++k) total += in.D[j][k], master_total += in.M[j][k];
  EXPECT_NEAR(total, covered, kTight);
  EXPECT_NEAR(master_total, covered, kTight);
  // The corner (1, 0) lies outside: its shape function is at most 0.5 on the covered part.
  double corner_weight = 0;
  for (double v : in.D[1]) corner_weight += v;
  EXPECT_GT(corner_weight, 0);
  EXPECT_LT(corner_weight, 0.5 * covered);
}

TEST(Mortar, DisjointOrEdgeOnSlavesCoverNothing) {
  const Triangle3 away{{{2, 2, 0.1}, {2, 3, 0.1}, {3, 2, 0.1}}};
  EXPECT_EQ(integrate_mortar_pair(kSlave, away).area, 0);
  const Triangle3 master_below{{{-1, -1, -0.1}, {3, -1, -0.1}, {-1, 3, -0.1}}};
  const Triangle3 edge_on{{{0.2, 0.2, 0}, {0.4, 0.2, 0}, {0.3, 0.2, 1}}};
  EXPECT_EQ(integrate_mortar_pair(edge_on, master_below).area, 0);
}

}  // namespace
}  // namespace ffeti
