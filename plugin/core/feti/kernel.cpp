#include "feti/kernel.h"

#include <algorithm>
#include <cmath>

namespace ffeti {

Eigen::MatrixXd candidate_kernel(const std::vector<double>& x, const std::vector<double>& y,
                                 const std::vector<int>& component, const std::vector<double>& z) {
  const Eigen::Index n = static_cast<Eigen::Index>(x.size());
  const bool vector_field =
      std::any_of(component.begin(), component.end(), [](int c) { return c != 0; });
  if (!vector_field) return Eigen::MatrixXd::Ones(n, 1);
  const bool three_d = !z.empty();
  double xc = 0, yc = 0, zc = 0;
  for (Eigen::Index i = 0; i < n; ++i) xc += x[i], yc += y[i], zc += three_d ? z[i] : 0.0;
  const double count = static_cast<double>(std::max<Eigen::Index>(n, 1));
  xc /= count, yc /= count, zc /= count;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(n, three_d ? 6 : 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const int c = component[i];
    const double dx = x[i] - xc, dy = y[i] - yc;
    R(i, c) = 1.0;  // translation along component c
    if (!three_d) {
      R(i, 2) = c == 0 ? -dy : dx;  // rotation about the centroid
      continue;
    }
    // Rotations about the x, y and z axes through the centroid: omega x (x - xc).
    const double dz = z[i] - zc;
    const double about_x[3] = {0, -dz, dy}, about_y[3] = {dz, 0, -dx}, about_z[3] = {-dy, dx, 0};
    R(i, 3) = about_x[c], R(i, 4) = about_y[c], R(i, 5) = about_z[c];
  }
  return R;
}

Eigen::MatrixXd kernel_in_span(const SparseMatrix& K, const Eigen::MatrixXd& candidates) {
  if (candidates.cols() == 0) return candidates;
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(candidates);
  const Eigen::MatrixXd Q =
      qr.householderQ() * Eigen::MatrixXd::Identity(candidates.rows(), candidates.cols());
  const Eigen::MatrixXd KQ = K.selfadjointView<Eigen::Lower>() * Q;
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(KQ, Eigen::ComputeThinV);
  // Rounding leaves ||K q|| ~ eps ||K|| sqrt(n) for a true kernel vector, while a constrained
  // mode has ||K q|| of the order of a diagonal entry: the threshold separates the two.
  const double scale = K.coeffs().cwiseAbs().maxCoeff();
  const double threshold = 1e-8 * scale;
  std::vector<Eigen::Index> null_columns;
  for (Eigen::Index j = 0; j < svd.singularValues().size(); ++j)
    if (svd.singularValues()[j] <= threshold) null_columns.push_back(j);
  // The whole span a kernel (every floating subdomain of Total FETI): Q itself. The singular
  // vectors of K Q, all of whose values are then rounding, would turn it by a rotation that
  // only the rounding decides, and with it every later round-off (the friction onset's 24
  // pulls took 2735 to 3007 multiplications with round-off alone: docs/log.md, 2026-12-07).
  if (static_cast<Eigen::Index>(null_columns.size()) == Q.cols()) return Q;
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
