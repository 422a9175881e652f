#include "feti/coarse_space.h"

#include "feti/errors.h"

#include <set>
#include <string>

namespace ffeti {

CoarseSpace::CoarseSpace(const SubdomainList& subdomains,
                         const std::vector<LocalConstraints>& local, int rows,
                         const std::vector<int>& bodies)
    : subdomains_(subdomains) {
  std::vector<Eigen::Triplet<double, int>> entries;
  for (size_t s = 0; s < subdomains.size(); ++s) {
    if (!subdomains[s]->floating()) continue;
    const Eigen::MatrixXd BR = local[s].B * subdomains[s]->kernel();  // rows of G, restricted
    for (Eigen::Index j = 0; j < BR.cols(); ++j) {
      const int g_row = static_cast<int>(owner_.size());
      owner_.emplace_back(static_cast<int>(s), static_cast<int>(j));
      for (size_t k = 0; k < local[s].rows.size(); ++k)
        if (BR(static_cast<Eigen::Index>(k), j) != 0)
          entries.emplace_back(g_row, local[s].rows[k], BR(static_cast<Eigen::Index>(k), j));
    }
  }
  G_.resize(static_cast<Eigen::Index>(owner_.size()), rows);
  G_.setFromTriplets(entries.begin(), entries.end());
  if (owner_.empty()) return;

  const Eigen::MatrixXd GGt = Eigen::MatrixXd(G_ * G_.transpose());
  GGt_.compute(GGt);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> spectrum(GGt);
  const double largest = spectrum.eigenvalues().maxCoeff();
  if (GGt_.info() == Eigen::Success && spectrum.eigenvalues().minCoeff() > 1e-12 * largest) return;

  // Singular GG': some combination of rigid modes meets no constraint. Name the bodies.
  std::set<int> unrestrained;
  for (Eigen::Index k = 0; k < spectrum.eigenvalues().size(); ++k) {
    if (spectrum.eigenvalues()[k] > 1e-12 * largest) continue;
    const auto v = spectrum.eigenvectors().col(k);
    for (Eigen::Index i = 0; i < v.size(); ++i)
      if (std::abs(v[i]) > 1e-6)
        unrestrained.insert(bodies[static_cast<size_t>(owner_[static_cast<size_t>(i)].first)]);
  }
  std::string names;
  for (int b : unrestrained) names += (names.empty() ? "" : ", ") + std::to_string(b);
  throw InputError("body: the rigid body modes of body " + names +
                   " are not restrained by any Dirichlet, gluing or contact condition "
                   "(add a Dirichlet condition or a contact zone; GG' is singular)");
}

Vec CoarseSpace::kernel_load(const std::vector<Vec>& f) const {
  Vec e(G_.rows());
  for (size_t k = 0; k < owner_.size(); ++k) {
    const auto [s, j] = owner_[k];
    e[static_cast<Eigen::Index>(k)] =
        subdomains_[static_cast<size_t>(s)]->kernel().col(j).dot(f[static_cast<size_t>(s)]);
  }
  return e;
}

void CoarseSpace::project_range(const Vec& x, Vec& y) const {
  if (empty()) {
    y.setZero(x.size());
    return;
  }
  const Vec coarse = GGt_.solve(G_ * x);  // (GG')^{-1} G x
  y.noalias() = G_.transpose() * coarse;
}

void CoarseSpace::project(const Vec& x, Vec& y) const {
  if (empty()) {
    y = x;
    return;
  }
  const Vec coarse = GGt_.solve(G_ * x);
  y = x;
  y.noalias() -= G_.transpose() * coarse;
}

Vec CoarseSpace::least_norm_solution(const Vec& e) const {
  if (empty()) return Vec::Zero(G_.cols());
  return G_.transpose() * GGt_.solve(e);
}

}  // namespace ffeti
