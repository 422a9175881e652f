// The FETI dual operator F = B K^+ B' = sum_s B_s K_s^+ B_s', applied implicitly.
#pragma once

#include "feti/constraints.h"
#include "feti/subdomain.h"

#include <vector>

namespace ffeti {

/// Stores references to the subdomains and their constraint blocks: both must outlive it.
/// Per-subdomain buffers are preallocated, so an application allocates nothing.
class DualOperator {
 public:
  DualOperator(const SubdomainList& subdomains,
               const std::vector<LocalConstraints>& local, int rows, int threads);

  int rows() const { return rows_; }

  /// y = F x: in parallel over subdomains w_s = K_s^+ B_s' x, then y = sum_s B_s w_s
  /// accumulated in subdomain order (the same sum for any thread count).
  void apply(const Vec& x, Vec& y) const;

  /// y = B K^+ v for per-subdomain vectors v_s (d = B K^+ f - c uses it).
  void apply_B_pseudo_inverse(const std::vector<Vec>& v, Vec& y) const;

  /// w_s = K_s^+ (v_s - B_s' x) for every subdomain (primal recovery).
  void pseudo_inverse_of_residual(const std::vector<Vec>& v, const Vec& x,
                                  std::vector<Vec>& w) const;

 private:
  void scatter_add(Vec& y) const;

  const SubdomainList& subdomains_;
  const std::vector<LocalConstraints>& local_;
  int rows_;
  int threads_;
  mutable std::vector<Vec> gathered_, local_rhs_, local_solution_, local_result_;
};

/// OpenMP thread count to use: `requested` if > 0, else the runtime default.
int resolve_thread_count(int requested);

}  // namespace ffeti
