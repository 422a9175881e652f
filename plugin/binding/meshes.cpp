// Mesh functions for the scripts' partitions: parts made connected (fetiConnectParts), a
// mesh or mesh3 cut into its part meshes in one pass (fetiSplitMesh, fetiSplitMesh3), and its
// flattest element (fetiFlattestElement). The mesh work itself is the
// core's (mesh/connect_parts, mesh/split_parts); here only FreeFEM's mesh types.
#include "binding/convert.h"
#include "binding/functions.h"
#include "binding/handles.h"

#include "base/errors.h"
#include "mesh/connect_parts.h"
#include "mesh/element_quality.h"
#include "mesh/facet_neighbours.h"
#include "mesh/split_parts.h"

#include "AFunction_ext.hpp"  // OneOperator5_

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace ffeti::binding {
namespace {

/// The element-to-node table of a triangle (n = 3) or tetrahedron (n = 4) mesh.
template <int n, class MeshType>
std::vector<int> element_nodes(const MeshType& Th) {
  std::vector<int> nodes(static_cast<size_t>(Th.nt) * n);
  for (int k = 0; k < Th.nt; ++k)
    for (int j = 0; j < n; ++j) nodes[static_cast<size_t>(k) * n + static_cast<size_t>(j)] = Th(k, j);
  return nodes;
}

std::vector<long> part_numbers(const KN<long>& part) {
  std::vector<long> parts(static_cast<size_t>(part.N()));
  for (long k = 0; k < part.N(); ++k) parts[static_cast<size_t>(k)] = part[k];
  return parts;
}

/// Makes every part of a mesh partition (`part`: one entry per element of Th, a mesh or a
/// mesh3) connected through element facets (edges of triangles, faces of tetrahedra): each
/// piece of a part other than its largest goes to the neighbouring part it shares most
/// facets with, until no piece is left (METIS may give a part two pieces, e.g. both jaws of
/// a spanner, and a disconnected subdomain has rigid modes no kernel candidate covers).
/// Returns the number of elements moved.
template <class MeshType, int n>
long feti_connect_parts(const MeshType* const& mesh, KN<long>* const& part) {
  return guarded("fetiConnectParts", [&] {
    const MeshType& Th = *mesh;
    if (part->N() != Th.nt)
      throw InputError("part: has " + std::to_string(part->N()) + " entries for the " + std::to_string(Th.nt) +
                       " elements of Th (one part number per element)");
    std::vector<long> parts = part_numbers(*part);
    const long moved = connect_element_parts(element_nodes<n>(Th), n, parts);
    copy_to(parts, *part);
    return moved;
  });
}

/// The body as split_parts reads it, the element across each facet given
/// (`facet_neighbour`): its element-to-node table, and the labels of its boundary facets
/// (an internal labelled facet from both sides: in the element across, the facet opposite
/// the node the two elements do not share).
template <int n, class MeshType>
SplitInput split_input(const MeshType& Th, std::vector<int> facet_neighbour) {
  SplitInput body;
  body.nodes_per_element = n;
  body.node_count = Th.nv;
  body.element_nodes = element_nodes<n>(Th);
  body.facet_neighbour = std::move(facet_neighbour);
  body.facet_label.assign(body.element_nodes.size(), -1);
  for (int b = 0; b < Th.nbBrdElmts(); ++b) {
    int j = 0;
    const int k = Th.BoundaryElement(b, j);
    const size_t at = n * static_cast<size_t>(k) + static_cast<size_t>(j);
    body.facet_label[at] = Th.be(b).lab;
    const int across = body.facet_neighbour[at];
    if (across < 0) continue;
    for (int side = 0; side < n; ++side) {
      bool shared = false;  // the node is one of the facet's (element k's but its j-th)
      for (int i = 0; i < n; ++i) shared = shared || (i != j && Th(across, side) == Th(k, i));
      if (!shared) body.facet_label[n * static_cast<size_t>(across) + static_cast<size_t>(side)] = Th.be(b).lab;
    }
  }
  return body;
}

/// A mesh3 as split_parts reads it: FreeFEM's own adjacency (built with the mesh) gives the
/// element across each face.
SplitInput split_input(const Mesh3& Th) {
  std::vector<int> across(4 * static_cast<size_t>(Th.nt), -1);
  for (int k = 0; k < Th.nt; ++k)
    for (int j = 0; j < 4; ++j) {
      int face_there = j;
      across[4 * static_cast<size_t>(k) + static_cast<size_t>(j)] = std::max(Th.ElementAdj(k, face_there), -1);
    }
  return split_input<4>(Th, std::move(across));
}

/// A plane mesh as split_parts reads it: the element across each edge from the
/// element-to-node table (FreeFEM's own 2D adjacency keeps its links private).
SplitInput split_input(const Mesh& Th) { return split_input<3>(Th, element_across_facets(element_nodes<3>(Th), 3)); }

/// One part as a FreeFEM mesh: vertices and triangles with their labels, each boundary
/// edge ordered as its triangle's edge (the part on its left, as trunc orders them).
Mesh* part_mesh(const Mesh& Th, const MeshPart& piece) {
  const int nv = static_cast<int>(piece.nodes.size()), nt = static_cast<int>(piece.elements.size());
  const int nbe = static_cast<int>(piece.facet_elements.size());
  auto* vertices = new Mesh::Vertex[static_cast<size_t>(nv)];
  auto* triangles = new Mesh::Triangle[static_cast<size_t>(nt)];
  auto* edges = new BoundaryEdge[static_cast<size_t>(nbe)];
  for (int i = 0; i < nv; ++i) {
    const Mesh::Vertex& from = Th(piece.nodes[static_cast<size_t>(i)]);
    vertices[i].x = from.x;
    vertices[i].y = from.y;
    vertices[i].lab = from.lab;
  }
  for (int e = 0; e < nt; ++e) {
    const size_t at = 3 * static_cast<size_t>(e);
    triangles[e].set(vertices, piece.element_nodes[at], piece.element_nodes[at + 1], piece.element_nodes[at + 2],
                     Th[piece.elements[static_cast<size_t>(e)]].lab);
  }
  for (int f = 0; f < nbe; ++f) {
    const size_t at = 3 * static_cast<size_t>(piece.facet_elements[static_cast<size_t>(f)]);
    const int side = piece.facet_sides[static_cast<size_t>(f)];
    edges[f].set(vertices, piece.element_nodes[at + static_cast<size_t>((side + 1) % 3)],
                 piece.element_nodes[at + static_cast<size_t>((side + 2) % 3)], piece.facet_labels[static_cast<size_t>(f)]);
  }
  return new Mesh(nv, nt, nbe, vertices, triangles, edges);
}

/// One part as a FreeFEM mesh3: vertices and tetrahedra with their labels, each boundary
/// triangle ordered as its tetrahedron's face (outward, as FreeFEM orders faces).
Mesh3* part_mesh(const Mesh3& Th, const MeshPart& piece) {
  const int nv = static_cast<int>(piece.nodes.size()), nt = static_cast<int>(piece.elements.size());
  const int nbe = static_cast<int>(piece.facet_elements.size());
  auto* vertices = new Vertex3[static_cast<size_t>(nv)];
  auto* tets = new Tet[static_cast<size_t>(nt)];
  auto* faces = new Triangle3[static_cast<size_t>(nbe)];
  for (int i = 0; i < nv; ++i) {
    const Vertex3& from = Th(piece.nodes[static_cast<size_t>(i)]);
    vertices[i].x = from.x;
    vertices[i].y = from.y;
    vertices[i].z = from.z;
    vertices[i].lab = from.lab;
  }
  for (int e = 0; e < nt; ++e) {
    int nodes[4];
    for (int j = 0; j < 4; ++j) nodes[j] = piece.element_nodes[4 * static_cast<size_t>(e) + static_cast<size_t>(j)];
    tets[e].set(vertices, nodes, Th[piece.elements[static_cast<size_t>(e)]].lab);
  }
  for (int f = 0; f < nbe; ++f) {
    const size_t e = static_cast<size_t>(piece.facet_elements[static_cast<size_t>(f)]);
    const int side = piece.facet_sides[static_cast<size_t>(f)];
    int nodes[3];
    for (int i = 0; i < 3; ++i) nodes[i] = piece.element_nodes[4 * e + static_cast<size_t>(Tet::nvface[side][i])];
    faces[f].set(vertices, nodes, piece.facet_labels[static_cast<size_t>(f)]);
  }
  auto* mesh = new Mesh3(nv, nt, nbe, vertices, tets, faces);
  mesh->BuildGTree();
  return mesh;
}

/// Cuts the mesh or mesh3 ThBody into the parts `part` gives (one part number per element,
/// from 0 to nparts - 1, nparts = its largest entry + 1) and stores part p in Th[first + p]:
/// the body's boundary labels kept, the cuts labelled `interfaceLabel`, the same meshes as
/// trunc(ThBody, part == p, label = interfaceLabel), numbered alike, in one pass over
/// the body instead of one per part. Returns the number of parts.
template <class MeshType>
long feti_split_mesh(KN<const MeshType*>* const& Th, const long& first, const MeshType* const& body,
                     KN<long>* const& part, const long& interface_label) {
  constexpr bool solid = std::is_same<MeshType, Mesh3>::value;
  return guarded(solid ? "fetiSplitMesh3" : "fetiSplitMesh", [&] {
    const std::string elements = solid ? "tetrahedra" : "triangles", element = solid ? "tetrahedron" : "triangle";
    if (part->N() != body->nt)
      throw InputError("part: has " + std::to_string(part->N()) + " entries for the " + std::to_string(body->nt) + " " +
                       elements + " of ThBody (one part number per " + element + ")");
    if (interface_label < std::numeric_limits<int>::min() || interface_label > std::numeric_limits<int>::max())
      throw InputError("interfaceLabel: " + std::to_string(interface_label) +
                       " is no mesh label (labels are int: narrowed, it would label the cuts with another number)");
    const std::vector<long> parts = part_numbers(*part);
    long count = 0;
    for (const long p : parts) count = std::max(count, p + 1);
    if (first < 0 || first + count > Th->N())
      throw InputError(std::string(solid ? "Th3" : "Th") + ": the parts " + std::to_string(first) + " .. " +
                       std::to_string(first + count - 1) + " do not all lie in the mesh array of " +
                       std::to_string(Th->N()));
    const std::vector<MeshPart> pieces = split_parts(split_input(*body), parts, count, static_cast<int>(interface_label));
    for (long p = 0; p < count; ++p) {
      const MeshType*& slot = (*Th)[first + p];
      if (slot) slot->destroy();  // the array owns its meshes (FreeFEM's DestroyKN destroys them)
      slot = part_mesh(*body, pieces[static_cast<size_t>(p)]);
    }
    return count;
  });
}

/// The flattest element of a mesh or mesh3 (mesh/element_quality.h): returns its flatness
/// (|area| / longest edge^2, |volume| / longest edge^3; +inf for an empty mesh) and puts its
/// number in *index (-1 if none). ffeti.idp's ffetiCheckMesh and ffetiCheckMesh3 ask it:
/// in a script, `area` and `volume` are whatever variables of those names it declared.
template <class MeshType>
double feti_flattest_element(const MeshType* const& mesh, long* const& index) {
  constexpr bool solid = std::is_same<MeshType, Mesh3>::value;
  return guarded("fetiFlattestElement", [&] {
    const MeshType& Th = *mesh;
    double worst = std::numeric_limits<double>::infinity();
    *index = -1;
    for (int k = 0; k < Th.nt; ++k) {
      double ratio = 0;
      if constexpr (solid) {
        std::array<std::array<double, 3>, 4> p;
        for (int j = 0; j < 4; ++j) {
          const auto& v = Th(Th(k, j));
          p[static_cast<size_t>(j)] = {v.x, v.y, v.z};
        }
        ratio = tetrahedron_flatness(p);
      } else {
        std::array<std::array<double, 3>, 3> p;
        for (int j = 0; j < 3; ++j) {
          const auto& v = Th(Th(k, j));
          p[static_cast<size_t>(j)] = {v.x, v.y, 0.0};
        }
        ratio = triangle_flatness(p);
      }
      if (ratio < worst) worst = ratio, *index = k;
    }
    return worst;
  });
}

}  // namespace

void add_mesh_functions() {
  Global.Add("fetiFlattestElement", "(", new OneOperator2_<double, pmesh, long*>(feti_flattest_element<Mesh>));
  Global.Add("fetiFlattestElement", "(", new OneOperator2_<double, pmesh3, long*>(feti_flattest_element<Mesh3>));
  Global.Add("fetiConnectParts", "(", new OneOperator2_<long, pmesh, KN<long>*>(feti_connect_parts<Mesh, 3>));
  Global.Add("fetiConnectParts", "(", new OneOperator2_<long, pmesh3, KN<long>*>(feti_connect_parts<Mesh3, 4>));
  Global.Add("fetiSplitMesh", "(",
             new OneOperator5_<long, KN<pmesh>*, long, pmesh, KN<long>*, long>(feti_split_mesh<Mesh>));
  // fetiSplitMesh takes either kind of mesh (the ffddm handoff macro serves both);
  // fetiSplitMesh3 stays the solid one's name.
  Global.Add("fetiSplitMesh", "(",
             new OneOperator5_<long, KN<pmesh3>*, long, pmesh3, KN<long>*, long>(feti_split_mesh<Mesh3>));
  Global.Add("fetiSplitMesh3", "(",
             new OneOperator5_<long, KN<pmesh3>*, long, pmesh3, KN<long>*, long>(feti_split_mesh<Mesh3>));
}

}  // namespace ffeti::binding
