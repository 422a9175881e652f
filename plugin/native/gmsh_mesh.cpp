#include "native/gmsh_mesh.h"

#include "base/errors.h"
#include "mesh/element_quality.h"

#include <gmsh.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace ffeti::native {
namespace {

constexpr int kLine2 = 1, kTriangle3 = 2, kTetrahedron4 = 4;  // gmsh element types

/// gmsh reports errors by throwing (its API), sometimes as std::string.
template <class Step>
void with_gmsh(const std::string& what, Step step) {
  try {
    step();
  } catch (const std::string& message) {
    throw InputError(what + ": gmsh: " + message);
  } catch (const std::exception& error) {
    throw InputError(what + ": gmsh: " + error.what());
  }
}

std::string group_list(int dim) {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  std::string list;
  for (const auto& [d, tag] : groups) list += (list.empty() ? "" : ", ") + std::to_string(tag);
  return list.empty() ? "none" : list;
}

const char* dimension_word(int dim) {
  return dim == 0 ? "point" : dim == 1 ? "curve" : dim == 2 ? "surface" : "volume";
}

const char* element_word(int type) { return type == kTriangle3 ? "3-node triangles" : "4-node tetrahedra"; }

}  // namespace

GmshMesh::GmshMesh(const std::string& path) : path_(path) {
  if (!std::ifstream(path)) throw InputError(path + ": cannot open the mesh file");
  gmsh::initialize();  // one GmshMesh at a time: gmsh keeps global state
  try {
    gmsh::option::setNumber("General.Verbosity", 1);  // errors only: ffeti-solve prints its own lines
    with_gmsh(path, [&] {
      gmsh::open(path);
      gmsh::model::getCurrent(model_);
    });
    std::vector<NodeTag> tags;
    std::vector<double> coordinates, parametric;
    gmsh::model::mesh::getNodes(tags, coordinates, parametric, -1, -1, false, false);
    if (tags.empty()) throw InputError(path + ": the mesh has no nodes (not a mesh file, or not meshed)");
    positions_.reserve(tags.size());
    for (size_t i = 0; i < tags.size(); ++i)
      positions_[tags[i]] = {coordinates[3 * i], coordinates[3 * i + 1], coordinates[3 * i + 2]};
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups);
    for (const auto& [dim, tag] : groups) dimension_ = std::max(dimension_, dim);
  } catch (...) {
    gmsh::finalize();  // the destructor does not run for a constructor that throws
    throw;
  }
}

GmshMesh::~GmshMesh() {
  gmsh::finalize();
}

std::array<double, 3> GmshMesh::position(NodeTag node) const {
  const auto found = positions_.find(node);
  if (found == positions_.end())
    throw InputError(path_ + ": node " + std::to_string(node) + " is not in the mesh");
  return found->second;
}

void GmshMesh::require_group(int dim, int group) const {
  gmsh::vectorpair groups;
  gmsh::model::getPhysicalGroups(groups, dim);
  if (std::find(groups.begin(), groups.end(), std::make_pair(dim, group)) == groups.end())
    throw InputError(path_ + ": no physical " + dimension_word(dim) + " " + std::to_string(group) +
                     " (the mesh has " + group_list(dim) + ")");
}

std::vector<Element> GmshMesh::elements(int dim, int group, int partition, int type, int count) const {
  require_group(dim, group);
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
  std::vector<Element> result;
  for (int entity : entities) {
    if (partition > 0) {  // a partitioned mesh: keep the entities of that partition
      std::vector<int> partitions;
      gmsh::model::getPartitions(dim, entity, partitions);
      if (std::find(partitions.begin(), partitions.end(), partition) == partitions.end()) continue;
    }
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, dim, entity);
    for (size_t t = 0; t < types.size(); ++t) {
      if (types[t] != type)
        throw InputError(path_ + ": physical " + dimension_word(dim) + " " + std::to_string(group) +
                         " holds elements of gmsh type " + std::to_string(types[t]) + "; ffeti-solve reads " +
                         element_word(type) + " only");
      for (size_t e = 0; e < element_tags[t].size(); ++e)
        result.push_back({element_tags[t][e], std::vector<NodeTag>(node_tags[t].begin() + static_cast<long>(count * e),
                                                                   node_tags[t].begin() + static_cast<long>(count * (e + 1)))});
    }
  }
  if (result.empty())
    throw InputError(path_ + ": physical " + dimension_word(dim) + " " + std::to_string(group) + " has no " +
                     (type == kTriangle3 ? "triangles" : "tetrahedra") +
                     (partition > 0 ? " in partition " + std::to_string(partition) : std::string()));
  return result;
}

std::vector<Element> GmshMesh::cells(int dim, int group, int partition) const {
  std::vector<Element> cells =
      dim == 2 ? elements(2, group, partition, kTriangle3, 3) : elements(3, group, partition, kTetrahedron4, 4);
  check_cells(dim, group, cells);
  return cells;
}

void GmshMesh::check_cells(int dim, int group, const std::vector<Element>& cells) const {
  for (const Element& t : cells) {
    double ratio = 0;
    if (dim == 2) {
      std::array<std::array<double, 3>, 3> p;
      for (size_t i = 0; i < 3; ++i) p[i] = position(t.nodes[i]);
      ratio = triangle_flatness(p);
    } else {
      std::array<std::array<double, 3>, 4> p;
      for (size_t i = 0; i < 4; ++i) p[i] = position(t.nodes[i]);
      ratio = tetrahedron_flatness(p);
    }
    const double bound = dim == 2 ? kFlatTriangle : kFlatTetrahedron;
    if (!(ratio >= bound)) {
      std::ostringstream message;
      message << path_ << ": physical " << (dim == 2 ? "surface " : "volume ") << group << ": "
              << (dim == 2 ? "triangle " : "tetrahedron ") << t.tag << " (nodes";
      for (size_t i = 0; i < t.nodes.size(); ++i) message << (i ? ", " : " ") << t.nodes[i];
      message << ") is flat or degenerate: |" << (dim == 2 ? "area| / (longest edge)^2" : "volume| / (longest edge)^3")
              << " = " << ratio << ", below " << bound << " (a regular "
              << (dim == 2 ? "triangle has 0.433" : "tetrahedron has 0.118") << "): remesh or remove it";
      throw InputError(message.str());
    }
  }
}

std::vector<std::array<NodeTag, 2>> GmshMesh::segments(int group) const {
  require_group(1, group);
  std::vector<int> entities;
  gmsh::model::getEntitiesForPhysicalGroup(1, group, entities);
  std::vector<std::array<NodeTag, 2>> result;
  for (int entity : entities) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, node_tags;
    gmsh::model::mesh::getElements(types, element_tags, node_tags, 1, entity);
    for (size_t t = 0; t < types.size(); ++t) {
      if (types[t] != kLine2)
        throw InputError(path_ + ": physical curve " + std::to_string(group) + " holds elements of gmsh type " +
                         std::to_string(types[t]) + "; ffeti-solve reads 2-node lines only");
      for (size_t e = 0; e < element_tags[t].size(); ++e)
        result.push_back({node_tags[t][2 * e], node_tags[t][2 * e + 1]});
    }
  }
  return result;
}

std::vector<std::array<NodeTag, 3>> GmshMesh::faces(int group) const {
  std::vector<std::array<NodeTag, 3>> result;
  for (const Element& e : elements(2, group, 0, kTriangle3, 3)) result.push_back({e.nodes[0], e.nodes[1], e.nodes[2]});
  return result;
}

std::vector<NodeTag> GmshMesh::nodes(int dim, int group) const {
  require_group(dim, group);
  std::vector<NodeTag> tags;
  std::vector<double> coordinates;
  gmsh::model::mesh::getNodesForPhysicalGroup(dim, group, tags, coordinates);
  std::sort(tags.begin(), tags.end());
  tags.erase(std::unique(tags.begin(), tags.end()), tags.end());
  return tags;
}

}  // namespace ffeti::native
