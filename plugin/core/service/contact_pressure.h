// Contact pressure per node from the contact forces (multipliers) of a solution: each
// contact row's force divided by its slave node's share of the contact curve. The shares
// come from the front end (a FreeFEM script integrates its test functions over the contact
// curve; ffeti-solve uses half the adjacent segment lengths), since the core knows nodes,
// not curves.
#pragma once

#include "feti/feti_problem.h"

#include <vector>

namespace ffeti {

struct ContactPressure {
  std::vector<Vec> per_dof;   ///< this rank's subdomains: the pressure at every dof of a slave node, 0 elsewhere
  Vec per_row, share_per_row; ///< every contact row (all ranks alike): pressure and its node's share
};

/// `share[k]` (local subdomain k, one value per dof, empty: none) is each dof's share of
/// the contact curve on that subdomain, e.g. int1d of its test function there. A node's
/// share is the sum over all its copies (every subdomain and rank) of the entries of the
/// dofs of the row's component; the pressure lambda_i / share_i goes to every dof at the
/// node. InputError, naming `Share`, when a row carrying a force has no share. Collective.
ContactPressure contact_pressure(const FetiProblem& problem, const Vec& lambda, const std::vector<Vec>& share);

}  // namespace ffeti
