#include "feti/contact_transfer.h"

#include <algorithm>
#include <limits>

namespace ffeti {
namespace {

/// Index of the point of `points` (sorted by x) nearest to (x, y): a scan outwards from x
/// that stops once the x distance alone exceeds the best distance found.
size_t nearest(const std::vector<ContactMultiplier>& points, double x, double y) {
  const auto by_x = [](const ContactMultiplier& p, double value) { return p.x < value; };
  const auto middle = static_cast<size_t>(std::lower_bound(points.begin(), points.end(), x, by_x) - points.begin());
  size_t best = 0;
  double best_sq = std::numeric_limits<double>::infinity();
  const auto consider = [&](size_t i) {
    const double dx = points[i].x - x, dy = points[i].y - y;
    if (dx * dx >= best_sq) return false;  // every point further out in this direction is too
    if (dx * dx + dy * dy < best_sq) best_sq = dx * dx + dy * dy, best = i;
    return true;
  };
  for (size_t i = middle; i < points.size() && consider(i); ++i) {}
  for (size_t i = middle; i-- > 0 && consider(i);) {}
  return best;
}

}  // namespace

std::vector<double> transfer_contact_forces(const std::vector<ContactMultiplier>& from,
                                            const std::vector<std::array<double, 2>>& to) {
  std::vector<double> forces(to.size(), 0.0);
  if (from.empty()) return forces;
  std::vector<ContactMultiplier> sorted = from;
  std::sort(sorted.begin(), sorted.end(), [](const ContactMultiplier& a, const ContactMultiplier& b) { return a.x < b.x; });
  std::vector<size_t> source(to.size());
  std::vector<int> sharing(sorted.size(), 0);
  for (size_t k = 0; k < to.size(); ++k) ++sharing[source[k] = nearest(sorted, to[k][0], to[k][1])];
  for (size_t k = 0; k < to.size(); ++k) forces[k] = sorted[source[k]].lambda / sharing[source[k]];
  return forces;
}

Vec start_from_contact_forces(const FetiProblem& problem, const std::vector<ContactMultiplier>& from) {
  const Constraints& c = problem.constraints();
  Vec start = Vec::Zero(c.rows());
  const std::vector<double> forces = transfer_contact_forces(from, problem.contact_positions());
  for (size_t k = 0; k < forces.size(); ++k) start[c.equality_rows + static_cast<Eigen::Index>(k)] = forces[k];
  return start;
}

}  // namespace ffeti
