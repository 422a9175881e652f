// A P1 plane-strain elastic block for the 2D friction tests: the element stiffness written
// out independently of the plugin (which takes K as given).
#pragma once

#include "constraints/problem_input.h"

namespace ffeti {

/// P1 plane-strain elasticity (E = 1000, nu = 0.3) on [x0, x0+w] x [0, h], nx x ny cells; dofs 2k (x), 2k+1 (y)
/// of node k; the top edge fixed at (drag, push).
SubdomainInput elastic_block(double x0, double w, double h, int nx, int ny, double drag, double push);

}  // namespace ffeti
