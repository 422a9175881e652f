// The core's ContactInput from a problem file's "contact" entries, for this rank's subdomains.
#pragma once

#include "native/native_problem.h"

#include <vector>

namespace ffeti::native {

/// The contact of the subdomains of `layouts`: slave dofs, master segments (triangles in a
/// solid) oriented with their body on the core's side, a rigid obstacle, friction.
/// `segments_here` and `segments_total` add the master segments (faces) found on these
/// subdomains and on the master groups in all (the caller checks them over the ranks).
ContactInput build_contact(const ProblemFile& problem, const GmshMesh& mesh, const std::vector<SubdomainLayout>& layouts,
                           long& segments_here, long& segments_total);

}  // namespace ffeti::native
