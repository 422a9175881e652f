// Which elements of a simplicial mesh touch across a facet (an edge of a triangle, a face of
// a tetrahedron), from the element-to-node table alone: the same code for plane and solid
// meshes, and no mesh library needed (connect_parts works on its answer, the plane meshes'
// split on which element lies across each facet).
#pragma once

#include <vector>

namespace ffeti {

/// The elements across each facet of each element: `element_nodes` holds
/// `nodes_per_element` node numbers per element (3: triangles, 4: tetrahedra), one element
/// after another. Two elements are neighbours when they share a facet, i.e. all but one of
/// their nodes (two for triangles, three for tetrahedra); elements sharing only a vertex or
/// (in 3D) an edge are not. Result[k] lists element k's neighbours in ascending order
/// (nodes_per_element in a conforming mesh, fewer on the boundary; more where a facet is
/// shared by more than two elements, each pair of them linked). InputError when nodes_per_element is
/// not 3 or 4, the table's size is not a multiple of it or a node number is negative.
std::vector<std::vector<int>> facet_neighbours(const std::vector<int>& element_nodes, int nodes_per_element);

/// Per facet, the element across it: entry k * nodes_per_element + j is the element sharing
/// element k's facet j (the one opposite its node j), -1 on the mesh's boundary (where a
/// facet has more than two elements, each sees the next of them in node order). The same
/// checks as facet_neighbours().
std::vector<int> element_across_facets(const std::vector<int>& element_nodes, int nodes_per_element);

}  // namespace ffeti
