// Validation of a problem's input before any numerics: sizes, finiteness, symmetry, dof
// ranges. Each failure is an InputError naming the argument as the FreeFEM functions do.
#pragma once

#include "constraints/problem_input.h"

#include <vector>

namespace ffeti {

/// `global_ids[k]` names local subdomain k in messages (empty: k itself).
void validate_input(const std::vector<SubdomainInput>& subdomains, const ContactInput& contact,
                    const std::vector<int>& global_ids = {});

/// contactGap's layout (ContactInput::gap_field): none, or one entry per subdomain, each
/// empty or one finite value per dof.
void validate_contact_gaps(const std::vector<std::vector<double>>& gaps, const std::vector<SubdomainInput>& subdomains,
                           const std::vector<int>& global_ids = {});

}  // namespace ffeti
