// A mesh cut into its parts in one pass (split_parts): each part's nodes, elements and
// boundary facets with the body's labels kept and the cuts labelled, checked on a box of
// Kuhn tetrahedra against counts worked out by hand.
#include "base/errors.h"
#include "kuhn_box.h"
#include "mesh/facet_neighbours.h"
#include "mesh/split_parts.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <vector>

namespace ffeti {
namespace {

constexpr int kOuter = 1, kInterface = 99;

/// The box of 2 x 2 x 2 Kuhn cubes as split_parts reads it, neighbours found by brute
/// force (every pair of facets compared); outer facets labelled kOuter and, when
/// `middle_label` >= 0, the inner plane z = 1/2 labelled too.
SplitInput kuhn_body(int middle_label) {
  const int n = 2, per_side = n + 1;
  SplitInput body;
  body.element_nodes = kuhn_box(n);
  body.node_count = per_side * per_side * per_side;
  const size_t facets = body.element_nodes.size();
  std::vector<std::array<int, 3>> keys(facets);
  for (size_t f = 0; f < facets; ++f) {
    const size_t k = f / 4, left_out = f % 4;
    std::array<int, 3> key{};
    size_t used = 0;
    for (size_t j = 0; j < 4; ++j)
      if (j != left_out) key[used++] = body.element_nodes[4 * k + j];
    std::sort(key.begin(), key.end());
    keys[f] = key;
  }
  body.facet_neighbour.assign(facets, -1);
  body.facet_label.assign(facets, -1);
  for (size_t f = 0; f < facets; ++f) {
    for (size_t g = 0; g < facets; ++g)
      if (g / 4 != f / 4 && keys[g] == keys[f]) body.facet_neighbour[f] = static_cast<int>(g / 4);
    const auto on_middle = [&](int node) { return node / (per_side * per_side) == 1; };
    if (body.facet_neighbour[f] < 0)
      body.facet_label[f] = kOuter;
    else if (middle_label >= 0 && std::all_of(keys[f].begin(), keys[f].end(), on_middle))
      body.facet_label[f] = middle_label;
  }
  return body;
}

/// Element k's part: its cube's index along `axis` (cube c = i + 2 (j + 2 k) holds
/// tetrahedra 6c .. 6c + 5).
std::vector<long> halves(int axis) {
  std::vector<long> part(48);
  for (size_t k = 0; k < part.size(); ++k) {
    const long cube = static_cast<long>(k / 6);
    part[k] = axis == 0 ? cube % 2 : cube / 4;
  }
  return part;
}

std::map<int, int> label_counts(const MeshPart& piece) {
  std::map<int, int> counts;
  for (const int label : piece.facet_labels) ++counts[label];
  return counts;
}

TEST(SplitParts, HalvesOfABoxKeepTheirNodesElementsAndFacets) {
  const SplitInput body = kuhn_body(-1);
  const std::vector<long> part = halves(0);
  const std::vector<MeshPart> parts = split_parts(body, part, 2, kInterface);
  ASSERT_EQ(parts.size(), 2u);
  for (long p = 0; p < 2; ++p) {
    const MeshPart& piece = parts[static_cast<size_t>(p)];
    EXPECT_EQ(piece.nodes.size(), 18u);     // 2 x 3 x 3 grid nodes of a half box
    EXPECT_EQ(piece.elements.size(), 24u);  // 4 cubes of 6
    // The half box's surface: 16 squares, two triangles each; the cut x = 1/2 is 4 of them.
    EXPECT_EQ(label_counts(piece), (std::map<int, int>{{kOuter, 24}, {kInterface, 8}}));
    for (size_t e = 0; e < piece.elements.size(); ++e) {
      EXPECT_EQ(part[static_cast<size_t>(piece.elements[e])], p);
      for (size_t j = 0; j < 4; ++j)
        EXPECT_EQ(piece.nodes[static_cast<size_t>(piece.element_nodes[4 * e + j])],
                  body.element_nodes[4 * static_cast<size_t>(piece.elements[e]) + j]);
    }
    for (size_t i = 0; i < piece.facet_elements.size(); ++i) {
      const size_t k = static_cast<size_t>(piece.elements[static_cast<size_t>(piece.facet_elements[i])]);
      const int across = body.facet_neighbour[4 * k + static_cast<size_t>(piece.facet_sides[i])];
      EXPECT_TRUE(across < 0 || part[static_cast<size_t>(across)] != p);
    }
  }
}

TEST(SplitParts, LabelledInnerFacetsAreKeptOnceInsideAPartAndOnBothSidesOfACut) {
  const SplitInput body = kuhn_body(7);
  // Split across x: the labelled plane z = 1/2 lies inside each half (2 squares each).
  const std::vector<MeshPart> across_x = split_parts(body, halves(0), 2, kInterface);
  for (const MeshPart& piece : across_x)
    EXPECT_EQ(label_counts(piece), (std::map<int, int>{{kOuter, 24}, {kInterface, 8}, {7, 4}}));
  // Split along z: the labelled plane is the cut, and both halves keep its label.
  const std::vector<MeshPart> along_z = split_parts(body, halves(2), 2, kInterface);
  for (const MeshPart& piece : along_z) EXPECT_EQ(label_counts(piece), (std::map<int, int>{{kOuter, 24}, {7, 8}}));
}

// The element across each facet (what the plane split reads instead of FreeFEM's private
// adjacency) as the brute-force comparison of every pair of facets finds it, in 3D; in 2D
// on two triangles sharing the edge 1-2 and a third sharing only a vertex.
TEST(SplitParts, ElementAcrossFacetsMatchesThePairwiseSearch) {
  EXPECT_EQ(element_across_facets(kuhn_box(2), 4), kuhn_body(-1).facet_neighbour);
  const std::vector<int> triangles{0, 1, 2, 1, 3, 2, 2, 4, 5};
  EXPECT_EQ(element_across_facets(triangles, 3), (std::vector<int>{1, -1, -1, -1, 0, -1, -1, -1, -1}));
  EXPECT_THROW(element_across_facets({0, 1}, 3), InputError);
}

TEST(SplitParts, RefusesPartsOutOfRangeEmptyPartsAndSizesThatDoNotMatch) {
  const SplitInput body = kuhn_body(-1);
  std::vector<long> part = halves(0);
  EXPECT_THROW(split_parts(body, part, 3, kInterface), InputError);  // part 2 empty
  part[5] = 2;
  EXPECT_THROW(split_parts(body, part, 2, kInterface), InputError);  // out of range
  part.pop_back();
  EXPECT_THROW(split_parts(body, part, 2, kInterface), InputError);  // one entry short
  EXPECT_THROW(split_parts(body, halves(0), 0, kInterface), InputError);
}

}  // namespace
}  // namespace ffeti
