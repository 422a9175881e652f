// Connected partitions of tetrahedron meshes: which elements are neighbours (a shared face,
// not an edge or a vertex), and METIS-like partitions with parts in pieces made connected.
#include "base/errors.h"
#include "mesh/connect_parts.h"
#include "mesh/element_quality.h"
#include "mesh/facet_neighbours.h"
#include "kuhn_box.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace ffeti {
namespace {

/// Number of face-connected pieces of each part, found here by a flood fill of its own.
std::map<long, int> pieces_per_part(const std::vector<std::vector<int>>& neighbours, const std::vector<long>& part) {
  std::vector<bool> seen(part.size(), false);
  std::map<long, int> pieces;
  for (size_t start = 0; start < part.size(); ++start) {
    if (seen[start]) continue;
    ++pieces[part[start]];
    std::vector<size_t> stack{start};
    seen[start] = true;
    while (!stack.empty()) {
      const size_t k = stack.back();
      stack.pop_back();
      for (int other : neighbours[k])
        if (!seen[static_cast<size_t>(other)] && part[static_cast<size_t>(other)] == part[k]) {
          seen[static_cast<size_t>(other)] = true;
          stack.push_back(static_cast<size_t>(other));
        }
    }
  }
  return pieces;
}

TEST(FacetNeighbours, TetrahedraTouchAcrossFacesOnly) {
  const std::vector<std::vector<int>> neighbours = facet_neighbours(kuhn_box(1), 4);
  ASSERT_EQ(neighbours.size(), 6u);
  // Around the diagonal each tetrahedron shares a face with the one before and after it and
  // only the diagonal edge with the other three.
  for (int t = 0; t < 6; ++t) {
    std::vector<int> expected{(t + 5) % 6, (t + 1) % 6};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(neighbours[static_cast<size_t>(t)], expected) << "tetrahedron " << t;
  }
}

TEST(FacetNeighbours, InnerTetrahedraHaveFourNeighbours) {
  const int n = 3;
  const std::vector<std::vector<int>> neighbours = facet_neighbours(kuhn_box(n), 4);
  std::map<size_t, int> by_count;
  for (const auto& list : neighbours) ++by_count[list.size()];
  // Each tetrahedron has 4 faces; the box's surface has 6 faces x n^2 squares x 2 triangles,
  // each bounding one tetrahedron: 4 * 6 n^3 - 12 n^2 face slots have a neighbour.
  long slots = 0;
  for (const auto& [count, elements] : by_count) {
    EXPECT_LE(count, 4u);
    slots += static_cast<long>(count) * elements;
  }
  EXPECT_EQ(slots, 4L * 6 * n * n * n - 12L * n * n);
  // Symmetric: k lists l whenever l lists k.
  for (size_t k = 0; k < neighbours.size(); ++k)
    for (int l : neighbours[k]) {
      const auto& back = neighbours[static_cast<size_t>(l)];
      EXPECT_NE(std::find(back.begin(), back.end(), static_cast<int>(k)), back.end()) << k << " and " << l;
    }
}

TEST(FacetNeighbours, TrianglesTouchAcrossEdges) {
  // Triangles 0 and 1 share the edge 1-2; triangle 2 touches triangle 1 at node 3 only.
  const std::vector<int> nodes = {0, 1, 2, 1, 3, 2, 3, 4, 5};
  EXPECT_EQ(facet_neighbours(nodes, 3), (std::vector<std::vector<int>>{{1}, {0}, {}}));
}

TEST(FacetNeighbours, BadTablesAreRefusedByName) {
  const auto message = [](const std::vector<int>& nodes, int per_element) {
    try {
      facet_neighbours(nodes, per_element);
    } catch (const InputError& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({0, 1, 2, 3}, 2), "nodes_per_element: 3 (triangles) or 4 (tetrahedra), got 2");
  EXPECT_EQ(message({0, 1, 2, 3, 4}, 4), "element_nodes: 5 entries are not a whole number of 4-node elements");
  EXPECT_EQ(message({0, 1, 2, 3, 1, -2, 3, 4}, 4), "element_nodes: node -2 of element 1 is negative");
}

TEST(ConnectElementParts, PiecesTouchingAlongAnEdgeAreSeparated) {
  // Part 0 is tetrahedra 0 and 3 of one cube: they share the diagonal edge, no face, so part
  // 0 has two pieces. The first stays; tetrahedron 3 touches part 1 (tetrahedron 2) and
  // part 2 (tetrahedron 4) across one face each and joins the smaller part number, 1.
  std::vector<long> part = {0, 1, 1, 0, 2, 2};
  EXPECT_EQ(connect_element_parts(kuhn_box(1), 4, part), 1);
  EXPECT_EQ(part, (std::vector<long>{0, 1, 1, 1, 2, 2}));
}

TEST(ConnectElementParts, ScatteredPartitionEndsConnected) {
  // A box of 6 * 4^3 tetrahedra dealt into 5 parts at random: every part in many pieces.
  const int n = 4;
  const std::vector<int> nodes = kuhn_box(n);
  const std::vector<std::vector<int>> neighbours = facet_neighbours(nodes, 4);
  std::mt19937 random(7);
  std::vector<long> part(neighbours.size());
  for (long& p : part) p = static_cast<long>(random() % 5);
  const std::map<long, int> before = pieces_per_part(neighbours, part);
  ASSERT_GT(before.at(0), 1);
  const long moved = connect_element_parts(nodes, 4, part);
  EXPECT_GT(moved, 0);
  const std::map<long, int> after_pieces = pieces_per_part(neighbours, part);
  EXPECT_EQ(after_pieces.size(), 5u);  // no part emptied
  for (const auto& [p, count] : after_pieces) EXPECT_EQ(count, 1) << "part " << p;
  // Connected already: a second call moves nothing.
  const std::vector<long> after = part;
  EXPECT_EQ(connect_element_parts(nodes, 4, part), 0);
  EXPECT_EQ(part, after);
}

TEST(ConnectElementParts, MeshInTwoPiecesEnds) {
  // Two cubes with no node in common, all of part 0: the second cube's piece has no other
  // part to join and stays (the body itself is in two pieces).
  std::vector<int> nodes = kuhn_box(1);
  for (size_t i = 0, n = nodes.size(); i < n; ++i) nodes.push_back(nodes[i] + 8);
  std::vector<long> part(12, 0);
  EXPECT_EQ(connect_element_parts(nodes, 4, part), 0);
  EXPECT_EQ(part, std::vector<long>(12, 0));
}

}  // namespace
}  // namespace ffeti

namespace ffeti {
namespace {

TEST(TetrahedronQuality, FlatnessIsVolumeOverTheCubeOfTheLongestEdge) {
  // The unit corner: volume 1/6, longest edge sqrt 2.
  EXPECT_NEAR(tetrahedron_flatness({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}), 1 / (6 * std::pow(2, 1.5)), 1e-15);
  // A regular one: 1 / (6 sqrt 2) = 0.118, above the bound by five orders.
  const double regular = tetrahedron_flatness({{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}}});
  EXPECT_NEAR(regular, 1 / (6 * std::sqrt(2.0)), 1e-15);
  // tests/edp/bad-input-3d.edp's flat one: its fourth vertex 1e-7 off the face (1,0,0),
  // (0,1,0), (0,0,1): 5e-9, refused by both front ends.
  const double flat = tetrahedron_flatness({{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.5, 0.25, 0.2500001}}});
  EXPECT_LT(flat, kFlatTetrahedron);
  EXPECT_GT(flat, 0);
  EXPECT_EQ(tetrahedron_flatness({{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}}}), 0);
}

TEST(TriangleQuality, FlatnessIsAreaOverTheSquareOfTheLongestEdge) {
  // square()'s halves: area 1/2, longest edge sqrt 2: 1/4; a regular one sqrt(3)/4, in any plane.
  EXPECT_NEAR(triangle_flatness({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}), 0.25, 1e-15);
  EXPECT_NEAR(triangle_flatness({{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}), std::sqrt(3.0) / 4, 1e-15);
  // tests/edp/flat-triangle.idp's flat one: its third vertex 1e-7 off the hypotenuse: 2.5e-8.
  const double flat = triangle_flatness({{{1, 0, 0}, {0.5, 0.5000001, 0}, {0, 1, 0}}});
  EXPECT_NEAR(flat, 2.5e-8, 1e-12);
  EXPECT_LT(flat, kFlatTriangle);
  EXPECT_EQ(triangle_flatness({{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}}}), 0);
}

}  // namespace
}  // namespace ffeti
