// A mortar row's motion derivative (MortarGeometry::row_at differenced as the sensitivity
// analysis does, contact_derivative.cpp) against closed forms, and its refusal of motions
// along which the row has a kink (MortarGeometry::unverified_motion).
#include "constraints/contact/mortar.h"
#include "constraints/contact/mortar_integration.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace ffeti {
namespace {

constexpr double kHeight = 0.1;  // the masters' plane z = kHeight, facing down

FaceRecord face(int subdomain, int body, const Triangle3& corners, bool slave) {
  FaceRecord f{subdomain, body, {}, corners, slave};
  for (int k = 0; k < 9; ++k) f.dofs[static_cast<size_t>(k)] = k;
  return f;
}

/// A master triangle facing down whose edge from (c, 5) to (c, -5) bounds it; it lies on
/// the side x < c (left) or x > c, its far corner `rise` above its plane (0: flat).
Triangle3 half_plane(double c, bool left, double rise = 0) {
  if (left) return {{{c, 5, kHeight}, {c, -5, kHeight}, {c - 10, 0, kHeight + rise}}};
  return {{{c, -5, kHeight}, {c, 5, kHeight}, {c + 10, 0, kHeight + rise}}};
}

/// The row of the slave's corner `corner` over the given masters (subdomains 1, 2, ...).
MortarGeometry row_of(const Triangle3& slave, const std::vector<Triangle3>& masters, int corner = 0) {
  auto surface = std::make_shared<MortarSurface>();
  surface->slaves.push_back(face(0, 0, slave, true));
  std::vector<MortarPair> pairs;
  for (size_t m = 0; m < masters.size(); ++m) {
    surface->masters.push_back(face(static_cast<int>(m) + 1, 1, masters[m], false));
    pairs.push_back({0, static_cast<int>(m), corner});
  }
  return MortarGeometry({0, 3 * corner}, slave[static_cast<size_t>(corner)], surface, pairs, 1e-9, {}, {0, 0, -1});
}

/// The velocities of g's moving nodes: `slave` for the slave face's (subdomain 0), `master`
/// for the masters'.
NodeMotion motion(const MortarGeometry& g, const Point3& slave, const Point3& master) {
  const std::vector<DofRef> nodes = g.moving_nodes();
  NodeMotion v(nodes.size());
  for (size_t k = 0; k < nodes.size(); ++k) v[k] = nodes[k][0] == 0 ? slave : master;
  return v;
}

/// The derivative of the row along v, as contact_row_derivatives takes it.
RowAt derivative(const MortarGeometry& g, const NodeMotion& v) {
  const double step = difference_step(g, v);
  const RowAt plus = g.row_at(v, step), minus = g.row_at(v, -step);
  RowAt d{plus.dofs, {}, (plus.gap - minus.gap) / (2 * step)};
  for (size_t k = 0; k < plus.dofs.size(); ++k) d.coefficients.push_back((plus.coefficients[k] - minus.coefficients[k]) / (2 * step));
  return d;
}

/// int_0^1 f by 6-point Gauss-Legendre (exact to degree 11).
double gauss(const std::function<double(double)>& f) {
  static const double x[3] = {0.2386191860831909, 0.6612093864662645, 0.9324695142031521};
  static const double w[3] = {0.4679139345726910, 0.3607615730481386, 0.1713244923791704};
  double sum = 0;
  for (size_t i = 0; i < 3; ++i) sum += w[i] / 2 * (f(0.5 - x[i] / 2) + f(0.5 + x[i] / 2));
  return sum;
}

TEST(MortarMotion, AMasterEdgeSweepingAcrossTheSlaveGivesTheLeibnizDerivativeOfTheIntegrals) {
  // The slave (0, 0), (1, 0), (0, 1), tilted (z = 0.1 x + 0.2 y), under a master covering
  // x < c at z = kHeight: row 0 integrates phi_0 = 1 - x - y times phi_k, psi_m and the gap
  // h - z_s over {0 <= x <= c, 0 <= y <= 1 - x}. The master moving along +x moves c: each
  // integral's derivative is its integrand's integral along the edge x = c (Leibniz), plus,
  // for M, the change of the master's psi_m moving with it (-d psi_m/dx int phi_0): an
  // independent closed form of what the clipped polygon's differences give.
  const double c = 0.6;
  const Triangle3 slave{{{0, 0, 0}, {1, 0, 0.1}, {0, 1, 0.2}}};
  const Triangle3 master = half_plane(c, true);
  const MortarGeometry g = row_of(slave, {master});
  const auto phi = [](size_t k, double x, double y) { return k == 0 ? 1 - x - y : k == 1 ? x : y; };
  const auto psi = [&](size_t m, double x, double y) {  // the master's barycentric coordinates
    const auto& a = master[0], &b = master[1], &e = master[2];
    const double area = (b[0] - a[0]) * (e[1] - a[1]) - (b[1] - a[1]) * (e[0] - a[0]);
    const auto cross = [&](const Point3& p, const Point3& q) { return (p[0] - x) * (q[1] - y) - (p[1] - y) * (q[0] - x); };
    return (m == 0 ? cross(b, e) : m == 1 ? cross(e, a) : cross(a, b)) / area;
  };
  // The integrands: 0 the weight, 1-3 D_0k, 4-6 M_0m, 7 the normal gap n.(x_s - x_m).
  const auto integrand = [&](size_t which, double x, double y) {
    const double p0 = phi(0, x, y);
    if (which == 0) return p0;
    if (which <= 3) return p0 * phi(which - 1, x, y);
    if (which <= 6) return p0 * psi(which - 4, x, y);
    return p0 * (kHeight - 0.1 * x - 0.2 * y);  // n = -e_z
  };
  double value[8], slope[8];
  for (size_t i = 0; i < 8; ++i) {
    value[i] = c * gauss([&](double s) {
      const double x = c * s;
      return (1 - x) * gauss([&](double r) { return integrand(i, x, (1 - x) * r); });
    });
    slope[i] = (1 - c) * gauss([&](double r) { return integrand(i, c, (1 - c) * r); });
  }
  for (size_t m = 0; m < 3; ++m) slope[4 + m] -= (psi(m, 1, 0) - psi(m, 0, 0)) * value[0];
  const auto quotient = [&](size_t i) { return (slope[i] * value[0] - value[i] * slope[0]) / (value[0] * value[0]); };
  const NodeMotion along_x = motion(g, {0, 0, 0}, {1, 0, 0});
  EXPECT_EQ(g.unverified_motion(along_x), "");
  const RowAt at = g.row_at(along_x, 0), d = derivative(g, along_x);
  ASSERT_EQ(d.dofs.size(), 18u);  // the slave's nine dofs (subdomain 0), the master's (1)
  for (size_t k = 0; k < 3; ++k) {
    // z dofs: the slave's -n_z D_0k / w = D_0k / w, the master's n_z M_0m / w = -M_0m / w.
    EXPECT_NEAR(at.coefficients[3 * k + 2], value[1 + k] / value[0], 1e-13);
    EXPECT_NEAR(at.coefficients[9 + 3 * k + 2], -value[4 + k] / value[0], 1e-13);
    EXPECT_NEAR(d.coefficients[3 * k + 2], quotient(1 + k), 1e-8);
    EXPECT_NEAR(d.coefficients[9 + 3 * k + 2], -quotient(4 + k), 1e-8);
    for (size_t i = 0; i < 2; ++i) EXPECT_EQ(d.coefficients[3 * k + i], 0.0);  // n has no x, y part
  }
  EXPECT_NEAR(at.gap, value[7] / value[0], 1e-13);
  EXPECT_NEAR(d.gap, quotient(7), 1e-8);
  EXPECT_GT(std::abs(quotient(7)), 1e-3);  // the motion does change the gap
}

TEST(MortarMotion, ASlaveCornerCrossingAMasterEdgeIsSmooth) {
  // The corner (1, 0) on the master's edge x = 1: the uncovered tip grows as the square of
  // the motion, so both one-sided derivatives are those of the covered slave: zero.
  const MortarGeometry g = row_of({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {half_plane(1, true)});
  const NodeMotion along_x = motion(g, {0, 0, 0}, {1, 0, 0});
  EXPECT_EQ(g.unverified_motion(along_x), "");
  const RowAt d = derivative(g, along_x);
  for (size_t k = 0; k < 9; ++k) EXPECT_NEAR(d.coefficients[k], 0, 1e-9);  // the slave's (the master's psi move)
}

// A slave (0, 0), (0.5, 0), (0.5, 1) whose edge x = 0.5 lies on the masters' edge x = 0.5,
// moving across it along +x; the row of its corner (0.5, 0) on that edge (corner 0's shape
// function vanishes there, so its row does not feel the edge).
const Triangle3 kEdgeSlave{{{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}}};
const NodeMotion kSlaveAlongX{{1, 0, 0}, {1, 0, 0}, {1, 0, 0}};  // the slave's corners come first

TEST(MortarMotion, ASlaveEdgeOnTheEdgeOfTwoFlatMastersMovesSmoothly) {
  // The masters in two subdomains (the edge's nodes have a dof in each): a flat surface, so
  // the integrands agree on both sides, and the derivatives summed over a node's copies are
  // the same either way; the touching master's pair takes over what the first one loses.
  const MortarGeometry g = row_of(kEdgeSlave, {half_plane(0.5, true), half_plane(0.5, false)}, 1);
  EXPECT_EQ(g.unverified_motion(kSlaveAlongX), "");
  // A rigid translation of the slave over a flat master: weights, D and the gap stay.
  const RowAt d = derivative(g, kSlaveAlongX);
  for (size_t k = 0; k < 9; ++k) EXPECT_NEAR(d.coefficients[k], 0, 1e-9);
  EXPECT_NEAR(d.gap, 0, 1e-9);
}

TEST(MortarMotion, ASlaveEdgeOnAMasterEdgeWhereTheMasterBendsOrEndsIsRefused) {
  const MortarGeometry bends = row_of(kEdgeSlave, {half_plane(0.5, true), half_plane(0.5, false, 3.0)}, 1);
  const std::string reason = bends.unverified_motion(kSlaveAlongX);
  EXPECT_NE(reason.find("kink"), std::string::npos) << reason;
  const MortarGeometry ends = row_of(kEdgeSlave, {half_plane(0.5, true)}, 1);
  EXPECT_NE(ends.unverified_motion(kSlaveAlongX), "");
  // Along the edge (y) nothing crosses it: accepted.
  EXPECT_EQ(bends.unverified_motion({{0, 1, 0}, {0, 1, 0}, {0, 1, 0}}), "");
  EXPECT_EQ(ends.unverified_motion({}), "");  // no motion
}

}  // namespace
}  // namespace ffeti
