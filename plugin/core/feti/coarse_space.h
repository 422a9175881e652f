// Natural coarse space: G = R'B' (one row per kernel vector of a floating subdomain),
// e = R'f, the factor of GG' and the orthogonal projector P = I - G'(GG')^{-1}G onto Ker G.
// G is small (rows: rigid modes; nonzeros: interface rows of floating subdomains): every
// rank builds it whole from the blocks B_s R_s of all ranks and factors GG' redundantly.
#pragma once

#include "constraints/constraints.h"
#include "feti/coarse_gram.h"
#include "feti/subdomain.h"
#include "parallel/communicator.h"
#include "qp/problem.h"

#include <Eigen/Dense>

#include <memory>
#include <vector>

namespace ffeti {

class CoarseSpace {
 public:
  /// `subdomains` and `local` are this rank's, `global_ids` their global indices; `bodies`
  /// covers all subdomains; the constraint rows from `first_bounded` on are bounded. Throws InputError naming the bodies whose rigid modes no
  /// constraint restrains (GG' singular). Keeps a reference to `subdomains` and `comm`.
  CoarseSpace(const SubdomainList& subdomains, const std::vector<LocalConstraints>& local,
              const std::vector<int>& global_ids, int rows, int first_bounded, const std::vector<int>& bodies,
              const Communicator& comm, GramLayout layout = GramLayout::automatic);

  int dimension() const { return static_cast<int>(G_.rows()); }
  bool empty() const { return G_.rows() == 0; }
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& G() const { return G_; }
  /// GG' and the Gram matrices over fewer columns (G_F G_F', G_S G_S'). Precondition: !empty().
  const CoarseGram& gram() const { return *gram_; }
  /// Bytes held: G, its row maps and GG''s factor (CoarseGram::held_bytes).
  double held_bytes() const;
  /// Global subdomain and kernel column behind each row of G (ascending subdomain).
  const std::vector<std::pair<int, int>>& row_owner() const { return owner_; }
  /// Number of floating subdomains over all ranks.
  int floating_subdomains() const;

  /// e = R'f for this rank's loads f_s (collective; the whole e on every rank).
  Vec kernel_load(const std::vector<Vec>& f) const;
  /// u_s += R_s alpha_s for this rank's subdomains, alpha indexed like the rows of G.
  void add_kernel_component(const Vec& alpha, std::vector<Vec>& u) const;
  /// y = P x, P = I - G'(GG')^{-1} G.
  void project(const Vec& x, Vec& y) const;
  /// y = Q x = G'(GG')^{-1} G x = x - P x.
  void project_range(const Vec& x, Vec& y) const;
  /// ||K u - f + B'lambda||_2 over all subdomains for u = K^+(f - B'lambda) + R alpha, from
  /// the defect G lambda - e alone: the fixing-dofs K^+ leaves the residual at the fixing
  /// dofs F of each floating subdomain, where it is (R_F')^{-1} R'(f - B'lambda). Collective.
  double equilibrium_residual_norm(const Vec& defect) const;
  /// The least-norm solution of G lambda = e: G'(GG')^{-1} e.
  Vec least_norm_solution(const Vec& e) const;

  /// min ||G lambda - e|| over lambda in `bounds` (the multipliers' constraint set),
  /// relative to ||e||; 0 when no bound is
  /// active at the minimum or e = 0. Positive: no multipliers within their bounds balance the
  /// loads on the floating bodies (a body pulled off the contacts that could hold it, or
  /// pushed along them harder than friction holds), so the problem has no solution. Found by MPRGP on G'G (cheap: G
  /// has one row per rigid mode); -1 if MPRGP did not converge (undecided). Stops at the
  /// first iterate within `enough` (returning that distance): feasibility needs no more, and
  /// resolving the minimum to round-off took 306 multiplications, 0.7 s, at 2016 floating
  /// subdomains. Same on every rank.
  double feasibility_residual(const Vec& e, const qp::ConstraintSet& bounds, double enough) const;

 private:
  /// G's rows (one per kernel vector (s, j) of a floating subdomain, in ascending (s, j)),
  /// owner_ and local_rows_ from B_s R_s: on one rank straight from `BR`; on several from
  /// every rank's packed B_s R_s.
  void assemble_local_rows(const std::vector<Eigen::MatrixXd>& BR, const std::vector<LocalConstraints>& local,
                           const std::vector<int>& global_ids, int rows);
  void assemble_gathered_rows(const std::vector<Eigen::MatrixXd>& BR, const std::vector<LocalConstraints>& local,
                              const std::vector<int>& global_ids, int rows, int subdomain_count, const Communicator& comm);

  Eigen::SparseMatrix<double, Eigen::RowMajor, int> G_;
  std::vector<std::pair<int, int>> owner_;
  std::vector<std::pair<int, int>> local_rows_;  // (row of G, local subdomain index)
  // GG' couples the rigid modes of neighbouring subdomains only: sparse. A dense factor
  // costs O(dim^3) to build and O(dim^2) per projection (dim = 2016 floating subdomains at
  // n = 2048 of the model problem, docs/results/scalability.md). CHOLMOD, supernodal where
  // the fill calls for it: at 8192 3D subdomains (dim 49,152) GG' fills like a 3D problem
  // and a simplicial factor took most of the set-up (docs/log.md). Its solves use the
  // factor's own workspace: projections are not thread-safe.
  std::unique_ptr<CoarseGram> gram_;
  mutable Vec coarse_rhs_, coarse_solution_;  // a projection's G x and (GG')^{-1} G x: no allocation per call
  const SubdomainList& subdomains_;
  const Communicator& comm_;
};

}  // namespace ffeti
