// Validation of a problem's input before any numerics: sizes, finiteness, symmetry, dof
// ranges. Each failure is an InputError naming the argument as the FreeFEM functions do.
#pragma once

#include "constraints/problem_input.h"

#include <array>
#include <vector>

namespace ffeti {

/// `global_ids[k]` names local subdomain k in messages (empty: k itself).
void validate_input(const std::vector<SubdomainInput>& subdomains, const ContactInput& contact,
                    const std::vector<int>& global_ids = {});

/// A per-subdomain dof list (none, or one list per subdomain): InputError "<name>: has N
/// entries for S subdomains", "<name>[<id>]: dof d is outside 0..n-1".
void check_list_dofs(const std::vector<std::vector<int>>& lists, const std::vector<size_t>& ids,
                     const std::vector<SubdomainInput>& subdomains, const char* name);

/// A per-subdomain list of entries of N dofs (segments, faces) as check_list_dofs checks it.
template <size_t N>
void check_entry_dofs(const std::vector<std::vector<std::array<int, N>>>& entries, const std::vector<size_t>& ids,
                      const std::vector<SubdomainInput>& subdomains, const char* name) {
  std::vector<std::vector<int>> dofs;
  for (const auto& list : entries) {
    dofs.emplace_back();
    for (const auto& entry : list) dofs.back().insert(dofs.back().end(), entry.begin(), entry.end());
  }
  check_list_dofs(dofs, ids, subdomains, name);
}

/// Contact triangles (contactFaces, contactSlaveFaces): their dofs, each corner's x, y and z
/// at one node, distinct corners with an area, the normal out of the body (surface_checks.h).
void check_face_list(const std::vector<std::vector<std::array<int, 9>>>& faces, const std::vector<size_t>& ids,
                     const std::vector<SubdomainInput>& subdomains, const char* name);

/// contactGap's layout (ContactInput::gap_field): none, or one entry per subdomain, each
/// empty or one finite value per dof.
void validate_contact_gaps(const std::vector<std::vector<double>>& gaps, const std::vector<SubdomainInput>& subdomains,
                           const std::vector<int>& global_ids = {});

}  // namespace ffeti
