// What ffeti-solve writes after a solve: gmsh views (displacement, contact pressure, active
// set, von Mises), a CSV table of nodal results and GetDP's .res solution file.
#pragma once

#include "feti/feti_problem.h"
#include "service/statistics.h"
#include "native/gmsh_mesh.h"
#include "native/native_problem.h"
#include "native/problem_file.h"
#include "parallel/communicator.h"

#include <map>
#include <vector>

namespace ffeti::native {

/// The solution of every subdomain, gathered on every rank, in problem-file order.
struct GatheredSolution {
  std::vector<std::vector<DofLocation>> dofs;  ///< per subdomain
  std::vector<Vec> u;                          ///< per subdomain, row order
};

/// Collective.
GatheredSolution gather_solution(const FetiResult& result, const std::vector<SubdomainLayout>& layouts,
                                 int subdomain_count, const Communicator& comm);

/// Von Mises stress of one cell (triangle, or tetrahedron in 3D) of a body with a material,
/// at its centroid (z = 0 in a plane problem).
struct ElementStress {
  std::size_t tag;
  int body;
  double x, y, z;
  double von_mises;
};

/// Nodal values: displacement (averaged over the subdomain copies of a node, which agree
/// to the solver's tolerance) and, at the slave nodes, the contact force (the multiplier),
/// the pressure (force over the node's share of the slave curve, or surface in 3D) and the
/// active flag; per cell of a body with a material, the von Mises stress.
struct NodalResults {
  std::map<NodeTag, std::array<double, 3>> displacement;  ///< the problem's components, the others 0
  std::map<NodeTag, int> body;
  std::map<NodeTag, double> contact_force, contact_pressure;
  std::map<NodeTag, double> friction_force;  ///< the friction row's multiplier (0 without friction); 3D: along t1
  std::map<NodeTag, double> friction_force_2;  ///< 3D: along t2 (0 in the plane)
  std::map<NodeTag, double> slip, slip_2;    ///< the step's slip along t1 and t2 (fetiContact's slip=, slip2=)
  std::map<NodeTag, Point3> normal, tangent_1, tangent_2;  ///< the row's n, t1, t2 (t2 = 0 in the plane)
  std::map<NodeTag, int> contact_state;      ///< 0 open, 1 stick, 2 slip (friction.h)
  std::vector<ElementStress> stresses;  ///< displacements (2 or 3 components), bodies with a material
};

NodalResults nodal_results(const ProblemFile& problem, const GmshMesh& mesh, const GatheredSolution& solution,
                           const std::vector<ContactMultiplier>& contact);

/// Views in one file that gmsh opens (format from the extension: .msh or .pos).
void write_views(const std::string& path, const ProblemFile& problem, const GmshMesh& mesh,
                 const NodalResults& results);

/// node,body,x,y,u_x,u_y,contact_row,contact_force,contact_pressure,active,friction_force,state,
/// slip,n_x,n_y,t1_x,t1_y (contact_row: 1 at the slave nodes that have a contact row;
/// friction_force, state (0 open, 1 stick, 2 slip), slip, n and t1 as fetiContact's
/// tangential=, state=, slip=, normal=, tangent1=; 0 elsewhere); a solid (3 components) adds
/// z after y, u_z after u_y, friction_force_2 after state, slip_2 after slip, the z
/// components of n and t1 and t2_x,t2_y,t2_z (tangential2=, slip2=, tangent2=).
void write_table(const std::string& path, const ProblemFile& problem, const GmshMesh& mesh, const NodalResults& results);

/// element,body,x,y,von_mises (centroids; a solid adds z after y), for the bodies with a material.
void write_stress_table(const std::string& path, const ProblemFile& problem, const NodalResults& results);

/// GetDP's .res: one $Solution per subdomain system, numbered by its $DofData block, so that
/// `getdp ... -pre <resolution> -res <file> -pos <post-operation>` post-processes it.
/// Every subdomain's dofs come from one .pre file, each system once (read_problem_file checks).
void write_getdp_solution(const std::string& path, const ProblemFile& problem, const GatheredSolution& solution);

}  // namespace ffeti::native
