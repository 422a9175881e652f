// Initial multipliers from the contact forces of a similar problem (the same scene on a
// coarser mesh, another split, the previous design): nested iteration for any scene,
// without its meshes.
#pragma once

#include "constraints/contact/point3.h"
#include "feti/feti_problem.h"
#include "service/statistics.h"

#include <vector>

namespace ffeti {

/// The forces of `from` carried to the contact rows at the positions `to` (z = 0 in a plane
/// problem): each takes the force of the row of `from` nearest to it, shared equally among
/// all that have that row as their nearest. The total force, and where it acts at the spacing of `from`, are kept (a
/// row of `from` nearest to none of `to` is dropped); any spacing, units, matching or not.
std::vector<double> transfer_contact_forces(const std::vector<ContactMultiplier>& from, const std::vector<Point3>& to);

/// Multipliers for `problem` to start a solve from (fetiSolve's start): the contact rows get
/// the forces `from` transferred to them, the equality rows 0.
Vec start_from_contact_forces(const FetiProblem& problem, const std::vector<ContactMultiplier>& from);

}  // namespace ffeti
