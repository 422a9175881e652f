#include "qp/bound_sets.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace ffeti::qp {
namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
}  // namespace

std::shared_ptr<const SetKind> FreeSet::shifted(const Vec&) const {
  return std::make_shared<FreeSet>(block().first, block().size);
}

void FreeSet::projected_gradient(const Vec&, const Vec& g, Vec& gp) const {
  gp.segment(block().first, block().size) = g.segment(block().first, block().size);
}

void FreeSet::reduced_free_gradient(const Vec&, const Vec& phi, double, Vec& phit) const {
  phit.segment(block().first, block().size) = phi.segment(block().first, block().size);
}

double FreeSet::feasible_step(const Vec&, const Vec&, bool) const { return kInfinity; }

template <bool kTwoSided>
BoundSet<kTwoSided>::BoundSet(Eigen::Index first, const Vec& lower, const Vec& upper)
    : SetKind({first, lower.size(), kTwoSided ? BlockKind::box : BlockKind::half_line}), lower_(lower) {
  if (!kTwoSided) return;
  if (upper.size() != lower.size()) throw std::invalid_argument("box block: lower and upper differ in size");
  upper_ = upper;
}

template <bool kTwoSided>
bool BoundSet<kTwoSided>::has_upper(Eigen::Index i) const {
  if constexpr (kTwoSided) return upper(i) < kInfinity;
  (void)i;
  return false;
}

template <bool kTwoSided>
bool BoundSet<kTwoSided>::free(Eigen::Index i, double x) const {
  if constexpr (kTwoSided) return above_bound(x, lower(i)) && x < upper(i);
  return above_bound(x, lower(i));
}

template <bool kTwoSided>
std::shared_ptr<const SetKind> BoundSet<kTwoSided>::shifted(const Vec& offset) const {
  const Vec moved = offset.segment(block().first, block().size);
  return std::make_shared<BoundSet>(block().first, lower_ - moved, kTwoSided ? Vec(upper_ - moved) : Vec());  // kUnbounded stays
}

template <bool kTwoSided>
int BoundSet<kTwoSided>::project(Vec& x) const {
  int projected = 0;
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i) {
    if (lower(i) != kUnbounded && x[i] < lower(i)) {
      x[i] = lower(i);
      ++projected;
    } else if (has_upper(i) && x[i] > upper(i)) {
      x[i] = upper(i);
      ++projected;
    }
  }
  return projected;
}

template <bool kTwoSided>
bool BoundSet<kTwoSided>::contains(const Vec& x) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i)
    if ((lower(i) != kUnbounded && x[i] < lower(i)) || (has_upper(i) && x[i] > upper(i))) return false;
  return true;
}

template <bool kTwoSided>
void BoundSet<kTwoSided>::restrict_to_face(const Vec& x, const Vec&, double, Vec& v) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i)
    if (!free(i, x[i])) v[i] = 0.0;
}

template <bool kTwoSided>
void BoundSet<kTwoSided>::mark_free(const Vec& x, std::vector<char>& face) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i) face[i] = free(i, x[i]);
}

template <bool kTwoSided>
void BoundSet<kTwoSided>::projected_gradient(const Vec& x, const Vec& g, Vec& gp) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i) {
    if (free(i, x[i])) gp[i] = g[i];
    else if (!above_bound(x[i], lower(i)) && has_upper(i) && x[i] >= upper(i)) gp[i] = 0.0;  // pinned: no direction is feasible
    else if (!above_bound(x[i], lower(i))) gp[i] = std::min(g[i], 0.0);  // at the lower bound
    else gp[i] = std::max(g[i], 0.0);                                     // at the upper bound
  }
}

template <bool kTwoSided>
void BoundSet<kTwoSided>::reduced_free_gradient(const Vec& x, const Vec& phi, double abar, Vec& phit) const {
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i) {
    phit[i] = phi[i];
    if (!free(i, x[i])) continue;
    if (lower(i) != kUnbounded) phit[i] = std::min((x[i] - lower(i)) / abar, phit[i]);
    if (has_upper(i)) phit[i] = std::max((x[i] - upper(i)) / abar, phit[i]);
  }
}

template <bool kTwoSided>
double BoundSet<kTwoSided>::feasible_step(const Vec& x, const Vec& p, bool) const {
  double step = kInfinity;
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i) {
    if (lower(i) != kUnbounded && p[i] > 0) step = std::min(step, (x[i] - lower(i)) / p[i]);
    if (p[i] < 0 && has_upper(i)) step = std::min(step, (x[i] - upper(i)) / p[i]);
  }
  return step;
}

template <bool kTwoSided>
int BoundSet<kTwoSided>::off_bound_count(const Vec& x) const {
  int count = 0;
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i)
    count += lower(i) != kUnbounded && x[i] > lower(i) ? 1 : 0;
  return count;
}

template <bool kTwoSided>
double BoundSet<kTwoSided>::linear_minimum(const Vec& y, Vec& x) const {
  if constexpr (!kTwoSided) return SetKind::linear_minimum(y, x);  // a half-line: unbounded along y < 0
  double value = 0;
  for (Eigen::Index i = block().first; i < block().first + block().size; ++i) {
    x[i] = y[i] > 0 ? lower(i) : y[i] < 0 ? upper(i) : 0.5 * (lower(i) + upper(i));
    value += y[i] * x[i];
  }
  return value;
}

template <bool kTwoSided>
void BoundSet<kTwoSided>::write_bounds(Vec& lower, Vec& upper) const {
  lower.segment(block().first, block().size) = lower_;
  if constexpr (kTwoSided) upper.segment(block().first, block().size) = upper_;
  (void)upper;
}

template class BoundSet<false>;
template class BoundSet<true>;

}  // namespace ffeti::qp
