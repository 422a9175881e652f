#include "feti/conjugate_projector.h"

#include <Eigen/Eigenvalues>

namespace ffeti {

ConjugateProjector::ConjugateProjector(Eigen::MatrixXd C, const DualOperator& F) {
  Eigen::MatrixXd FC;
  F.apply(C, FC);
  Eigen::MatrixXd E = C.transpose() * FC;
  C_ = C.sparseView();
  FC_ = FC.sparseView();  // the rows F does not reach stay exact zeros
  E = 0.5 * (E + E.transpose());  // symmetric up to the block solves' round-off
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(E);
  const Vec& values = eigen.eigenvalues();
  const double largest = values.size() ? values.maxCoeff() : 0.0;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < values.size(); ++i)
    if (values[i] > 1e-12 * largest) kept.push_back(i);
  const auto rank = static_cast<Eigen::Index>(kept.size());
  E_vectors_.resize(E.rows(), rank);
  E_inverse_values_.resize(rank);
  for (Eigen::Index k = 0; k < rank; ++k) {
    E_vectors_.col(k) = eigen.eigenvectors().col(kept[static_cast<size_t>(k)]);
    E_inverse_values_[k] = 1.0 / values[kept[static_cast<size_t>(k)]];
  }
}

Vec ConjugateProjector::solve_E(const Vec& r) const {
  return E_vectors_ * E_inverse_values_.cwiseProduct(E_vectors_.transpose() * r);
}

void ConjugateProjector::project(const Vec& x, Vec& y) const { y = x - C_ * solve_E(FC_.transpose() * x); }

void ConjugateProjector::project_transposed(const Vec& x, Vec& y) const { y = x - FC_ * solve_E(C_.transpose() * x); }

Vec ConjugateProjector::base(const Vec& d) const { return C_ * solve_E(C_.transpose() * d); }

}  // namespace ffeti
