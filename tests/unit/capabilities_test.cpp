// The capability table (constraints/capabilities.h): one entry per contact kind and per
// registered discretization, one message form, friction wherever a kind has rows, and the
// refusals of the input checks (validate_input) and of the sensitivity analysis worded by it.
#include "constraints/capabilities.h"
#include "constraints/constraints.h"
#include "constraints/contact/contact_discretization.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/mortar.h"
#include "constraints/contact/node_to_segment.h"
#include "constraints/contact/node_to_node.h"
#include "constraints/contact/obstacle.h"
#include "constraints/input_checks.h"
#include "base/errors.h"
#include "membrane_model.h"
#include "refusal.h"

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <string>

namespace ffeti {
namespace {

std::vector<SubdomainInput> membranes() { return test::membrane_subdomains(test::membrane_options(4, 2)); }

TEST(Capabilities, OneEntryPerKindAndPerRegisteredDiscretization) {
  const auto& table = capability_table();
  for (size_t k = 0; k < table.size(); ++k) EXPECT_EQ(static_cast<size_t>(table[k].kind), k) << table[k].name;
  ASSERT_EQ(contact_discretizations().size(), table.size());
  for (const auto& unit : contact_discretizations())
    EXPECT_LT(static_cast<size_t>(unit->kind()), table.size());
}

TEST(Capabilities, OneMessageFormNamingTheDimensionWhereTheFeatureWorksInTheOther) {
  EXPECT_EQ(unsupported(ContactKind::mortar, Feature::sensitivity_with_friction, 3),
            "mortar contact does not support sensitivity with friction yet (see the capability table in "
            "docs/reference.md)");
  EXPECT_EQ(unsupported(ContactKind::node_to_node, Feature::ffeti_solve, 3),
            "node-to-node contact does not support ffeti-solve in three dimensions yet (see the capability table in "
            "docs/reference.md)");
  EXPECT_EQ(unsupported(ContactKind::node_to_face, Feature::rows, 2),
            "node-to-face contact does not support plane problems yet (see the capability table in docs/reference.md)");
  EXPECT_TRUE(supports(ContactKind::node_to_segment, Feature::friction, 2));
  EXPECT_FALSE(supports(ContactKind::node_to_segment, Feature::rows, 3));
  EXPECT_TRUE(supports(ContactKind::mortar, Feature::sensitivity, 3));
  EXPECT_FALSE(supports(ContactKind::mortar, Feature::sensitivity_with_friction, 3));
  EXPECT_NO_THROW(require(ContactKind::obstacle, Feature::friction, 2, "friction"));
  EXPECT_EQ(refusal([] { require(ContactKind::mortar, Feature::sensitivity_with_friction, 3, "P"); }),
            "P: " + unsupported(ContactKind::mortar, Feature::sensitivity_with_friction, 3));
}

TEST(Capabilities, FrictionWorksWhereverAKindHasRows) {
  for (const KindCapabilities& k : capability_table())
    for (int dimension : {2, 3})
      EXPECT_EQ(supports(k.kind, Feature::friction, dimension), supports(k.kind, Feature::rows, dimension))
          << k.name << " in " << dimension << "D";
}

TEST(Capabilities, TheInputChecksRefuseAKindInADimensionItLacks) {
  auto subdomains = membranes();
  for (SubdomainInput& s : subdomains) s.z.assign(s.x.size(), 0.0);
  ContactInput contact;
  contact.input_of<NodeToSegmentInput>().segments = {{{0, 1, 2, 3}}, {}};
  EXPECT_EQ(refusal([&] { validate_input(subdomains, contact); }),
            "contactSegments: " + unsupported(ContactKind::node_to_segment, Feature::rows, 3));
}

// Which kind the arguments choose is each unit's rule (check_combination), asked by validate_input.
TEST(Capabilities, EachListKindRefusesTheOtherKindsInputForItsSlaves) {
  const auto unit = [](ContactKind kind) -> const ContactDiscretization& {
    return *contact_discretizations()[static_cast<size_t>(kind)];
  };
  ContactInput mortar;
  mortar.input_of<MortarInput>().slave_faces = {{{0, 1, 2, 3, 4, 5, 6, 7, 8}}};
  EXPECT_NO_THROW(unit(ContactKind::mortar).check_combination(mortar));
  mortar.slave_dofs = {{0}};
  const std::string both = "contactSlaveFaces: the slave nodes of mortar contact are the corners of these faces; give "
                           "contactSlave (node to face, obstacle) or contactSlaveFaces (mortar), not both";
  EXPECT_EQ(refusal([&] { unit(ContactKind::mortar).check_combination(mortar); }), both);
  mortar.slave_dofs.clear();
  mortar.input_of<ObstacleInput>().given = true;
  EXPECT_EQ(refusal([&] { unit(ContactKind::mortar).check_combination(mortar); }), both);

  const std::string combined = "contactMaster: node-to-node contact cannot be combined with contactSegments, "
                               "contactFaces or obstacle in one problem (the slave dofs would belong to both)";
  ContactInput pairs;
  pairs.slave_dofs = {{0}, {}};
  pairs.input_of<NodeToNodeInput>().masters = {{}, {0}};
  EXPECT_NO_THROW(unit(ContactKind::node_to_node).check_combination(pairs));
  for (const auto& add : std::vector<std::function<void(ContactInput&)>>{
           [](ContactInput& c) { c.input_of<NodeToSegmentInput>().segments = {{{0, 1, 2, 3}}, {}}; },
           [](ContactInput& c) { c.input_of<NodeToFaceInput>().faces = {{}, {{0, 1, 2, 3, 4, 5, 6, 7, 8}}}; },
           [](ContactInput& c) { c.input_of<ObstacleInput>().given = true; }}) {
    ContactInput with = pairs;
    add(with);
    EXPECT_EQ(refusal([&] { unit(ContactKind::node_to_node).check_combination(with); }), combined);
  }
  auto subdomains = membranes();
  pairs.slave_dofs.resize(subdomains.size());
  pairs.input_of<NodeToNodeInput>().masters.resize(subdomains.size());
  pairs.input_of<ObstacleInput>().given = true;
  EXPECT_EQ(refusal([&] { validate_input(subdomains, pairs); }), combined);
}

// ffeti-solve reads the list kinds' problem-file key through the registry: the key "master"
// names the group whose nodes, segments or triangles make the list of the kind the problem's
// components choose; mortar has no key.
TEST(Capabilities, EachListKindDeclaresItsProblemFileKey) {
  const std::pair<int, ContactKind> chosen[] = {
      {1, ContactKind::node_to_node}, {2, ContactKind::node_to_segment}, {3, ContactKind::node_to_face}};
  const MeshEntries entries[] = {MeshEntries::node_dofs, MeshEntries::segments, MeshEntries::triangles};
  for (size_t i = 0; i < 3; ++i) {
    const ContactDiscretization* kind = file_list_kind(chosen[i].first);
    ASSERT_NE(kind, nullptr);
    EXPECT_EQ(kind->kind(), chosen[i].second);
    EXPECT_STREQ(kind->list_input()->file_key, "master");
    EXPECT_EQ(kind->list_input()->file_entries, entries[i]);
  }
  EXPECT_EQ(file_list_kind(4), nullptr);
  EXPECT_EQ(contact_discretizations()[static_cast<size_t>(ContactKind::mortar)]->list_input()->file_key, nullptr);
}

// Each list kind says whether its own list is given (check_kind_inputs names it beside a
// kind that owns its input) and checks it (check_against, asked by validate_input).
TEST(Capabilities, EachListKindKnowsAndChecksItsOwnList) {
  const auto given = [](const ContactInput& contact) {
    std::vector<std::string> arguments;
    for (const ContactDiscretization* kind : kinds_with_lists())
      if (kind->list_given(contact)) arguments.push_back(kind->list_input()->argument);
    return arguments;
  };
  ContactInput contact;
  EXPECT_TRUE(given(contact).empty());
  contact.input_of<NodeToNodeInput>().masters = {{}, {0}};
  contact.input_of<NodeToSegmentInput>().segments = {{{0, 1, 2, 3}}, {}};
  EXPECT_EQ(given(contact), (std::vector<std::string>{"contactSegments", "contactMaster"}));
  auto subdomains = membranes();
  ContactInput bad;
  bad.slave_dofs.resize(subdomains.size());
  bad.input_of<NodeToNodeInput>().masters.resize(subdomains.size());
  bad.input_of<NodeToNodeInput>().masters[1] = {100000};
  std::vector<size_t> ids(subdomains.size());
  for (size_t k = 0; k < ids.size(); ++k) ids[k] = k;
  const auto& pairs = *contact_discretizations()[static_cast<size_t>(ContactKind::node_to_node)];
  EXPECT_EQ(refusal([&] { pairs.check_against(subdomains, ids, bad, 2); }).rfind("contactMaster[1]: dof 100000 is outside", 0),
            0u);
  EXPECT_EQ(refusal([&] { validate_input(subdomains, bad); }).rfind("contactMaster[1]: dof 100000 is outside", 0), 0u);
}

// fetiSetup reads the list kinds' per-subdomain arguments through the registry (read_list).
TEST(Capabilities, EachListKindCutsItsOwnArgumentIntoEntries) {
  std::vector<std::string> arguments;
  for (const ContactDiscretization* kind : kinds_with_lists()) arguments.push_back(kind->list_input()->argument);
  EXPECT_EQ(arguments, (std::vector<std::string>{"contactSegments", "contactSlaveFaces", "contactFaces", "contactMaster"}));
  const auto& segments = *contact_discretizations()[static_cast<size_t>(ContactKind::node_to_segment)];
  ContactInput contact;
  segments.read_list({{}, {0, 1, 2, 3, 4, 5, 6, 7}}, {3, 5}, contact);
  ASSERT_EQ(contact.input_of<NodeToSegmentInput>().segments.size(), 2u);
  EXPECT_TRUE(contact.input_of<NodeToSegmentInput>().segments[0].empty());
  EXPECT_EQ(contact.input_of<NodeToSegmentInput>().segments[1], (std::vector<std::array<int, 4>>{{0, 1, 2, 3}, {4, 5, 6, 7}}));
  EXPECT_EQ(refusal([&] { segments.read_list({{0, 1, 2}}, {7}, contact); }),
            "contactSegments[7]: needs 4 dofs per segment (a_x, a_y, b_x, b_y)");
  const auto& faces = *contact_discretizations()[static_cast<size_t>(ContactKind::mortar)];
  faces.read_list({{0, 1, 2, 3, 4, 5, 6, 7, 8}}, {0}, contact);
  EXPECT_EQ(contact.input_of<MortarInput>().slave_faces, (std::vector<std::vector<std::array<int, 9>>>{{{0, 1, 2, 3, 4, 5, 6, 7, 8}}}));
  EXPECT_TRUE(contact.input_of<NodeToFaceInput>().faces.empty());
  EXPECT_EQ(refusal([&] { faces.read_list({{0, 1}}, {2}, contact); }),
            "contactSlaveFaces[2]: needs 9 dofs per face (a_x, a_y, a_z, b_x, ..., c_z)");
}

TEST(Capabilities, TheMarkdownTableHasARowPerKindAndSaysWhereAFeatureWorksInOneDimension) {
  const std::string table = capability_table_markdown();
  EXPECT_EQ(table.rfind("| contact | selected by | plane (2D) | solid (3D) | friction", 0), 0u) << table;
  for (const KindCapabilities& k : capability_table())
    EXPECT_NE(table.find(std::string("\n| ") + k.name + " | "), std::string::npos) << k.name;
  EXPECT_NE(table.find("| node-to-node | `contactSlave, contactMaster` | yes | yes | yes | yes | — | yes | plane only | yes |"), std::string::npos) << table;
}

}  // namespace
}  // namespace ffeti
