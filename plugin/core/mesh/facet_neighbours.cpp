#include "mesh/facet_neighbours.h"

#include "base/errors.h"

#include <algorithm>
#include <array>
#include <string>
#include <tuple>
#include <utility>

namespace ffeti {

namespace {

/// A facet as its sorted node numbers (a triangle's edge padded with -1), with its element
/// and the element's node it leaves out (the facet's number within the element).
struct Facet {
  std::array<int, 3> key;
  int element, left_out;
  bool operator<(const Facet& other) const {
    return std::tie(key, element, left_out) < std::tie(other.key, other.element, other.left_out);
  }
};

/// Every facet of every element, sorted by its nodes: elements sharing a facet sit next to
/// each other. InputError on the table's faults facet_neighbours() names.
std::vector<Facet> sorted_facets(const std::vector<int>& element_nodes, int nodes_per_element) {
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
  std::vector<Facet> facets;
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
      facets.push_back({key, static_cast<int>(k), static_cast<int>(left_out)});
    }
  std::sort(facets.begin(), facets.end());
  return facets;
}

/// body(first, last) for each run [first, last) of facets with the same nodes.
template <class Body>
void for_each_shared_facet(const std::vector<Facet>& facets, Body&& body) {
  for (size_t first = 0; first < facets.size();) {
    size_t last = first + 1;
    while (last < facets.size() && facets[last].key == facets[first].key) ++last;
    body(first, last);
    first = last;
  }
}

}  // namespace

std::vector<std::vector<int>> facet_neighbours(const std::vector<int>& element_nodes, int nodes_per_element) {
  const std::vector<Facet> facets = sorted_facets(element_nodes, nodes_per_element);
  std::vector<std::vector<int>> neighbours(element_nodes.size() / static_cast<size_t>(nodes_per_element));
  for_each_shared_facet(facets, [&](size_t first, size_t last) {
    // A facet of more than two elements (a non-manifold mesh) links each pair of them.
    for (size_t a = first; a < last; ++a)
      for (size_t b = first; b < last; ++b)
        if (facets[a].element != facets[b].element)
          neighbours[static_cast<size_t>(facets[a].element)].push_back(facets[b].element);
  });
  for (auto& list : neighbours) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  return neighbours;
}

std::vector<int> element_across_facets(const std::vector<int>& element_nodes, int nodes_per_element) {
  const std::vector<Facet> facets = sorted_facets(element_nodes, nodes_per_element);
  const size_t n = static_cast<size_t>(nodes_per_element);
  std::vector<int> across(element_nodes.size(), -1);
  for_each_shared_facet(facets, [&](size_t first, size_t last) {
    // Of more than two elements on one facet, each sees the next one in the run.
    if (last - first < 2) return;
    for (size_t a = first; a < last; ++a) {
      const Facet& next = facets[a + 1 < last ? a + 1 : first];
      across[static_cast<size_t>(facets[a].element) * n + static_cast<size_t>(facets[a].left_out)] = next.element;
    }
  });
  return across;
}

}  // namespace ffeti
