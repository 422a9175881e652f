// Natural coarse space: G = R'B' (one row per kernel vector of a floating subdomain),
// e = R'f, the factor of GG' and the orthogonal projector P = I - G'(GG')^{-1}G onto Ker G.
#pragma once

#include "feti/constraints.h"
#include "feti/subdomain.h"

#include <Eigen/Dense>

#include <vector>

namespace ffeti {

class CoarseSpace {
 public:
  /// Throws InputError naming the bodies whose rigid modes no constraint restrains
  /// (GG' singular). `bodies[s]` is the body of subdomain s, for that message.
  CoarseSpace(const SubdomainList& subdomains, const std::vector<LocalConstraints>& local,
              int rows, const std::vector<int>& bodies);

  int dimension() const { return static_cast<int>(G_.rows()); }
  bool empty() const { return G_.rows() == 0; }
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& G() const { return G_; }
  /// Subdomain and kernel column behind each row of G.
  const std::vector<std::pair<int, int>>& row_owner() const { return owner_; }

  /// e = R'f for per-subdomain loads f_s.
  Vec kernel_load(const std::vector<Vec>& f) const;
  /// y = P x, P = I - G'(GG')^{-1} G.
  void project(const Vec& x, Vec& y) const;
  /// y = Q x = G'(GG')^{-1} G x = x - P x.
  void project_range(const Vec& x, Vec& y) const;
  /// The least-norm solution of G lambda = e: G'(GG')^{-1} e.
  Vec least_norm_solution(const Vec& e) const;

 private:
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> G_;
  std::vector<std::pair<int, int>> owner_;
  Eigen::LLT<Eigen::MatrixXd> GGt_;
  const SubdomainList& subdomains_;
};

}  // namespace ffeti
