#include "service/contact_transfer.h"

#include "base/errors.h"

#include <algorithm>
#include <limits>

namespace ffeti {
namespace {

/// A row of the source problem in coordinates (u, v), u along the axis over which the rows
/// spread the most: a contact line along y has a single x, and a scan sorted by x would
/// visit every row for every query.
struct Source {
  double u, v, force;
};

/// Index of the source (sorted by u) nearest to (u, v): a scan outwards from u that stops
/// once the u distance alone exceeds the best distance found.
size_t nearest(const std::vector<Source>& sources, double u, double v) {
  const auto by_u = [](const Source& s, double value) { return s.u < value; };
  const auto middle = static_cast<size_t>(std::lower_bound(sources.begin(), sources.end(), u, by_u) - sources.begin());
  size_t best = 0;
  double best_sq = std::numeric_limits<double>::infinity();
  const auto consider = [&](size_t i) {
    const double du = sources[i].u - u, dv = sources[i].v - v;
    if (du * du >= best_sq) return false;  // every source further out in this direction is too
    if (du * du + dv * dv < best_sq) best_sq = du * du + dv * dv, best = i;
    return true;
  };
  for (size_t i = middle; i < sources.size() && consider(i); ++i) {}
  for (size_t i = middle; i-- > 0 && consider(i);) {}
  return best;
}

}  // namespace

std::vector<double> transfer_contact_forces(const std::vector<ContactMultiplier>& from,
                                            const std::vector<std::array<double, 2>>& to) {
  std::vector<double> forces(to.size(), 0.0);
  if (from.empty()) return forces;
  const auto [x_low, x_high] = std::minmax_element(from.begin(), from.end(), [](auto& a, auto& b) { return a.x < b.x; });
  const auto [y_low, y_high] = std::minmax_element(from.begin(), from.end(), [](auto& a, auto& b) { return a.y < b.y; });
  const bool along_y = y_high->y - y_low->y > x_high->x - x_low->x;
  std::vector<Source> sources;
  for (const ContactMultiplier& row : from)
    sources.push_back(along_y ? Source{row.y, row.x, row.lambda} : Source{row.x, row.y, row.lambda});
  std::sort(sources.begin(), sources.end(), [](const Source& a, const Source& b) { return a.u < b.u; });
  std::vector<size_t> source(to.size());
  std::vector<int> sharing(sources.size(), 0);
  for (size_t k = 0; k < to.size(); ++k) {
    const auto& [x, y] = to[k];
    ++sharing[source[k] = along_y ? nearest(sources, y, x) : nearest(sources, x, y)];
  }
  for (size_t k = 0; k < to.size(); ++k) forces[k] = sources[source[k]].force / sharing[source[k]];
  return forces;
}

Vec start_from_contact_forces(const FetiProblem& problem, const std::vector<ContactMultiplier>& from) {
  const Constraints& c = problem.constraints();
  // It pairs rows along a contact curve: plane problems.
  for (ContactKind kind : c.contact_kinds) require(kind, Feature::contact_start, problem.space_dimension(), "P");
  Vec start = Vec::Zero(c.rows());
  const std::vector<double> forces = transfer_contact_forces(from, problem.contact_positions());
  for (size_t k = 0; k < forces.size(); ++k) start[c.equality_rows + static_cast<Eigen::Index>(k)] = forces[k];
  return start;
}

}  // namespace ffeti
