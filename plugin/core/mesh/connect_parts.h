// Mesh partitions whose parts are connected: a disconnected subdomain has rigid modes that
// no kernel candidate covers, and METIS may give a part two pieces (both jaws of a spanner,
// two corners of a quarter sphere).
#pragma once

#include <vector>

namespace ffeti {

/// Makes every part of a partition of a mesh connected through element facets: each
/// facet-connected piece of a part other than its largest (a stray piece) goes to the
/// neighbouring part it shares most facets with, counting only facets with the largest
/// pieces (a stray piece touching strays only waits a round), until no stray piece is left;
/// on a mesh in several pieces, strays in a piece holding no part's largest piece stay
/// where they are. `neighbours[k]`
/// are the elements across the facets of element k (entries -1 or k itself are ignored);
/// `part[k]` is element k's part, changed in place. Returns the number of elements moved.
/// InputError when the sizes differ.
long connect_parts(const std::vector<std::vector<int>>& neighbours, std::vector<long>& part);

/// The same from the element-to-node table of a triangle (3 nodes per element) or
/// tetrahedron (4) mesh: neighbours share an edge or a face (facet_neighbours).
long connect_element_parts(const std::vector<int>& element_nodes, int nodes_per_element, std::vector<long>& part);

}  // namespace ffeti
