#include "mesh/split_parts.h"

#include "base/errors.h"

#include <algorithm>
#include <string>

namespace ffeti {
namespace {

void check_input(const SplitInput& body, const std::vector<long>& part, long part_count) {
  const size_t n = static_cast<size_t>(body.nodes_per_element);
  if (n != 3 && n != 4)
    throw InputError("nodes_per_element: 3 (triangles) or 4 (tetrahedra), got " + std::to_string(n));
  if (body.element_nodes.size() % n != 0 || body.facet_neighbour.size() != body.element_nodes.size() ||
      body.facet_label.size() != body.element_nodes.size())
    throw InputError("split_parts: the element, neighbour and label tables differ in size");
  if (part.size() * n != body.element_nodes.size())
    throw InputError("part: has " + std::to_string(part.size()) + " entries for the " +
                     std::to_string(body.element_nodes.size() / n) + " elements (one part number per element)");
  if (part_count < 1) throw InputError("nparts: needs at least one part, got " + std::to_string(part_count));
  for (size_t k = 0; k < part.size(); ++k)
    if (part[k] < 0 || part[k] >= part_count)
      throw InputError("part: element " + std::to_string(k) + " is in part " + std::to_string(part[k]) +
                       ", outside 0 .. " + std::to_string(part_count - 1));
  for (const int node : body.element_nodes)
    if (node < 0 || node >= body.node_count)
      throw InputError("element_nodes: node " + std::to_string(node) + " outside 0 .. " +
                       std::to_string(body.node_count - 1));
}

}  // namespace

std::vector<MeshPart> split_parts(const SplitInput& body, const std::vector<long>& part, long part_count,
                                  int interface_label) {
  check_input(body, part, part_count);
  const int n = body.nodes_per_element;
  std::vector<MeshPart> parts(static_cast<size_t>(part_count));
  for (size_t k = 0; k < part.size(); ++k) parts[static_cast<size_t>(part[k])].elements.push_back(static_cast<int>(k));
  // local[node]: the node's position in the part being built, -1 elsewhere; reset over the
  // part's own nodes only, so that the whole split stays linear in the body's size.
  std::vector<int> local(static_cast<size_t>(body.node_count), -1);
  for (long p = 0; p < part_count; ++p) {
    MeshPart& piece = parts[static_cast<size_t>(p)];
    if (piece.elements.empty())
      throw InputError("part: part " + std::to_string(p) + " of " + std::to_string(part_count) +
                       " has no element: ask for fewer parts or refine the mesh");
    piece.element_nodes.reserve(piece.elements.size() * static_cast<size_t>(n));
    for (size_t e = 0; e < piece.elements.size(); ++e) {
      const size_t k = static_cast<size_t>(piece.elements[e]);
      for (int j = 0; j < n; ++j) {
        const size_t at = k * static_cast<size_t>(n) + static_cast<size_t>(j);
        int& position = local[static_cast<size_t>(body.element_nodes[at])];
        if (position < 0) {
          position = static_cast<int>(piece.nodes.size());
          piece.nodes.push_back(body.element_nodes[at]);
        }
        piece.element_nodes.push_back(position);
        const int across = body.facet_neighbour[at];
        const bool cut = across < 0 || part[static_cast<size_t>(across)] != p;
        const bool labelled = body.facet_label[at] >= 0;
        // A labelled facet inside the part: both elements see it, the lower number keeps it.
        if (cut || (labelled && static_cast<size_t>(across) > k)) {
          piece.facet_elements.push_back(static_cast<int>(e));
          piece.facet_sides.push_back(j);
          piece.facet_labels.push_back(labelled ? body.facet_label[at] : interface_label);
        }
      }
    }
    // The nodes in the body's order, as trunc numbers them: the parts' dofs, hence every
    // sum over them, come out as trunc's parts give them (the same answers to the last bit).
    std::vector<int> first_met = piece.nodes;
    std::sort(piece.nodes.begin(), piece.nodes.end());
    for (size_t i = 0; i < piece.nodes.size(); ++i) local[static_cast<size_t>(piece.nodes[i])] = static_cast<int>(i);
    for (int& position : piece.element_nodes) position = local[static_cast<size_t>(first_met[static_cast<size_t>(position)])];
    for (const int node : piece.nodes) local[static_cast<size_t>(node)] = -1;
  }
  return parts;
}

}  // namespace ffeti
