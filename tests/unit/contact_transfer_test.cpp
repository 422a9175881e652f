#include "service/contact_transfer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace ffeti {
namespace {

/// The nearest source row by brute force: what the scan in transfer_contact_forces must find.
size_t brute_force_nearest(const std::vector<ContactMultiplier>& from, const Point3& p) {
  const auto distance = [&](const ContactMultiplier& row) { return std::hypot(row.x - p[0], row.y - p[1], row.z - p[2]); };
  size_t best = 0;
  for (size_t j = 1; j < from.size(); ++j)
    if (distance(from[j]) < distance(from[best])) best = j;
  return best;
}

/// Every row of `to` must get the force of its nearest row of `from` (brute force) shared
/// among the rows served by that one, and the served sources' total force be kept.
void expect_nearest_shares(const std::vector<ContactMultiplier>& from, const std::vector<Point3>& to) {
  const std::vector<double> forces = transfer_contact_forces(from, to);
  std::vector<int> sharing(from.size(), 0);
  for (const auto& p : to) ++sharing[brute_force_nearest(from, p)];
  double total = 0, served = 0;
  for (size_t k = 0; k < to.size(); ++k) {
    const size_t j = brute_force_nearest(from, to[k]);
    EXPECT_DOUBLE_EQ(forces[k], from[j].lambda / sharing[j]) << "row " << k;
    total += forces[k];
  }
  for (size_t j = 0; j < from.size(); ++j) served += sharing[j] > 0 ? from[j].lambda : 0.0;
  EXPECT_NEAR(total, served, 1e-9 * served);  // the force of every source that serves a row is kept
}

TEST(ContactTransfer, EveryRowTakesItsNearestSourcesForceSharedAmongThoseItServes) {
  // Random clouds (ties have probability 0): each source gets a distinct force, so the force
  // a row receives times the rows sharing it identifies the source it was given.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<ContactMultiplier> from(300);
  for (size_t j = 0; j < from.size(); ++j) from[j] = {unit(random), unit(random), 1.0 + static_cast<double>(j)};
  std::vector<Point3> to(1000);
  for (auto& p : to) p = {1.5 * unit(random) - 0.25, 1.5 * unit(random) - 0.25, 0.0};  // some outside the cloud
  expect_nearest_shares(from, to);
}

TEST(ContactTransfer, RowsOnACurvedSurfaceInThreeDimensionsTakeTheirNearestSourceInSpace) {
  // A spherical cap seen from below (x, y spread, z varies a little): the nearest source is
  // found in 3D, whichever axis the scan runs along; a flat plane z = 5 as well.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (const double curvature : {0.0, 0.3}) {
    const auto cap = [&](double x, double y) { return Point3{x, y, 5.0 + curvature * (x * x + y * y)}; };
    std::vector<ContactMultiplier> from(400);
    for (size_t j = 0; j < from.size(); ++j) {
      const Point3 p = cap(unit(random), unit(random));
      from[j] = {p[0], p[1], 1.0 + static_cast<double>(j), p[2]};
    }
    std::vector<Point3> to(1500);
    for (auto& p : to) p = cap(1.2 * unit(random), 1.2 * unit(random));
    expect_nearest_shares(from, to);
  }
}

TEST(ContactTransfer, AFinerLineOfCouplesKeepsTheTotalForceWhateverTheUnits) {
  // A contact line of 11 couples refined to 41 (every coarse couple is also a fine one),
  // in metres and in millimetres.
  for (const double scale : {1.0, 1000.0}) {
    std::vector<ContactMultiplier> coarse;
    for (int j = 0; j <= 10; ++j) coarse.push_back({scale * j / 10.0, 2.0 * scale, std::sin(0.3 * j) + 1.5});
    std::vector<Point3> fine;
    for (int k = 0; k <= 40; ++k) fine.push_back({scale * (k / 40.0 + 1e-9), 2.0 * scale, 0.0});
    const std::vector<double> forces = transfer_contact_forces(coarse, fine);
    double coarse_total = 0, fine_total = 0;
    for (const auto& c : coarse) coarse_total += c.lambda;
    for (double f : forces) fine_total += f;
    EXPECT_NEAR(fine_total, coarse_total, 1e-12 * coarse_total) << "scale " << scale;
    // Fine couple 4 j sits on coarse couple j, and with 4 j - 1, 4 j + 1, 4 j + 2 (ties broken
    // by the shift) shares its force in four.
    EXPECT_DOUBLE_EQ(forces[20], coarse[5].lambda / 4);
    EXPECT_DOUBLE_EQ(forces[19], coarse[5].lambda / 4);
  }
}

TEST(ContactTransfer, AContactLineAlongYIsTransferredAsOneAlongX) {
  // The same line of couples laid along y (one x for all: the model problem's contact line)
  // and along x: the same forces, row for row.
  std::vector<ContactMultiplier> along_x, along_y;
  std::vector<Point3> fine_x, fine_y;
  for (int j = 0; j <= 20; ++j) {
    along_x.push_back({j / 20.0, 1.0, 1.0 + j % 3});
    along_y.push_back({1.0, j / 20.0, 1.0 + j % 3});
  }
  for (int k = 0; k <= 40; ++k) {
    fine_x.push_back({k / 40.0 + 1e-9, 1.0, 0.0});
    fine_y.push_back({1.0, k / 40.0 + 1e-9, 0.0});
  }
  EXPECT_EQ(transfer_contact_forces(along_x, fine_x), transfer_contact_forces(along_y, fine_y));
}

TEST(ContactTransfer, NoSourceRowsGiveZeroForces) {
  const std::vector<double> forces = transfer_contact_forces({}, {{0.0, 0.0, 0.0}, {1.0, 1.0, 0.0}});
  ASSERT_EQ(forces.size(), 2u);
  EXPECT_EQ(forces[0], 0.0);
  EXPECT_EQ(forces[1], 0.0);
}

}  // namespace
}  // namespace ffeti
