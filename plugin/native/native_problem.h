// The core's input (SubdomainInput, ContactInput, settings) built from a problem file, its
// gmsh mesh and the subdomain systems on disk, for the subdomains one rank holds.
#pragma once

#include "feti/dual_system.h"
#include "feti/feti_problem.h"
#include "native/gmsh_mesh.h"
#include "native/problem_file.h"
#include "native/system_files.h"

#include <map>
#include <vector>

namespace ffeti::native {

/// What the result writers need to know about one subdomain beyond the core's input.
struct SubdomainLayout {
  int id = 0;                       ///< global index (position in the problem file)
  std::vector<DofLocation> dofs;    ///< node and component of each row
  std::map<std::pair<NodeTag, int>, int> rows;  ///< the row of each (node, component)
  std::vector<Element> cells;       ///< the mesh cells of the subdomain (triangles, or tetrahedra in 3D)
};

struct NativeInput {
  std::vector<SubdomainInput> subdomains;  ///< this rank's, in ascending global index
  std::vector<SubdomainLayout> layouts;    ///< the same subdomains
  ContactInput contact;                    ///< of this rank's subdomains
  /// Master segments (faces in 3D) on this rank's subdomains, and on the master groups in
  /// all: every one must lie on some rank's subdomain (checked by the caller over the ranks).
  long master_segments_here = 0, master_segments_total = 0;
  std::vector<int> ids;                    ///< the subdomains of this rank, ascending
  FetiSetupSettings setup;
  DualSolveSettings solve;
  int verbosity = 0;                       ///< progress lines (solver.verbosity)
};

/// The subdomains of `rank` among `ranks` (ascending), balanced by cells: the largest
/// first to the rank with the fewest so far.
std::vector<int> balanced_subdomains(const std::vector<std::vector<Element>>& cells, int rank, int ranks);

/// Builds the input of this rank's subdomains (`ids`, balanced_subdomains). InputError naming the problem
/// file entry and the data file for sizes that disagree (matrix, right-hand side, dof
/// map), dofs at nodes outside the subdomain's cells, cell nodes without dofs, physical
/// groups that do not exist, a mesh of the wrong dimension for "components", flat
/// tetrahedra, bad options, and (checked on every rank alike, from the whole mesh) a cell in
/// two subdomains, a node in two bodies, a Dirichlet group without a node in the subdomains
/// or fixing a dof to two values, a contact pair on one body.
NativeInput build_input(const ProblemFile& problem, const GmshMesh& mesh, int rank, int ranks);

}  // namespace ffeti::native
