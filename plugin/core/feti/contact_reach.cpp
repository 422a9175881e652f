#include "feti/contact_reach.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ffeti {

std::string ReachCheck::warning() const {
  if (penetrating == 0) return "";
  char text[400];
  std::snprintf(text, sizeof text,
                "%d of the %d slave nodes that contactRadius left without a contact row end up behind the master "
                "surface they lie over (the deepest by %.3g): the answer lets them pass through it; give a larger "
                "contactRadius (ffeti-solve: search_distance)",
                penetrating, watched, depth);
  return text;
}

ReachCheck check_beyond_reach(const Constraints::Watched& rows, const std::vector<Vec>& u,
                              const std::vector<int>& global_ids, const Communicator& comm) {
  ReachCheck check;
  check.watched = rows.rows();
  if (check.watched == 0) return check;
  std::vector<int> local_of;  // global subdomain -> local index (-1: another rank's)
  for (size_t k = 0; k < global_ids.size(); ++k) {
    const auto s = static_cast<size_t>(global_ids[k]);
    if (s >= local_of.size()) local_of.resize(s + 1, -1);
    local_of[s] = static_cast<int>(k);
  }
  // Each rank adds the terms of its subdomains; the rows' values are the sums over ranks.
  std::vector<double> mine(static_cast<size_t>(check.watched), 0.0);
  double largest = 0;
  for (const Vec& v : u) largest = std::max(largest, v.size() ? v.cwiseAbs().maxCoeff() : 0.0);
  for (int row = 0; row < check.watched; ++row)
    for (int k = rows.row_start[static_cast<size_t>(row)]; k < rows.row_start[static_cast<size_t>(row) + 1]; ++k) {
      const ConstraintEntry& e = rows.entries[static_cast<size_t>(k)];
      const auto s = static_cast<size_t>(e.subdomain);
      if (s < local_of.size() && local_of[s] >= 0)
        mine[static_cast<size_t>(row)] += e.coefficient * u[static_cast<size_t>(local_of[s])][e.dof];
    }
  const std::vector<double> all = comm.allgather(mine);
  // Round-off of a row that just closes is not a penetration: a millionth of the largest
  // displacement is.
  const double tolerance = 1e-6 * comm.max(largest);
  for (int row = 0; row < check.watched; ++row) {
    double value = 0;
    for (size_t p = static_cast<size_t>(row); p < all.size(); p += static_cast<size_t>(check.watched)) value += all[p];
    const double depth = value - rows.rhs[static_cast<size_t>(row)];
    if (depth > tolerance) ++check.penetrating, check.depth = std::max(check.depth, depth);
  }
  return check;
}

}  // namespace ffeti
