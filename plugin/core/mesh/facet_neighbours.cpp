#include "mesh/facet_neighbours.h"

#include "base/errors.h"

#include <algorithm>
#include <array>
#include <string>
#include <utility>

namespace ffeti {

std::vector<std::vector<int>> facet_neighbours(const std::vector<int>& element_nodes, int nodes_per_element) {
  if (nodes_per_element != 3 && nodes_per_element != 4)
    throw InputError("nodes_per_element: 3 (triangles) or 4 (tetrahedra), got " + std::to_string(nodes_per_element));
  const size_t n = static_cast<size_t>(nodes_per_element);
  if (element_nodes.size() % n != 0)
    throw InputError("element_nodes: " + std::to_string(element_nodes.size()) + " entries are not a whole number of " +
                     std::to_string(n) + "-node elements");
  for (size_t i = 0; i < element_nodes.size(); ++i)
    if (element_nodes[i] < 0)
      throw InputError("element_nodes: node " + std::to_string(element_nodes[i]) + " of element " +
                       std::to_string(i / n) + " is negative");
  const size_t elements = element_nodes.size() / n;
  // Each facet as its sorted node numbers (a triangle's edge padded with -1), with its
  // element; after sorting, elements sharing a facet sit next to each other.
  std::vector<std::pair<std::array<int, 3>, int>> facets;
  facets.reserve(elements * n);
  for (size_t k = 0; k < elements; ++k)
    for (size_t left_out = 0; left_out < n; ++left_out) {
      std::array<int, 3> key{-1, -1, -1};
      size_t used = 0;
      for (size_t j = 0; j < n; ++j)
        if (j != left_out) key[used++] = element_nodes[k * n + j];
      // Three compare-swaps sort the key (the padding, if any, goes first).
      if (key[0] > key[1]) std::swap(key[0], key[1]);
      if (key[1] > key[2]) std::swap(key[1], key[2]);
      if (key[0] > key[1]) std::swap(key[0], key[1]);
      facets.emplace_back(key, static_cast<int>(k));
    }
  std::sort(facets.begin(), facets.end());
  std::vector<std::vector<int>> neighbours(elements);
  for (size_t first = 0; first < facets.size();) {
    size_t last = first + 1;
    while (last < facets.size() && facets[last].first == facets[first].first) ++last;
    // A facet of more than two elements (a non-manifold mesh) links each pair of them.
    for (size_t a = first; a < last; ++a)
      for (size_t b = first; b < last; ++b)
        if (facets[a].second != facets[b].second)
          neighbours[static_cast<size_t>(facets[a].second)].push_back(facets[b].second);
    first = last;
  }
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

}  // namespace ffeti
