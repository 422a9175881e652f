// A 2D gmsh mesh as ffeti-solve needs it, read through gmsh's C++ API (libgmsh): node
// coordinates, the triangles of physical surfaces, the segments of physical curves and the
// nodes of any physical group. Only linear elements (3-node triangles, 2-node lines): the
// node-to-segment contact and the P1 stress views assume them.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace ffeti::native {

using NodeTag = std::size_t;

struct Triangle {
  std::size_t tag;
  std::array<NodeTag, 3> nodes;
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
  std::array<double, 2> position(NodeTag node) const;

  /// The triangles of physical surface `group`; with partition > 0 only those of that mesh
  /// partition. InputError naming the group (and listing the file's groups) if it does
  /// not exist, or if it holds elements other than 3-node triangles.
  std::vector<Triangle> triangles(int group, int partition = 0) const;
  /// The 2-node segments of physical curve `group`, in the curve's orientation.
  std::vector<std::array<NodeTag, 2>> segments(int group) const;
  /// Every node of physical group `group` of dimension `dim` (0, 1 or 2), sorted.
  std::vector<NodeTag> nodes(int dim, int group) const;

 private:
  void require_group(int dim, int group) const;

  std::string path_, model_;
  std::unordered_map<NodeTag, std::array<double, 2>> positions_;
};

}  // namespace ffeti::native
