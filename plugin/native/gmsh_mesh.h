// A gmsh mesh as ffeti-solve needs it, read through gmsh's C++ API (libgmsh): node
// coordinates, the cells of physical surfaces (2D: triangles) or volumes (3D: tetrahedra),
// the segments of physical curves, the triangles of physical surfaces and the nodes of any
// physical group. Only linear elements (3-node triangles, 4-node tetrahedra, 2-node lines):
// the node-to-segment and node-to-face contact and the P1 stress views assume them.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace ffeti::native {

using NodeTag = std::size_t;

/// A mesh cell: a triangle (3 nodes) of a plane problem, a tetrahedron (4 nodes) of a
/// solid one, or a boundary triangle.
struct Element {
  std::size_t tag;
  std::vector<NodeTag> nodes;
};

class GmshMesh {
 public:
  /// Opens `path` with gmsh (any format gmsh reads). InputError naming the file if it is
  /// missing or gmsh cannot read it. Keeps gmsh's model open for writing views.
  explicit GmshMesh(const std::string& path);
  ~GmshMesh();
  GmshMesh(const GmshMesh&) = delete;
  GmshMesh& operator=(const GmshMesh&) = delete;

  const std::string& path() const { return path_; }
  const std::string& model_name() const { return model_; }
  /// x, y, z (z = 0 in a plane mesh).
  std::array<double, 3> position(NodeTag node) const;
  /// The largest dimension of the mesh's physical groups (2: surfaces, 3: volumes).
  int dimension() const { return dimension_; }

  /// The cells of physical group `group` of dimension `dim` (2: 3-node triangles of a
  /// surface, 3: 4-node tetrahedra of a volume); with partition > 0 only those of that mesh
  /// partition. InputError naming the group (and listing the file's groups) if it does not
  /// exist, holds other elements or none, or (volumes) holds a flat tetrahedron.
  std::vector<Element> cells(int dim, int group, int partition = 0) const;
  /// The 2-node segments of physical curve `group`, in the curve's orientation.
  std::vector<std::array<NodeTag, 2>> segments(int group) const;
  /// The 3-node triangles of physical surface `group` (boundary faces of a solid).
  std::vector<std::array<NodeTag, 3>> faces(int group) const;
  /// Every node of physical group `group` of dimension `dim` (0 to 3), sorted.
  std::vector<NodeTag> nodes(int dim, int group) const;

 private:
  void require_group(int dim, int group) const;
  /// The elements of `group` whose gmsh type must be `type` (`nodes` per element).
  std::vector<Element> elements(int dim, int group, int partition, int type, int nodes) const;
  /// InputError naming the file, the group and the element unless every cell (tetrahedra, or
  /// triangles in the plane) is above its flatness bound (mesh/element_quality.h).
  void check_cells(int dim, int group, const std::vector<Element>& cells) const;

  std::string path_, model_;
  int dimension_ = 0;
  std::unordered_map<NodeTag, std::array<double, 3>> positions_;
};

}  // namespace ffeti::native
