#include "qp/constraint_set.h"

#include "qp/bound_sets.h"
#include "qp/disc_set.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace ffeti::qp {

void ConstraintSet::append(std::shared_ptr<const SetKind> kind) {
  if (kind->block().size == 0) return;
  blocks_.push_back(kind->block());
  size_ += kind->block().size;
  kinds_.push_back(std::move(kind));
}

void ConstraintSet::add_free(Eigen::Index size) { append(std::make_shared<FreeSet>(size_, size)); }

void ConstraintSet::add_half_line(const Vec& lower) { append(std::make_shared<HalfLineSet>(size_, lower, Vec())); }

void ConstraintSet::add_box(const Vec& lower, const Vec& upper) { append(std::make_shared<BoxSet>(size_, lower, upper)); }

void ConstraintSet::add_disc(const Vec& centre, const Vec& radius) {
  append(std::make_shared<DiscSet>(size_, centre, radius));
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
  return set;
}

ConstraintSet ConstraintSet::shifted(const Vec& offset) const {
  ConstraintSet set;
  for (const auto& kind : kinds_) set.append(kind->shifted(offset));
  return set;
}

bool ConstraintSet::bounded() const {
  return std::any_of(blocks_.begin(), blocks_.end(), [](const Block& block) { return block.kind != BlockKind::free; });
}

void ConstraintSet::componentwise_bounds(Vec& lower, Vec& upper) const {
  lower = Vec::Constant(size_, kUnbounded);
  upper = Vec::Constant(size_, std::numeric_limits<double>::infinity());
  for (const auto& kind : kinds_) kind->write_bounds(lower, upper);
}

Vec ConstraintSet::lower() const {
  Vec lower, upper;
  componentwise_bounds(lower, upper);
  return lower;
}

Vec ConstraintSet::upper() const {
  Vec lower, upper;
  componentwise_bounds(lower, upper);
  return upper;
}

int ConstraintSet::project(Vec& x) const {
  int moved = 0;
  for (const auto& kind : kinds_) moved += kind->project(x);
  return moved;
}

int ConstraintSet::project_curved(Vec& x) const {
  int moved = 0;
  for (const auto& kind : kinds_) moved += kind->project_curved(x);
  return moved;
}

bool ConstraintSet::contains(const Vec& x) const {
  return std::all_of(kinds_.begin(), kinds_.end(), [&](const auto& kind) { return kind->contains(x); });
}

void ConstraintSet::free_gradient(const Vec& x, const Vec& g, double a_norm, Vec& phi) const {
  phi = g;
  restrict_to_face(x, g, a_norm, phi);
}

void ConstraintSet::restrict_to_face(const Vec& x, const Vec& g, double a_norm, Vec& v) const {
  for (const auto& kind : kinds_) kind->restrict_to_face(x, g, a_norm, v);
}

std::vector<char> ConstraintSet::free_components(const Vec& x) const {
  std::vector<char> face(static_cast<size_t>(size_), 1);
  for (const auto& kind : kinds_) kind->mark_free(x, face);
  return face;
}

Vec ConstraintSet::projected_gradient(const Vec& x, const Vec& g) const {
  Vec gp(x.size());
  projected_gradient(x, g, gp);
  return gp;
}

void ConstraintSet::projected_gradient(const Vec& x, const Vec& g, Vec& gp) const {
  gp.resize(x.size());
  for (const auto& kind : kinds_) kind->projected_gradient(x, g, gp);
}

double ConstraintSet::projected_gradient_max(const Vec& x, const Vec& g) const {
  return projected_gradient(x, g).lpNorm<Eigen::Infinity>();
}

bool ConstraintSet::curved() const {
  return std::any_of(kinds_.begin(), kinds_.end(), [](const auto& kind) { return kind->curved(); });
}

ReducedFreeGradient ConstraintSet::reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const {
  phit.resize(x.size());
  for (const auto& kind : kinds_) kind->reduced_free_gradient(x, phi, abar, phit);
  ReducedFreeGradient r;
  for (Eigen::Index i = 0; i < x.size(); ++i) {  // in order: the same sums whatever the blocks
    r.dot_phi += phit[i] * phi[i];
    r.squared_norm += phit[i] * phit[i];
  }
  return r;
}

double ConstraintSet::feasible_step(const Vec& x, const Vec& p, bool slide_on_circles) const {
  double step = std::numeric_limits<double>::infinity();
  for (const auto& kind : kinds_) step = std::min(step, kind->feasible_step(x, p, slide_on_circles));
  return step;
}

void ConstraintSet::add_curvature(const Vec& x, const Vec& g, const Vec& p, Vec& Ap) const {
  for (const auto& kind : kinds_) kind->add_curvature(x, g, p, Ap);
}

void ConstraintSet::precondition_curvature(const Vec& x, const Vec& g, double a_norm, Vec& v) const {
  for (const auto& kind : kinds_) kind->precondition_curvature(x, g, a_norm, v);
}

bool ConstraintSet::holds_tangents(const Vec& x, const Vec& g, double a_norm) const {
  return std::any_of(kinds_.begin(), kinds_.end(), [&](const auto& kind) { return kind->holds_tangents(x, g, a_norm); });
}

double ConstraintSet::linear_minimum(const Vec& y, Vec& x) const {
  double value = 0;
  for (const auto& kind : kinds_)
    if (kind->block().compact()) value += kind->linear_minimum(y, x);
  return value;
}

void ConstraintSet::add_linear_minimizer_change(const Vec& y, const Vec& dy, Vec& dx) const {
  for (const auto& kind : kinds_)
    if (kind->block().compact()) kind->add_linear_minimizer_change(y, dy, dx);
}

int ConstraintSet::off_bound_count(const Vec& x) const {
  int count = 0;
  for (const auto& kind : kinds_) count += kind->off_bound_count(x);
  return count;
}

}  // namespace ffeti::qp
