#include "feti/kernel.h"

#include <algorithm>
#include <cmath>

namespace ffeti {

Eigen::MatrixXd candidate_kernel(const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<int>& component) {
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  const bool vector_field =
      std::any_of(component.begin(), component.end(), [](int c) { return c != 0; });
  if (!vector_field) return Eigen::MatrixXd::Ones(n, 1);
  double xc = 0, yc = 0;
  for (Eigen::Index i = 0; i < n; ++i) xc += x[i], yc += y[i];
  xc /= std::max<Eigen::Index>(n, 1);
  yc /= std::max<Eigen::Index>(n, 1);
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const int c = component[i];
    R(i, c) = 1.0;                                 // translation along component c
    R(i, 2) = c == 0 ? -(y[i] - yc) : (x[i] - xc);  // rotation about the centroid
  }
  return R;
}

Eigen::MatrixXd kernel_in_span(const SparseMatrix& K, const Eigen::MatrixXd& candidates) {
  if (candidates.cols() == 0) return candidates;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(candidates);
  const Eigen::MatrixXd Q =
      qr.householderQ() * Eigen::MatrixXd::Identity(candidates.rows(), candidates.cols());
  const Eigen::MatrixXd KQ = K * Q;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(KQ, Eigen::ComputeThinV);
  // Rounding leaves ||K q|| ~ eps ||K|| sqrt(n) for a true kernel vector, while a constrained
  // mode has ||K q|| of the order of a diagonal entry: the threshold separates the two.
  const double scale = K.coeffs().cwiseAbs().maxCoeff();
  const double threshold = 1e-8 * scale;
  std::vector<Eigen::Index> null_columns;
  for (Eigen::Index j = 0; j < svd.singularValues().size(); ++j)
    if (svd.singularValues()[j] <= threshold) null_columns.push_back(j);
  Eigen::MatrixXd R(Q.rows(), static_cast<Eigen::Index>(null_columns.size()));
  for (size_t k = 0; k < null_columns.size(); ++k)
    R.col(static_cast<Eigen::Index>(k)) = Q * svd.matrixV().col(null_columns[k]);
  return R;
}

std::vector<int> fixing_dofs(const Eigen::MatrixXd& R) {
  const Eigen::MatrixXd Rt = R.transpose();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Rt);
  std::vector<int> dofs;
  for (Eigen::Index k = 0; k < R.cols(); ++k) dofs.push_back(qr.colsPermutation().indices()[k]);
  std::sort(dofs.begin(), dofs.end());
  return dofs;
}

}  // namespace ffeti
