// After a solve: the slave nodes contactRadius left without a row, checked against the
// master they lie over (Constraints::beyond_reach). A radius too small otherwise converges
// to an answer whose slaves pass through the master surface without a word (issue 37).
#pragma once

#include "constraints/constraints.h"
#include "parallel/communicator.h"

#include <string>
#include <vector>

namespace ffeti {

struct ReachCheck {
  int watched = 0;      ///< slaves without a row, over a master in front of it
  int penetrating = 0;  ///< of these, how many ended up behind it
  double depth = 0;     ///< the deepest one's distance behind it (a length)
  /// The warning both front ends print ("" when none penetrates).
  std::string warning() const;
};

/// `u` per local subdomain, `global_ids` their global indices. Collective.
ReachCheck check_beyond_reach(const Constraints::Watched& rows, const std::vector<Vec>& u,
                              const std::vector<int>& global_ids, const Communicator& comm);

}  // namespace ffeti
