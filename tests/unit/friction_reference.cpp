#include "friction_reference.h"

#include <algorithm>
#include <cmath>

namespace ffeti {

std::vector<ReferenceForces> friction_dual(const Eigen::MatrixXd& K, const Vec& f, const std::vector<int>& fixed,
                                           const std::vector<double>& fixed_values, const std::vector<ReferenceRow>& rows) {
  const Eigen::Index n = K.rows();
  Vec prescribed = Vec::Zero(n);
  std::vector<bool> is_fixed(static_cast<size_t>(n), false);
  for (size_t k = 0; k < fixed.size(); ++k) prescribed[fixed[k]] = fixed_values[k], is_fixed[static_cast<size_t>(fixed[k])] = true;
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!is_fixed[static_cast<size_t>(i)]) free.push_back(i);
  const auto nf = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd Kff(nf, nf);
  Vec ff(nf);
  const Vec loaded = f - K * prescribed;
  for (Eigen::Index a = 0; a < nf; ++a) {
    ff[a] = loaded[free[static_cast<size_t>(a)]];
    for (Eigen::Index b = 0; b < nf; ++b) Kff(a, b) = K(free[static_cast<size_t>(a)], free[static_cast<size_t>(b)]);
  }
  // B: the normal rows, then each row's tangents; entries on fixed dofs to c.
  std::vector<Vec> all;
  std::vector<double> c;
  for (const ReferenceRow& r : rows) all.push_back(r.normal), c.push_back(r.gap);
  for (const ReferenceRow& r : rows)
    for (const Vec& t : r.tangents) all.push_back(t), c.push_back(0);
  const auto m = static_cast<Eigen::Index>(all.size());
  Eigen::MatrixXd B(m, nf);
  Vec cv(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    cv[i] = c[static_cast<size_t>(i)] - all[static_cast<size_t>(i)].dot(prescribed);
    for (Eigen::Index a = 0; a < nf; ++a) B(i, a) = all[static_cast<size_t>(i)][free[static_cast<size_t>(a)]];
  }
  const Eigen::LLT<Eigen::MatrixXd> Kllt(Kff);
  const Eigen::MatrixXd H = B * Kllt.solve(B.transpose());
  const Vec d = B * Kllt.solve(ff) - cv;
  const auto rows_n = static_cast<Eigen::Index>(rows.size());
  const auto project = [&](Vec& l) {
    Eigen::Index t = rows_n;
    for (Eigen::Index k = 0; k < rows_n; ++k) {
      l[k] = std::max(l[k], 0.0);
      const auto size = static_cast<Eigen::Index>(rows[static_cast<size_t>(k)].tangents.size());
      const double norm = l.segment(t, size).norm(), g = rows[static_cast<size_t>(k)].bound;
      if (norm > g) l.segment(t, size) *= g / norm;
      t += size;
    }
  };
  const double step = 1 / Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(H).eigenvalues().maxCoeff();
  Vec l = Vec::Zero(m), y = l;
  double momentum = 1;
  for (int it = 0; it < 2000000; ++it) {
    Vec next = y - step * (H * y - d);
    project(next);
    if ((y - next).dot(next - l) > 0) momentum = 1;  // the step turned back: restart the momentum
    const double next_momentum = (1 + std::sqrt(1 + 4 * momentum * momentum)) / 2;
    const double moved = (next - l).norm();
    y = next + (momentum - 1) / next_momentum * (next - l);
    l = next, momentum = next_momentum;
    if (moved <= 1e-15 * l.norm()) break;
  }
  std::vector<ReferenceForces> out;
  Eigen::Index t = rows_n;
  for (Eigen::Index k = 0; k < rows_n; ++k) {
    ReferenceForces forces{l[k], {}};
    for (size_t j = 0; j < rows[static_cast<size_t>(k)].tangents.size(); ++j) forces.tangential.push_back(l[t++]);
    out.push_back(forces);
  }
  return out;
}

SubdomainInput mirrored(SubdomainInput body) {
  const bool three_d = !body.z.empty();
  std::vector<double>& last = three_d ? body.z : body.y;
  for (double& v : last) v = -v;
  const int flipped = three_d ? 2 : 1;
  const auto sign = [&](Eigen::Index dof) { return body.component[static_cast<size_t>(dof)] == flipped ? -1.0 : 1.0; };
  for (int k = 0; k < body.K.get().outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(body.K, k); it; ++it) it.valueRef() *= sign(it.row()) * sign(it.col());
  for (Eigen::Index i = 0; i < body.f.size(); ++i) body.f[i] *= sign(i);
  for (size_t k = 0; k < body.dirichlet_dofs.size(); ++k) body.dirichlet_values[k] *= sign(body.dirichlet_dofs[k]);
  return body;
}

}  // namespace ffeti
