// The Dirichlet preconditioner of the FETI dual problem (Farhat, Mandel, Roux), scaled for
// non-redundant gluing rows (Rixen, Farhat):
//   M^{-1} = A (sum_s B_s S_s B_s') A,  A = (B B')^{-1},  S_s = K_bb - K_bi K_ii^{-1} K_ib,
// b the dofs of subdomain s that its constraint rows touch, i the others. B B' is block
// diagonal (rows meet only where they share a node): at a node shared by m subdomains its
// m - 1 gluing rows make one block, and A reduces to the multiplicity scaling 1/m where the
// node has one row. It bounds the condition number of the projected operator by C (1 + log H/h)^2, so that
// projected CG takes a number of iterations bounded in h and in the number of subdomains
// (docs/results/scalability.md). Costs one more factorization per subdomain (K_ii; one per
// set of identical ones) and per application one K_ii solve per subdomain, as much as an
// application of F.
// The lumped variant keeps S_s ~ K_bb: no factorization, a sparse product per application.
// Stiffness scaling (Rixen, Farhat: "k-scaling") weighs each subdomain's side of a row by the
// stiffness of the others there: with D the diagonal of K_s at each column of B,
//   M^{-1} = A B D^{-1} S D^{-1} B' A,  A = (B D^{-1} B')^{-1},
// which is the multiplicity scaling where the sides are equally stiff (a regular grid's
// straight interfaces) and, for one row between two one-dof subdomains, the exact inverse
// of F. On unstructured METIS parts, whose sides differ, the lumped one took fewer
// multiplications (docs/results/real-meshes.md); the Dirichlet one on membranes graded
// 1:1000 more (feti_problem_test.cpp).
#pragma once

#include "factor/cholmod_factor.h"
#include "constraints/constraints.h"
#include "parallel/subdomain_sum.h"

#include <Eigen/SparseCholesky>

#include <memory>
#include <vector>

namespace ffeti {

/// The preconditioner of the dual problem a set-up asks for (fetiSetup's `preconditioner`).
enum class DualPreconditioner { none, lumped, dirichlet };
/// How it weighs the sides of a row (fetiSetup's `scaling`): A = (BB')^{-1}, or by stiffness.
enum class InterfaceScaling { multiplicity, stiffness };

class DirichletPreconditioner {
 public:
  /// `operator_matrices[k]`: the K of local subdomain k as the dual operator sees it;
  /// `local[k]` its constraint block; `global_ids[k]` its global index (errors name it);
  /// `constraints` all rows (every rank's copy); `sum` the
  /// ordered sum over subdomains of F; `lumped`: S_s replaced by K_bb (no K_ii);
  /// `share_factors`: subdomains whose K_ii are bitwise equal factorize it once
  /// (SharedFactors); `scaling`: the weights of the rows' sides. Keeps references to `local`
  /// and `sum`. Collective (stiffness scaling gathers every rank's weights).
  DirichletPreconditioner(const std::vector<const SparseMatrix*>& operator_matrices,
                          const std::vector<LocalConstraints>& local, const std::vector<int>& global_ids,
                          const Constraints& constraints, const SubdomainSum& sum, int threads, bool lumped,
                          bool share_factors, InterfaceScaling scaling = InterfaceScaling::multiplicity);
  ~DirichletPreconditioner();

  /// y = M^{-1} x. Collective.
  void apply(const Vec& x, Vec& y) const;
  /// Wall-clock seconds spent in apply so far.
  double application_seconds() const { return application_seconds_; }
  /// Bytes held on this rank: each subdomain's K_bb, K_ib, weights and buffers, the K_ii
  /// factors (one per set of identical ones), B B''s factor.
  double held_bytes() const;

 private:
  struct Block;
  const std::vector<LocalConstraints>& local_;
  const SubdomainSum& sum_;
  int threads_;
  // B B' has a block of a few rows per node (and per contact couple): Eigen's simplicial
  // Cholesky is enough, and it is not a subdomain factorization (fetiFactorizations).
  Eigen::SimplicialLLT<SparseMatrix> row_gram_;
  std::vector<std::unique_ptr<Block>> blocks_;
  mutable Vec scaled_, summed_;
  mutable std::vector<Vec> results_;
  mutable std::vector<double> flat_;
  mutable double application_seconds_ = 0;
};

}  // namespace ffeti
