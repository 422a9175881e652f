// A mesh cut into its parts in one pass over the elements: each part's nodes, elements and
// boundary facets, for the front end to build the part meshes from. FreeFEM's trunc, called
// once per part, reads the whole body each time (O(parts x elements): half an hour at the
// 3D boxes' largest scale); this reads each element and facet a bounded number of times.
#pragma once

#include <vector>

namespace ffeti {

/// One part of a split mesh. `nodes` are the body's node numbers the part uses, ascending
/// (trunc's order); `elements` the body's element numbers of the part, ascending, and
/// `element_nodes` their nodes as positions in `nodes`. Each boundary facet of the part is
/// (facet_elements[i], facet_sides[i], facet_labels[i]): a position in `elements`, the
/// element's facet (the one opposite its node of that number) and the facet's label.
struct MeshPart {
  std::vector<int> nodes, elements, element_nodes;
  std::vector<int> facet_elements, facet_sides, facet_labels;
};

/// The body's mesh as the split reads it: `nodes_per_element` (3 or 4) node numbers per
/// element in `element_nodes`; for facet j of element k (opposite its node j) at
/// k * nodes_per_element + j, the element across it (`facet_neighbour`, negative on the
/// body's outer boundary) and the label of the body's boundary facet lying there
/// (`facet_label`, negative where the body has none; an internal labelled facet is labelled
/// from both sides).
struct SplitInput {
  int nodes_per_element = 4;
  int node_count = 0;
  std::vector<int> element_nodes, facet_neighbour, facet_label;
};

/// Cuts the body into `part_count` parts, `part[k]` being element k's. A part's boundary
/// facets are those whose neighbour lies in another part or outside the body, with the
/// body's label where it has one and `interface_label` on the cuts; a labelled facet inside
/// one part is kept once. InputError on sizes that do not match, a part number out of
/// [0, part_count) or an empty part.
std::vector<MeshPart> split_parts(const SplitInput& body, const std::vector<long>& part, long part_count,
                                  int interface_label);

}  // namespace ffeti
