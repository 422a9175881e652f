// Which rank holds which subdomain when a script decides where subdomains are assembled.
#pragma once

#include "parallel/communicator.h"

#include <string>
#include <vector>

namespace ffeti {

/// Owner of each subdomain from `assembled_here[s]` (non-zero: this rank assembled subdomain
/// s): among the ranks that assembled it, the (s mod count)-th, so that a script assembling
/// everything on every rank is spread round-robin and a script assembling each subdomain
/// once keeps its own split. InputError when the ranks disagree on the number of
/// subdomains or no rank assembled one (`provider` names what shows a subdomain assembled,
/// for that error: "K", or "F" where subdomains share matrices). Collective.
std::vector<int> subdomain_owners(const std::vector<long long>& assembled_here, const Communicator& comm,
                                  const std::string& provider = "K");

}  // namespace ffeti
