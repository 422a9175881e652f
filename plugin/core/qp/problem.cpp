#include "qp/problem.h"

#include <stdexcept>

namespace ffeti::qp {

void ConstraintSet::append(BlockKind kind, const Vec& lower_part, const Vec& upper_part) {
  const Eigen::Index first = size(), n = lower_part.size();
  if (n == 0) return;
  blocks_.push_back({first, n, kind});
  if (has_discs() && kind != BlockKind::disc)  // no disc here: centre 0, radius +infinity
    append_disc_data(first, Vec::Zero(n), Vec::Constant(n, std::numeric_limits<double>::infinity()));
  lower.conservativeResize(first + n);
  lower.tail(n) = lower_part;
  if (kind == BlockKind::box && upper.size() == 0 && first > 0)
    upper = Vec::Constant(first, std::numeric_limits<double>::infinity());  // the blocks before have none
  if (upper.size() == 0 && kind != BlockKind::box) return;
  upper.conservativeResize(first + n);
  upper.tail(n) = upper_part;
}

void ConstraintSet::add_free(Eigen::Index size) {
  append(BlockKind::free, Vec::Constant(size, kUnbounded), Vec::Constant(size, std::numeric_limits<double>::infinity()));
}

void ConstraintSet::add_half_line(const Vec& lower_part) {
  append(BlockKind::half_line, lower_part, Vec::Constant(lower_part.size(), std::numeric_limits<double>::infinity()));
}

void ConstraintSet::add_box(const Vec& lower_part, const Vec& upper_part) {
  if (upper_part.size() != lower_part.size()) throw std::invalid_argument("box block: lower and upper differ in size");
  append(BlockKind::box, lower_part, upper_part);
}

void ConstraintSet::add_disc(const Vec& centre, const Vec& radius) {
  if (centre.size() != 2 * radius.size()) throw std::invalid_argument("disc block: centre needs two entries per radius");
  if (!((radius.array() >= 0).all() && radius.allFinite() && centre.allFinite()))
    throw std::invalid_argument("disc block: radii must be finite and >= 0, centres finite");
  const Eigen::Index first = size(), n = centre.size();
  if (n == 0) return;
  if (!has_discs())  // the blocks before have none
    append_disc_data(0, Vec::Zero(first), Vec::Constant(first, std::numeric_limits<double>::infinity()));
  Vec pair_radius(n);  // (g_0, g_0, g_1, g_1, ...)
  for (Eigen::Index j = 0; j < radius.size(); ++j) pair_radius[2 * j] = pair_radius[2 * j + 1] = radius[j];
  append_disc_data(first, centre, pair_radius);
  append(BlockKind::disc, Vec::Constant(n, kUnbounded), Vec::Constant(n, std::numeric_limits<double>::infinity()));
}

void ConstraintSet::append_disc_data(Eigen::Index first, const Vec& centre_part, const Vec& radius_part) {
  disc_centre.conservativeResize(first + centre_part.size());
  disc_centre.tail(centre_part.size()) = centre_part;
  disc_radius.conservativeResize(first + radius_part.size());
  disc_radius.tail(radius_part.size()) = radius_part;
}

ConstraintSet ConstraintSet::from_bounds(const Vec& lower, const Vec& upper) {
  if (upper.size() && upper.size() != lower.size()) throw std::invalid_argument("bounds: lower and upper differ in size");
  const auto kind_of = [&](Eigen::Index i) {
    if (upper.size() && upper[i] < std::numeric_limits<double>::infinity()) return BlockKind::box;
    return lower[i] == kUnbounded ? BlockKind::free : BlockKind::half_line;
  };
  ConstraintSet set;
  for (Eigen::Index first = 0, end = 0; first < lower.size(); first = end) {
    const BlockKind kind = kind_of(first);
    for (end = first + 1; end < lower.size() && kind_of(end) == kind;) ++end;
    const Vec l = lower.segment(first, end - first);
    if (kind == BlockKind::box) set.add_box(l, upper.segment(first, end - first));
    else if (kind == BlockKind::half_line) set.add_half_line(l);
    else set.add_free(end - first);
  }
  if (upper.size() && set.upper.size() == 0) set.upper = upper;  // kept as given: +infinity everywhere
  return set;
}

ConstraintSet ConstraintSet::shifted(const Vec& offset) const {
  ConstraintSet set = *this;
  set.lower = lower - offset;  // kUnbounded stays
  if (upper.size()) set.upper = upper - offset;
  for (const Block& block : blocks_)
    if (block.kind == BlockKind::disc)
      set.disc_centre.segment(block.first, block.size) -= offset.segment(block.first, block.size);
  return set;
}

bool ConstraintSet::bounded() const {
  for (const Block& block : blocks_)
    if (block.kind != BlockKind::free) return true;
  return false;
}

Budget::Budget(int max_hessian) : max_hessian_(max_hessian) {
  if (max_hessian < 1) throw std::invalid_argument("maxit: must be >= 1");
}

}  // namespace ffeti::qp
