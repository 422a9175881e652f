// The contact registry (constraints/contact/registry.cpp): a kind is its position, the
// capability table is the units' rows in that order, the kinds that own their input list
// their arguments for fetiSetup and their keys for ffeti-solve, and their entries are read
// and checked alike from a script's array or a problem file's fields.
#include "constraints/capabilities.h"
#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/obstacle.h"
#include "refusal.h"

#include <gtest/gtest.h>

#include <string>

namespace ffeti {
namespace {

const ContactDiscretization& with_argument(const std::string& argument) {
  for (const ContactDiscretization* unit : kinds_with_input())
    if (argument == unit->input()->argument) return *unit;
  throw std::logic_error("no kind reads " + argument);
}

TEST(ContactRegistry, AKindIsItsPositionAndTheTableIsTheUnitsRows) {
  const auto& units = contact_discretizations();
  ASSERT_EQ(capability_table().size(), units.size());
  for (size_t k = 0; k < units.size(); ++k) {
    EXPECT_EQ(static_cast<size_t>(units[k]->kind()), k) << units[k]->capabilities().name;
    EXPECT_STREQ(capability_table()[k].name, units[k]->capabilities().name);
  }
  // The kinds other code names are the units of those names.
  const std::pair<ContactKind, const char*> named[] = {
      {ContactKind::node_to_segment, "node-to-segment"}, {ContactKind::obstacle, "obstacle"},
      {ContactKind::ball, "ball"},                       {ContactKind::mortar, "mortar"},
      {ContactKind::node_to_face, "node-to-face"},       {ContactKind::node_to_node, "node-to-node"}};
  for (const auto& [kind, name] : named) EXPECT_STREQ(capability_table()[static_cast<size_t>(kind)].name, name);
}

TEST(ContactRegistry, TheRigidObstaclesReadTheirOwnArgument) {
  ContactInput plane;
  with_argument("obstacle").read_input({0, -1, 0, 2}, 2, plane);
  EXPECT_TRUE(plane.input_of<ObstacleInput>().given);
  EXPECT_EQ(plane.input_of<ObstacleInput>().point, (std::array<double, 3>{0, -1, 0}));
  EXPECT_EQ(plane.input_of<ObstacleInput>().normal, (std::array<double, 3>{0, 2, 0}));
  EXPECT_EQ(refusal([] {
              ContactInput c;
              with_argument("obstacle").read_input({0, 0, 0, 1}, 3, c);
            }),
            "obstacle: with Z (three dimensions) needs six entries, a plane [px, py, pz, nx, ny, nz]; got four (a "
            "line of a plane problem)");
  // The ball keeps its own entries (it shares no field with the plane).
  ContactInput ball;
  with_argument("obstacleBall").read_input({1, 2, 3, 0.5}, 3, ball);
  EXPECT_FALSE(ball.input_of<ObstacleInput>().given);
  EXPECT_EQ(ball.kind_parameters.at(ContactKind::ball), (std::vector<double>{1, 2, 3, 0.5}));
  EXPECT_EQ(refusal([] {
              ContactInput c;
              with_argument("obstacleBall").read_input({1, 2, 0}, 2, c);
            }),
            "obstacleBall: the radius must be finite and > 0, got 0.000000");
  EXPECT_EQ(refusal([&] { with_argument("obstacleBall").read_input({1, 2, 0.5}, 2, plane); }),
            "obstacle, obstacleBall: give one obstacle, a plane or a ball");
}

TEST(ContactRegistry, AProblemFilesFieldsBecomeTheArgumentsEntries) {
  const KindInput spec{"obstacleThing", "thing", {{"point", InputField::kDimension}, {"size", 1}, {"hollow", 1, true}}, 2,
                       "[px, py, pz, size(, hollow)]"};
  EXPECT_EQ(input_values(spec, {{1, 2, 3}, {4}, {}}, 3, "f: contact[0].thing."), (std::vector<double>{1, 2, 3, 4}));
  EXPECT_EQ(input_values(spec, {{1, 2}, {4}, {1}}, 2, "f: contact[0].thing."), (std::vector<double>{1, 2, 4, 1}));
  EXPECT_EQ(refusal([&] { input_values(spec, {{1, 2, 3}, {}, {}}, 3, "f: contact[0].thing."); }),
            "f: contact[0].thing.size: missing");
  // A point or vector of the problem's dimension in the words of its "components"; a field
  // of fixed size by its count.
  EXPECT_EQ(refusal([&] { input_values(spec, {{1, 2}, {4}, {}}, 3, "f: contact[0].thing."); }),
            "f: contact[0].thing.point: needs three numbers [x, y, z] (\"components\": 3)");
  EXPECT_EQ(refusal([&] { input_values(spec, {{1, 2, 3}, {4}, {}}, 2, "f: contact[0].thing."); }),
            "f: contact[0].thing.point: needs two numbers [x, y]");
  EXPECT_EQ(refusal([&] { input_values(spec, {{1, 2}, {4, 5}, {}}, 2, "f: contact[0].thing."); }),
            "f: contact[0].thing.size: needs one number, got 2");
  const KindInput directed{"obstacleArrow", "arrow", {{"direction", 3, false, true}}, 1, "[dx, dy, dz]"};
  EXPECT_EQ(refusal([&] { input_values(directed, {{0, 0, 0}}, 3, "f: contact[0].arrow."); }),
            "f: contact[0].arrow.direction: must not be zero");
}

// The plane obstacle's key is its own (point and normal, or a straight curve of the mesh).
TEST(ContactRegistry, ThePlaneObstacleDeclaresItsProblemFileKey) {
  const KindInput& plane = *with_argument("obstacle").input();
  EXPECT_STREQ(plane.file_key, "obstacle");
  EXPECT_STREQ(plane.line_key, "curve");
  EXPECT_EQ(input_values(plane, {{0, -1}, {0, 2}}, 2, "f: contact[0].obstacle."), (std::vector<double>{0, -1, 0, 2}));
  EXPECT_EQ(refusal([&] { input_values(plane, {{0, -1, 0}, {0, 0, 0}}, 3, "f: contact[0].obstacle."); }),
            "f: contact[0].obstacle.normal: must not be zero");
  EXPECT_EQ(with_argument("obstacleBall").input()->file_key, nullptr);
}

}  // namespace
}  // namespace ffeti
