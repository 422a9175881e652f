#include "parallel/ownership.h"

#include "base/errors.h"

#include <string>

namespace ffeti {

std::vector<int> subdomain_owners(const std::vector<long long>& assembled_here, const Communicator& comm,
                                  const std::string& provider) {
  std::vector<int> counts;
  const std::vector<long long> all = comm.allgather(assembled_here, &counts);
  const size_t S = assembled_here.size();
  for (int r = 0; r < comm.size(); ++r)
    if (static_cast<size_t>(counts[static_cast<size_t>(r)]) != S)
      throw InputError(provider + ": rank " + std::to_string(r) + " has " + std::to_string(counts[static_cast<size_t>(r)]) +
                       " subdomains, rank " + std::to_string(comm.rank()) + " has " + std::to_string(S));
  std::vector<int> owner(S, -1);
  for (size_t s = 0; s < S; ++s) {
    std::vector<int> providers;
    for (int r = 0; r < comm.size(); ++r)
      if (all[static_cast<size_t>(r) * S + s]) providers.push_back(r);
    if (providers.empty())
      throw InputError(provider + "[" + std::to_string(s) + "]: empty on every rank (no rank assembled subdomain " +
                       std::to_string(s) + ")");
    owner[s] = providers[s % providers.size()];
  }
  return owner;
}

}  // namespace ffeti
