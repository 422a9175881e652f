// The seed's two-membrane model problem assembled in C++ (P1 on structured triangles),
// split into N x N subdomains per body, plus a monolithic reference solver (primal-dual
// active set with a sparse direct solver) that shares no code with the FETI path.
#pragma once

#include "feti/dual_system.h"
#include "feti/feti_problem.h"
#include "constraints/problem_input.h"

#include <functional>
#include <vector>

namespace ffeti::test {

/// Solve settings for comparisons with finite differences: tol 1e-12, room to converge.
DualSolveSettings tight();

/// P1 stiffness `factor` * int grad u . grad v and load int f v on [x0,x0+w] x [y0,y0+h]
/// with nx x ny cells, each cut along the same diagonal as FreeFEM's square(); with
/// `x_map`, each node's x is moved to x_map(x) (a graded mesh: the same map on every
/// subdomain of a body keeps their shared nodes shared).
SubdomainInput p1_rectangle(double x0, double y0, double w, double h, int nx, int ny,
                            double factor, const std::function<double(double, double)>& f,
                            int body, const std::function<double(double)>& x_map = {});

/// Two decoupled copies of a scalar problem as a 2-component field (dofs 2k, 2k+1, the same
/// node): a vector problem whose kernel is the two translations, not the rotation the
/// candidate rigid modes also contain, and whose stiffness does not depend on the
/// coordinates. The load is zero.
SubdomainInput two_components(const SubdomainInput& scalar);

struct MembraneOptions {
  int n = 16;              ///< cells per unit length (h = 1/n)
  int N = 2;               ///< subdomains per direction and body
  bool fix_right_body = false;  ///< Dirichlet at x = 2 too: a coercive contact scene
  bool with_contact = true;
  bool body2 = true;
  std::function<double(double)> x_map;  ///< grades body 0 in x (an increasing map of [0, 1] onto itself)
};

/// Options with n cells per unit length and N x N subdomains per body, the rest default.
MembraneOptions membrane_options(int n, int N);

/// An x_map for n cells that grades body 0 towards the contact line, its cells `ratio` times
/// narrower there than at x = 0: x -> 1 - (e^{a(1-x)} - 1) / (e^a - 1).
std::function<double(double)> graded_towards_contact(int n, double ratio);

/// Body 0 = (0,1)^2 with u = 0 at x = 0, body 1 = (1,2)x(0,1); energy as the seed prints it
/// (int |grad u|^2 - int f u, so K = 2 x Laplacian), f = -3 on y > 0.75 in body 0 and
/// f = -1 on y < 0.25 in body 1.
std::vector<SubdomainInput> membrane_subdomains(const MembraneOptions& options);
ContactInput membrane_contact(const std::vector<SubdomainInput>& subdomains);

/// Monolithic reference: the same discrete problem on the unsplit bodies, solved by a
/// primal-dual active set method with Eigen's SparseLU.
struct ReferenceSolution {
  double energy;
  std::vector<double> active_y;  ///< y of the contact nodes with a positive multiplier
  int iterations;
};
ReferenceSolution membrane_reference(int n);

/// The membranes of `o` (with their contact when o.with_contact) as one FetiProblem.
FetiProblem membrane_problem(const MembraneOptions& o, FetiVariant variant, int threads = 0,
                             DualPreconditioner preconditioner = DualPreconditioner::none,
                             InterfaceScaling scaling = InterfaceScaling::multiplicity);

}  // namespace ffeti::test
