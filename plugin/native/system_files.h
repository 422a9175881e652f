// Subdomain systems from files: the matrix and right-hand side as GetDP's Print[] writes
// them (Matlab text, from its PETSc back end) or in Matrix Market (read by CHOLMOD), and
// the map from their rows to mesh nodes and field components (GetDP's .pre file, or a
// plain list).
#pragma once

#include "factor/cholmod_factor.h"
#include "native/gmsh_mesh.h"

#include <string>
#include <vector>

namespace ffeti::native {

/// `.mtx`: Matrix Market (coordinate; general or symmetric), else GetDP's Matlab text
/// (file_mat_*.m). Returned with both triangles. InputError naming the file if it is
/// missing, malformed, not square, or lists an entry outside its declared size.
SparseMatrix read_matrix(const std::string& path);

/// `.mtx`: Matrix Market array with one column, else GetDP's Matlab text (file_vec_*.m).
Vec read_vector(const std::string& path);

/// The node and field component of one matrix row.
struct DofLocation {
  NodeTag node;
  int component;
};

/// Rows of system `system` (its $DofData block, counted from 0 in file order) of GetDP's
/// .pre file. Each distinct basis function is a component, in increasing basis function
/// number (declare the x space before the y space); their count must be `components`.
/// InputError for a missing block, fixed or linked dofs (GetDP Constraints: assemble
/// without them and name the groups in "dirichlet"), or a row numbered twice or never.
std::vector<DofLocation> read_getdp_dof_map(const std::string& path, int system, int components);

/// One "node_tag component" line per row ('#' starts a comment).
std::vector<DofLocation> read_explicit_dof_map(const std::string& path, int components);

}  // namespace ffeti::native
