// The problem file of ffeti-solve (JSON, read with nlohmann/json): which mesh, which
// subdomain systems, which physical groups carry the conditions, and the solver options.
// The format is documented in docs/reference.md ("ffeti-solve").
#pragma once

#include "constraints/capabilities.h"
#include "service/options.h"

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ffeti::native {

/// How the rows of a subdomain matrix map to mesh nodes and field components.
struct DofMapSpec {
  std::string getdp_pre;  ///< GetDP's .pre file (with `system`), or
  int system = 0;         ///< its $DofData block: the system's position in the resolution
  std::string explicit_file;  ///< a text file, one "node_tag component" line per row
};

struct SubdomainSpec {
  /// The physical groups whose cells form the subdomain: surfaces (key "surfaces", plane
  /// problems: triangles) or volumes (key "volumes", "components": 3: tetrahedra).
  std::vector<int> regions;
  int partition = 0;          ///< > 0: only the elements of this mesh partition
  int body = 0;
  std::string matrix, rhs;    ///< GetDP's Print[] output (.m) or Matrix Market (.mtx)
  DofMapSpec dofs;
};

/// Linear elastic material of a body (plane strain or plane stress in 2D; a solid in 3D):
/// von Mises views.
struct MaterialSpec {
  double young = 0, poisson = 0;
  bool plane_stress = false;
};

struct BodySpec {
  std::string name;
  std::optional<MaterialSpec> material;
};

struct DirichletSpec {
  int group = 0;                ///< physical group tag
  int dim = 1;                  ///< its dimension: 0 point, 1 curve, 2 surface (3D); default the boundary's
  std::vector<int> components;  ///< fixed components (vector fields); empty: all
  double value = 0;
};

struct ContactSpec {
  int slave = 0;      ///< physical curve (surface in 3D) of the slave nodes
  /// The physical group of the list kind's key (ListInput::file_key, "master": a curve of
  /// master segments, a surface of master triangles in 3D, the master nodes' curve of a
  /// scalar field); 0 with an obstacle.
  int master = 0;
  ContactKind kind = ContactKind::node_to_segment;  ///< the kind the entry makes
  std::optional<double> search_distance;  ///< node to segment or face only (default: no limit)
  /// The given scalar keys of the entry's list kind (ListInput::options: node to node's "gap",
  /// node to face's "contact_normal"), by their position among its options; a word as its
  /// position among the option's words. One value per problem.
  std::map<size_t, double> options;
  /// A kind that owns its input, given by its key (KindInput::file_key, read through
  /// the registry: constraints/contact/contact_discretization.h): its entries, as its fetiSetup
  /// argument takes them (none where line_curve gives them). At most one per entry.
  std::map<ContactKind, std::vector<double>> kind_parameters;
  /// > 0: the kind's line key (KindInput::line_key, the plane obstacle's "curve"): a straight
  /// physical curve, the line's point and normal (towards the slave) read from the mesh.
  int line_curve = 0;
  /// A rigid obstacle (a kind's own key: "obstacle", "cylinder"): no master group.
  bool rigid() const { return !kind_parameters.empty(); }
  std::optional<double> friction;    ///< Coulomb coefficient of this entry's rows (capability table: where)
  std::optional<double> slip_bound;  ///< Tresca bound of each of this entry's rows, a force
};


struct OutputSpec {  ///< files to write; empty: not written
  std::string views;           ///< gmsh views (.msh or .pos)
  std::string table;           ///< nodal results, CSV
  std::string stress_table;    ///< von Mises per element, CSV
  std::string getdp_solution;  ///< GetDP's .res, one $Solution per subdomain system
  std::string history;         ///< convergence history, CSV
};

struct ProblemFile {
  std::string path;       ///< of the problem file, for error messages
  std::string directory;  ///< relative paths inside are relative to it
  std::string mesh;
  int components = 2;     ///< field components per node: 1 (membranes), 2 (plane elasticity) or 3 (solids)
  std::vector<BodySpec> bodies;
  std::vector<SubdomainSpec> subdomains;
  std::vector<DirichletSpec> dirichlet;
  std::vector<ContactSpec> contact;
  GivenOptions solver;  ///< the "solver" object: the options of fetiSetup and fetiSolve
  OutputSpec output;
  /// Of the subdomains' cells: 3 (tetrahedra) with 3 components, else 2 (triangles). The
  /// conditions sit on groups of one dimension less: curves in 2D, surfaces in 3D.
  int dimension() const { return components == 3 ? 3 : 2; }
};

/// Reads and checks the problem file. InputError naming the file and the key for a missing
/// file, malformed JSON, a missing or mistyped entry, an unknown key or a bad value.
ProblemFile read_problem_file(const std::string& path);

/// A path of the problem file resolved against its directory.
std::string resolve(const ProblemFile& problem, const std::string& path);

}  // namespace ffeti::native
