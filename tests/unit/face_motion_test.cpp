// Which motions of a node-to-face row the sensitivities accept: every motion of a slave over
// the interior of its face (the slave, the face or both moving: matching or non-matching
// faces), and on the face's boundary the motions that keep the slave on it; refused, a slave
// on an edge or a corner moving across it relative to the face (it changes face on one side
// of the design: a one-sided derivative) and a moving slave beyond the face's edges.
#include "base/errors.h"
#include "constraints/contact/node_to_face.h"
#include "sens/contact_derivative.h"

#include <gtest/gtest.h>

#include <array>
#include <memory>

namespace ffeti {
namespace {

// The face (0, 0, 0), (2, 0, 0), (0, 2, 0), its normal +z.
FaceGeometry face_row(const Point3& slave) {
  const std::array<Point3, 3> corners = {Point3{0, 0, 0}, Point3{2, 0, 0}, Point3{0, 2, 0}};
  std::array<DofRef, 9> face;
  for (int k = 0; k < 9; ++k) face[static_cast<size_t>(k)] = {1, k};
  return FaceGeometry({{{0, 0}, {0, 1}, {0, 2}}}, slave, face, corners);
}

const Point3 kStill{0, 0, 0}, kUp{0, 0, 1}, kAlongX{1, 0, 0}, kAlongY{0, 1, 0};

TEST(FaceMotion, EveryMotionOverTheInteriorIsAccepted) {
  const FaceGeometry interior = face_row({0.5, 0.6, 0.1});
  EXPECT_EQ(interior.unverified_motion({kUp, kStill, kStill, kStill}), "");  // the slave alone
  EXPECT_EQ(interior.unverified_motion({kStill, kUp, kUp, kStill}), "");     // the face alone
  EXPECT_EQ(interior.unverified_motion({kUp, kStill, kUp, kStill}), "");     // both (non-matching faces)
  EXPECT_EQ(interior.unverified_motion({kAlongX, kStill, kAlongY, kUp}), "");  // sliding over the face
  EXPECT_EQ(interior.unverified_motion({kStill, kStill, kStill, kStill}), "");
}

TEST(FaceMotion, MotionsKeepingTheSlaveOnTheBoundaryAreAccepted) {
  const FaceGeometry matching = face_row({2, 0, 0});  // over corner b
  EXPECT_EQ(matching.unverified_motion({kUp, kUp, kUp, kUp}), "");
  EXPECT_EQ(matching.unverified_motion({kAlongY, kStill, kAlongY, kStill}), "");  // with its corner
  const FaceGeometry edge = face_row({1, 1, 0});  // over the edge b-c
  EXPECT_EQ(edge.unverified_motion({kStill, kUp, kStill, kStill}), "");         // the face tilts
  const Point3 along_edge{-1, 1, 0};
  EXPECT_EQ(edge.unverified_motion({along_edge, kStill, kStill, kStill}), "");  // along the edge
}

TEST(FaceMotion, MovingAcrossAnEdgeOrACornerIsRefused) {
  const FaceGeometry edge = face_row({1, 1, 0});  // over the edge b-c
  const std::string across = edge.unverified_motion({kAlongX, kStill, kStill, kStill});
  EXPECT_NE(across.find("edge or a corner"), std::string::npos) << across;
  EXPECT_NE(edge.unverified_motion({kStill, kStill, kAlongX, kStill}), "");  // corner b drags the edge
  EXPECT_EQ(edge.unverified_motion({kStill, kAlongX, kStill, kStill}), "");  // corner a: the edge stays
  const FaceGeometry corner = face_row({2, 0, 0});
  EXPECT_NE(corner.unverified_motion({kAlongY, kStill, kStill, kStill}), "");  // the slave leaves its corner
}

TEST(FaceMotion, AMovingSlaveBeyondTheFaceIsRefused) {
  const FaceGeometry beyond = face_row({3, 1, 0.1});
  EXPECT_NE(beyond.unverified_motion({kUp, kStill, kStill, kStill}).find("beyond"), std::string::npos);
  EXPECT_EQ(beyond.unverified_motion({kStill, kStill, kStill, kStill}), "");
}

// The sensitivities refuse a one-sided row only where its derivative is used: a row neither
// kept nor carrying a force (inactive) may slide across an edge.
TEST(FaceMotion, OnlyRowsInUseAreRefused) {
  Constraints constraints;
  constraints.geometry = {std::make_shared<const FaceGeometry>(face_row({1, 1, 0}))};  // over the edge b-c
  const std::vector<std::vector<double>> vx = {{1, 1, 1}, std::vector<double>(9, 0.0)};  // the slave slides along x
  const std::vector<std::vector<double>> still = {{0, 0, 0}, std::vector<double>(9, 0.0)};
  const SerialCommunicator comm;
  EXPECT_THROW(contact_row_derivatives(constraints, {0, 1}, {&vx, &still, &still}, {true}, comm), InputError);
  const auto unused = contact_row_derivatives(constraints, {0, 1}, {&vx, &still, &still}, {false}, comm);
  ASSERT_EQ(unused.size(), 1u);
  EXPECT_FALSE(unused[0].entries.empty());  // computed all the same, for whoever would read it
}

}  // namespace
}  // namespace ffeti
