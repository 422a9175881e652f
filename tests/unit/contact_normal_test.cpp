// contactNormal (node to face): the slave surface's normal at a slave node from the faces
// around it, the row's normal it gives (slave, average) and the row built along it, and the
// row's derivative when a neighbour of the slave moves (the sensitivities' motion of that
// normal) against the closed form.
#include "base/errors.h"
#include "constraints/contact/mortar.h"
#include "constraints/contact/node_to_face.h"
#include "sens/contact_derivative.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace ffeti {
namespace {

// The master face (0, 0, 0), (2, 0, 0), (0, 2, 0), normal +z (subdomain 1, dofs 0-8); the
// slave s = (0.5, 0.6, 0.1) (subdomain 0, dofs 0-2) on the plane z = 0.1 + 0.2 (x - 0.5) of
// the slave body above it, its four neighbours 0.3 away along +-x, +-y (subdomain 0, x dofs
// 3, 6, 9, 12), neighbour 0 raised by `lift`. The fan's faces (s, n_{k+1}, n_k) point down,
// out of the slave's body.
const Point3 kSlave{0.5, 0.6, 0.1};

SlaveFan fan(ContactNormal normal, double lift = 0) {
  SlaveFan f{normal, {}, {}, {}};
  const Point3 offsets[4] = {{0.3, 0, 0.06 + lift}, {0, 0.3, 0}, {-0.3, 0, -0.06}, {0, -0.3, 0}};
  for (int k = 0; k < 4; ++k) {
    f.neighbours.push_back({0, 3 + 3 * k});
    f.positions.push_back({kSlave[0] + offsets[k][0], kSlave[1] + offsets[k][1], kSlave[2] + offsets[k][2]});
    f.faces.push_back({-1, (k + 1) % 4, k});
  }
  return f;
}

FaceGeometry row(ContactNormal normal) {
  const std::array<Point3, 3> corners = {Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}};
  std::array<DofRef, 9> face;
  for (int k = 0; k < 9; ++k) face[static_cast<size_t>(k)] = {1, k};
  return FaceGeometry({{{0, 0}, {0, 1}, {0, 2}}}, kSlave, face, corners, false, fan(normal));
}

TEST(ContactNormal, TheFanGivesTheSlaveSurfacesOutwardNormal) {
  const SlaveFan f = fan(ContactNormal::slave);
  const Point3 o = fan_normal(f, kSlave, f.positions);
  const double length = std::sqrt(1.04);  // the plane's downward normal (0.2, 0, -1)
  EXPECT_NEAR(o[0], 0.2 / length, 1e-15);
  EXPECT_NEAR(o[1], 0, 1e-15);
  EXPECT_NEAR(o[2], -1 / length, 1e-15);
}

TEST(ContactNormal, TheRowTakesTheChosenNormalAndProjectsAlongIt) {
  const double length = std::sqrt(1.04);
  // master: the face's e_z, the slave's vertical projection (0.5, 0.6, 0), the gap 0.1.
  const FaceGeometry master = row(ContactNormal::master);
  EXPECT_NEAR(master.normal()[2], 1, 1e-15);
  EXPECT_NEAR(master.linearized({}, 0, true).gap, 0.1, 1e-15);
  // slave: n = -(0.2, 0, -1)/|.|; along it the slave reaches z = 0 at p = (0.52, 0.6, 0),
  // 0.1 |(0.2, 0, -1)| away, weights (0.44, 0.26, 0.3).
  const FaceGeometry slave = row(ContactNormal::slave);
  const Point3 n = slave.normal();
  EXPECT_NEAR(n[0], -0.2 / length, 1e-15);
  EXPECT_NEAR(n[2], 1 / length, 1e-15);
  const LinearizedFaceRow r = slave.linearized({}, 0, true);
  EXPECT_NEAR(r.gap, 0.1 * length, 1e-15);
  const double w[3] = {0.44, 0.26, 0.3};
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(r.coefficients[i], -n[i], 1e-15);
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(r.coefficients[3 + 3 * k + i], w[k] * n[i], 1e-15);
  }
  // average: (e_z - o)/|.|, halfway in angle between the face's and the slave's normals.
  const Point3 a = row(ContactNormal::average).normal();
  const double angle = std::atan2(0.2, 1) / 2;
  EXPECT_NEAR(a[0], -std::sin(angle), 1e-15);
  EXPECT_NEAR(a[2], std::cos(angle), 1e-15);
  // The friction rows' tangents are those of the row's normal.
  const auto slips = slave.slip_rows();
  ASSERT_EQ(slips.size(), 2u);
  for (const RowAt& s : slips) EXPECT_NEAR(s.coefficients[0] * n[0] + s.coefficients[1] * n[1] + s.coefficients[2] * n[2], 0, 1e-15);
  EXPECT_EQ(slave.moving_nodes().size(), 8u);  // the slave, a, b, c, four neighbours
}

// Neighbour 0 moving up by t turns the slave's normal: the sum of the fan's face normals is
// (0.072 + 0.6 t, 0, -0.36), so with L = |.| the slave row's n = (-(0.072 + 0.6 t), 0, 0.36)/L
// and its gap 0.1 / n_z. The sensitivities' derivative against these.
TEST(ContactNormal, TheRowsDerivativeFollowsTheSlavesNeighbours) {
  const std::vector<std::vector<double>> still = {std::vector<double>(15, 0.0), std::vector<double>(9, 0.0)};
  std::vector<std::vector<double>> up = still;
  up[0][3] = 1;  // neighbour 0's velocity (0, 0, 1), read at its x dof
  const SerialCommunicator comm;
  const double L = std::sqrt(0.072 * 0.072 + 0.36 * 0.36);
  const double dnx = -0.6 / L + 0.072 * 0.072 * 0.6 / (L * L * L), dnz = -0.36 * 0.072 * 0.6 / (L * L * L);
  const double nz = 0.36 / L;
  for (ContactNormal normal : {ContactNormal::slave, ContactNormal::master}) {
    Constraints constraints;
    constraints.geometry = {std::make_shared<const FaceGeometry>(row(normal))};
    const auto d = contact_row_derivatives(constraints, {0, 1}, {&still, &still, &up}, {true}, comm);
    ASSERT_EQ(d.size(), 1u);
    if (normal == ContactNormal::master) {  // the face's normal: the slave's neighbours do not move the row
      EXPECT_TRUE(d[0].entries.empty());
      EXPECT_EQ(d[0].rhs, 0);
      continue;
    }
    double ds_x = 0, ds_z = 0;
    for (const auto& e : d[0].entries)
      if (e.subdomain == 0 && e.dof == 0) ds_x = e.coefficient;
      else if (e.subdomain == 0 && e.dof == 2) ds_z = e.coefficient;
    EXPECT_NEAR(ds_x, -dnx, 1e-7 * std::abs(dnx));  // the slave's coefficient is -n
    EXPECT_NEAR(ds_z, -dnz, 1e-7 * std::abs(dnz));
    const double dgap = -0.1 * dnz / (nz * nz);
    EXPECT_NEAR(d[0].rhs, dgap, 1e-7 * std::abs(dgap));
  }
}

TEST(ContactNormal, AWrongWordOrKindIsRefusedByName) {
  // The word, node to face's option in the registry, read as both front ends read it.
  const NodeToFace unit;
  const ListOption& option = unit.list_input()->options.at(0);
  EXPECT_STREQ(option.argument, "contactNormal");
  ContactInput given;
  unit.read_option(0, word_position(option, "average"), given);
  EXPECT_EQ(given.input_of<NodeToFaceInput>().normal, ContactNormal::average);
  EXPECT_EQ(word_position(option, "slaves"), -1);
  EXPECT_EQ(word_refusal(option, "slaves"),
            "must be \"master\", \"slave\", \"average\" or \"flatter\", got \"slaves\"");
  ContactInput mortar;
  mortar.input_of<NodeToFaceInput>().normal = ContactNormal::slave;
  mortar.input_of<NodeToFaceInput>().faces = {{{0, 1, 2, 3, 4, 5, 6, 7, 8}}};
  mortar.input_of<MortarInput>().slave_faces = {{{0, 1, 2, 3, 4, 5, 6, 7, 8}}};
  try {
    NodeToFace().check_combination(mortar);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contactNormal: \"slave\" applies to node-to-face contact"), std::string::npos)
        << e.what();
  }
  mortar.input_of<NodeToFaceInput>().normal = ContactNormal::master;
  EXPECT_NO_THROW(NodeToFace().check_combination(mortar));
  // The default resolves itself per couple of bodies, and mortar keeps its master's normals.
  EXPECT_EQ(NodeToFaceInput().normal, ContactNormal::flatter);
  mortar.input_of<NodeToFaceInput>().normal = ContactNormal::flatter;
  EXPECT_NO_THROW(NodeToFace().check_combination(mortar));
}

/// Unit normals round the axis -z or +z, tilted by 0, tilt / 2 and tilt at eight azimuths: a
/// cap's normals over a contact whose rim tilts by `tilt` (0: a flat face).
std::vector<Point3> cap(double tilt, double side) {
  std::vector<Point3> normals;
  for (double t : {0.0, tilt / 2, tilt})
    for (int k = 0; k < 8; ++k) {
      const double p = k * M_PI / 4;
      normals.push_back({std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), side * std::cos(t)});
    }
  return normals;
}

TEST(ContactNormal, FlatterTakesTheNormalOfTheFlatterSurface) {
  // A sphere's cap on a flat block, either side the slave (the master's normals point up, the
  // slave's own outward ones down): the block's normal.
  EXPECT_EQ(flatter_side(cap(0.2, 1), cap(0, -1)), ContactNormal::slave);
  EXPECT_EQ(flatter_side(cap(0, 1), cap(0.2, -1)), ContactNormal::master);
  // A flatter cap against a rounder one: the flatter's, at a share of half the spread.
  EXPECT_EQ(flatter_side(cap(0.2, 1), cap(0.05, -1)), ContactNormal::slave);
  EXPECT_EQ(flatter_side(cap(0.05, 1), cap(0.2, -1)), ContactNormal::master);
  // Curved alike (two equal spheres, or nearly): the average.
  EXPECT_EQ(flatter_side(cap(0.2, 1), cap(0.2, -1)), ContactNormal::average);
  EXPECT_EQ(flatter_side(cap(0.2, 1), cap(0.17, -1)), ContactNormal::average);
  // Flat on flat, or no slave normals (no slave faces given): the master's.
  EXPECT_EQ(flatter_side(cap(0, 1), cap(0, -1)), ContactNormal::master);
  EXPECT_EQ(flatter_side(cap(0.2, 1), {}), ContactNormal::master);
}

}  // namespace
}  // namespace ffeti
