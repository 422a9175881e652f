#include "service/contact_transfer.h"

#include "base/errors.h"

#include <algorithm>
#include <limits>

namespace ffeti {
namespace {

/// A row of the source problem in coordinates (u, v, w), u along the axis over which the
/// rows spread the most: a contact line along y has a single x, a contact plane z = c a
/// single z, and a scan sorted by that coordinate would visit every row for every query.
struct Source {
  double u, v, w, force;
};

/// The axis (0 x, 1 y, 2 z) over which the rows of `from` spread the most.
int widest_axis(const std::vector<ContactMultiplier>& from) {
  Point3 low, high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  for (const ContactMultiplier& row : from) {
    const Point3 p{row.x, row.y, row.z};
    for (int d = 0; d < 3; ++d) low[d] = std::min(low[d], p[d]), high[d] = std::max(high[d], p[d]);
  }
  int widest = 0;
  for (int d = 1; d < 3; ++d)
    if (high[d] - low[d] > high[widest] - low[widest]) widest = d;
  return widest;
}

/// `p` with the coordinate along `axis` first (the others in cyclic order).
Point3 along(const Point3& p, int axis) { return {p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3]}; }

/// Index of the source (sorted by u) nearest to q = (u, v, w): a scan outwards from u that
/// stops once the u distance alone exceeds the best distance found.
size_t nearest(const std::vector<Source>& sources, const Point3& q) {
  const auto by_u = [](const Source& s, double value) { return s.u < value; };
  const auto middle = static_cast<size_t>(std::lower_bound(sources.begin(), sources.end(), q[0], by_u) - sources.begin());
  size_t best = 0;
  double best_sq = std::numeric_limits<double>::infinity();
  const auto consider = [&](size_t i) {
    const double du = sources[i].u - q[0], dv = sources[i].v - q[1], dw = sources[i].w - q[2];
    if (du * du >= best_sq) return false;  // every source further out in this direction is too
    if (du * du + dv * dv + dw * dw < best_sq) best_sq = du * du + dv * dv + dw * dw, best = i;
    return true;
  };
  for (size_t i = middle; i < sources.size() && consider(i); ++i) {}
  for (size_t i = middle; i-- > 0 && consider(i);) {}
  return best;
}

}  // namespace

std::vector<double> transfer_contact_forces(const std::vector<ContactMultiplier>& from, const std::vector<Point3>& to) {
  std::vector<double> forces(to.size(), 0.0);
  if (from.empty()) return forces;
  const int axis = widest_axis(from);
  std::vector<Source> sources;
  for (const ContactMultiplier& row : from) {
    const Point3 p = along({row.x, row.y, row.z}, axis);
    sources.push_back({p[0], p[1], p[2], row.lambda});
  }
  std::sort(sources.begin(), sources.end(), [](const Source& a, const Source& b) { return a.u < b.u; });
  std::vector<size_t> source(to.size());
  std::vector<int> sharing(sources.size(), 0);
  for (size_t k = 0; k < to.size(); ++k) ++sharing[source[k] = nearest(sources, along(to[k], axis))];
  for (size_t k = 0; k < to.size(); ++k) forces[k] = sources[source[k]].force / sharing[source[k]];
  return forces;
}

Vec start_from_contact_forces(const FetiProblem& problem, const std::vector<ContactMultiplier>& from) {
  const Constraints& c = problem.constraints();
  for (ContactKind kind : c.contact_kinds) require(kind, Feature::contact_start, problem.space_dimension(), "P");
  std::vector<Point3> positions;
  for (size_t k = 0; k < problem.contact_positions().size(); ++k) {
    const auto& [x, y] = problem.contact_positions()[k];
    positions.push_back({x, y, problem.contact_heights()[k]});
  }
  Vec start = Vec::Zero(c.rows());
  const std::vector<double> forces = transfer_contact_forces(from, positions);
  for (size_t k = 0; k < forces.size(); ++k) start[c.equality_rows + static_cast<Eigen::Index>(k)] = forces[k];
  return start;
}

}  // namespace ffeti
