// Which motions of a node-to-face row the sensitivities accept: the slave or the face alone,
// or both when the slave sits over a corner (matching faces); both over the interior of a
// face (non-matching faces) is refused, its derivative not being trusted yet.
#include "constraints/contact/node_to_face.h"

#include <gtest/gtest.h>

#include <array>

namespace ffeti {
namespace {

FaceGeometry face_row(const Point3& slave) {
  const std::array<Point3, 3> corners = {Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}};
  std::array<DofRef, 9> face;
  for (int k = 0; k < 9; ++k) face[static_cast<size_t>(k)] = {1, k};
  return FaceGeometry({{{0, 0}, {0, 1}, {0, 2}}}, slave, face, corners);
}

const Point3 kStill{0, 0, 0}, kUp{0, 0, 1};

TEST(FaceMotion, OneSideMovingIsAccepted) {
  const FaceGeometry interior = face_row({0.5, 0.6, 0.1});
  EXPECT_EQ(interior.unverified_motion({kUp, kStill, kStill, kStill}), "");  // the slave alone
  EXPECT_EQ(interior.unverified_motion({kStill, kUp, kUp, kStill}), "");     // the face alone
  EXPECT_EQ(interior.unverified_motion({kStill, kStill, kStill, kStill}), "");
}

TEST(FaceMotion, BothSidesMovingOverACornerIsAccepted) {
  const FaceGeometry matching = face_row({2, 0, 0});  // over corner b
  EXPECT_EQ(matching.unverified_motion({kUp, kUp, kUp, kUp}), "");
}

TEST(FaceMotion, BothSidesMovingOverTheFaceIsRefused) {
  const FaceGeometry interior = face_row({0.5, 0.6, 0.1});
  const std::string reason = interior.unverified_motion({kUp, kStill, kUp, kStill});
  EXPECT_NE(reason.find("both move"), std::string::npos) << reason;
  const FaceGeometry edge = face_row({1, 1, 0});  // over the edge b-c: not a corner either
  EXPECT_NE(edge.unverified_motion({kUp, kUp, kUp, kUp}), "");
}

}  // namespace
}  // namespace ffeti
