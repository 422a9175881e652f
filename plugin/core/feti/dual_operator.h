// The FETI dual operator F = B K^+ B' = sum_s B_s K_s^+ B_s', applied implicitly.
#pragma once

#include "parallel/process.h"

#include "constraints/constraints.h"
#include "feti/subdomain.h"
#include "parallel/subdomain_sum.h"

#include <vector>

namespace ffeti {

/// Works on this rank's subdomains; dual vectors (length m) are replicated on every rank.
/// Stores references to the subdomains, their constraint blocks and the sum: all must
/// outlive it. Per-subdomain buffers are preallocated, so an application allocates only
/// the exchange buffer.
class DualOperator {
 public:
  DualOperator(const SubdomainList& subdomains, const std::vector<LocalConstraints>& local,
               const SubdomainSum& sum, int rows, int threads);

  int rows() const { return rows_; }

  /// y = F x: in parallel over subdomains w_s = K_s^+ B_s' x, then y = sum_s B_s w_s
  /// added in global subdomain order (the same sum for any thread or rank count). Where a
  /// subdomain holds an explicit block of K_s^+ on its interface or its factor ordered the
  /// interface last, and B_s touches nothing else, w_s is computed on the interface alone
  /// (Subdomain::apply_pseudo_inverse_on_interface: a dense product, or a solve that reads
  /// the factor's interface block).
  void apply(const Vec& x, Vec& y) const;

  /// Y = F X for a block of dual vectors (columns): one pass over each subdomain's factor
  /// for all columns, then per column the same ordered sum as apply(). A column agrees with
  /// apply() to round-off (CHOLMOD's block solve may order its operations differently).
  void apply(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const;

  /// y = B K^+ v for per-subdomain vectors v_s (d = B K^+ f - c uses it); a subdomain whose
  /// v_s is zero solves nothing (most of a large scene's loads are).
  void apply_B_pseudo_inverse(const std::vector<Vec>& v, Vec& y) const;

  /// Bv = B K^+ v and Fx = F x (the dual data's d and F lambda~) in one pass over the
  /// subdomains, each as apply_B_pseudo_inverse() and apply() compute them.
  void apply_B_pseudo_inverse_and_F(const std::vector<Vec>& v, const Vec& x, Vec& Bv, Vec& Fx) const;

  /// y = B u for per-subdomain vectors u_s.
  void apply_B(const std::vector<Vec>& u, Vec& y) const;

  /// Wall-clock seconds spent in apply() (both forms) since construction: a solve's share
  /// of its time that is the dual operator itself, apart from the vector and coarse work.
  double application_seconds() const { return application_seconds_; }
  /// Columns F was applied to in apply() (both forms) since construction.
  long applications() const { return applications_; }
  /// Of application_seconds(), the subdomain solves K_s^+ (CHOLMOD's forward and backward
  /// triangular solves with the reduced-to-full copies around them), summed over
  /// subdomains: thread-seconds, the wall-clock share only on one thread. The rest of an
  /// application is B_s', B_s and the sum over subdomains.
  double solve_seconds() const { return solve_seconds_; }

  /// Bytes held on this rank: the B_s renumbered to their interfaces and the buffers of
  /// the applications so far.
  double held_bytes() const;

  /// sum_s ||B_s' x||^2 over this rank's subdomains (callers sum over the ranks).
  double local_transpose_squared_norm(const Vec& x) const;

  /// w_s = K_s^+ (v_s - B_s' x) for every local subdomain (primal recovery).
  void pseudo_inverse_of_residual(const std::vector<Vec>& v, const Vec& x,
                                  std::vector<Vec>& w) const;

 private:
  void sum_local_results(Vec& y) const;
  /// body(i) for every local subdomain i on the operator's threads; a failure in any (a
  /// solve out of memory) is rethrown on every rank after all ran (rethrow_on_every_rank).
  template <class Body>
  void on_subdomains(Body&& body) const;
  /// result = B_s K_s^+ B_s' x_s for local subdomain i, as apply() defines it; returns the
  /// seconds of its solve.
  double apply_on_subdomain(size_t i, const Vec& x, Eigen::Ref<Vec> result) const;
  /// result = B_s K_s^+ v_s for local subdomain i.
  void B_pseudo_inverse_on_subdomain(size_t i, const Vec& v, Eigen::Ref<Vec> result) const;
  /// y (rows x cols): column j the ordered sum of block_result_[s].col(j) over subdomains.
  void sum_block_results(Eigen::Index cols, Eigen::MatrixXd& y) const;

  const SubdomainList& subdomains_;
  const std::vector<LocalConstraints>& local_;
  const SubdomainSum& sum_;
  int rows_;
  int threads_;
  /// Per subdomain, B_s with its columns renumbered to the subdomain's interface (rows x
  /// interface size); empty where apply() takes the whole-subdomain solve.
  std::vector<SparseMatrix> interface_B_;
  mutable std::vector<Vec> gathered_, local_rhs_, local_solution_, local_result_, interface_rhs_, interface_solution_;
  mutable std::vector<Eigen::MatrixXd> block_gathered_, block_rhs_, block_solution_, block_result_;
  mutable Vec column_;
  mutable double application_seconds_ = 0, solve_seconds_ = 0;
  mutable std::vector<double> subdomain_solve_seconds_;  // of one application, per subdomain
  mutable long applications_ = 0;
  mutable std::vector<double> flat_;
};

}  // namespace ffeti
