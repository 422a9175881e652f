#include "solid_block.h"

#include "feti/dirichlet.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace ffeti {

Eigen::MatrixXd tetrahedron_stiffness(const std::array<Eigen::Vector3d, 4>& p, double young, double poisson) {
  Eigen::Matrix4d M;
  for (int k = 0; k < 4; ++k) M.row(k) << 1, p[k].transpose();
  const Eigen::Matrix4d C = M.inverse();  // columns: barycentric coordinates' coefficients
  const double volume = std::abs(M.determinant()) / 6;
  Eigen::Matrix<double, 6, 12> B = Eigen::Matrix<double, 6, 12>::Zero();
  for (int k = 0; k < 4; ++k) {
    const double gx = C(1, k), gy = C(2, k), gz = C(3, k);
    B(0, 3 * k) = gx, B(1, 3 * k + 1) = gy, B(2, 3 * k + 2) = gz;
    B(3, 3 * k) = gy, B(3, 3 * k + 1) = gx;
    B(4, 3 * k + 1) = gz, B(4, 3 * k + 2) = gy;
    B(5, 3 * k) = gz, B(5, 3 * k + 2) = gx;
  }
  const double lambda = young * poisson / ((1 + poisson) * (1 - 2 * poisson)), mu = young / (2 * (1 + poisson));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  D.topLeftCorner<3, 3>().diagonal().array() += 2 * mu;
  D.bottomRightCorner<3, 3>().diagonal().setConstant(mu);
  return volume * B.transpose() * D * B;
}

SubdomainInput solid_block(double x0, const std::array<double, 3>& size, const std::array<int, 3>& cells,
                           const std::array<double, 3>& top, double turn) {
  const int nx = cells[0], ny = cells[1], nz = cells[2];
  const auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  const int nodes = (nx + 1) * (ny + 1) * (nz + 1);
  std::vector<Eigen::Vector3d> position(static_cast<size_t>(nodes));
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        position[static_cast<size_t>(id(i, j, k))] = {x0 + size[0] * i / nx, size[1] * j / ny, size[2] * k / nz};
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        // Kuhn's six tetrahedra: from corner (0,0,0) to (1,1,1) one axis at a time, in each order.
        std::array<int, 3> axes{0, 1, 2};
        do {
          std::array<int, 3> step{0, 0, 0};
          std::array<int, 4> v;
          v[0] = id(i, j, k);
          for (int s = 0; s < 3; ++s) {
            step[static_cast<size_t>(axes[static_cast<size_t>(s)])] = 1;
            v[static_cast<size_t>(s) + 1] = id(i + step[0], j + step[1], k + step[2]);
          }
          std::array<Eigen::Vector3d, 4> p;
          for (size_t a = 0; a < 4; ++a) p[a] = position[static_cast<size_t>(v[a])];
          const Eigen::MatrixXd Ke = tetrahedron_stiffness(p, 1000, 0.3);
          for (int a = 0; a < 12; ++a)
            for (int b = 0; b < 12; ++b)
              entries.emplace_back(3 * v[static_cast<size_t>(a / 3)] + a % 3, 3 * v[static_cast<size_t>(b / 3)] + b % 3,
                                   Ke(a, b));
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
  // Turned about z after the stiffness is assembled in the unturned frame: a turned block
  // has the turned stiffness Q K Q', Q the turn applied to each node's three dofs.
  const double c = std::cos(turn), s = std::sin(turn);
  Eigen::Matrix3d Q;
  Q << c, -s, 0, s, c, 0, 0, 0, 1;
  SparseMatrix K(3 * nodes, 3 * nodes), blocks(3 * nodes, 3 * nodes);
  K.setFromTriplets(entries.begin(), entries.end());
  std::vector<Eigen::Triplet<double, int>> turn_entries;
  for (int n = 0; n < nodes; ++n)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) turn_entries.emplace_back(3 * n + a, 3 * n + b, Q(a, b));
  blocks.setFromTriplets(turn_entries.begin(), turn_entries.end());
  SubdomainInput out;
  out.K = SparseMatrix(blocks * K * SparseMatrix(blocks.transpose()));
  out.f = Vec::Zero(3 * nodes);
  const Eigen::Vector3d moved = Q * Eigen::Vector3d(top[0], top[1], top[2]);
  for (int n = 0; n < nodes; ++n) {
    const Eigen::Vector3d p = Q * position[static_cast<size_t>(n)];
    for (int a = 0; a < 3; ++a) {
      out.x.push_back(p[0]), out.y.push_back(p[1]), out.z.push_back(p[2]), out.component.push_back(a);
      if (position[static_cast<size_t>(n)][2] == size[2]) {
        out.dirichlet_dofs.push_back(3 * n + a);
        out.dirichlet_values.push_back(moved[a]);
      }
    }
  }
  return out;
}

std::vector<std::vector<int>> bottom_dofs(const std::vector<SubdomainInput>& subdomains) {
  std::vector<std::vector<int>> out;
  for (const SubdomainInput& s : subdomains) {
    out.emplace_back();
    for (int k = 0; k < static_cast<int>(s.z.size()); ++k)
      if (s.z[static_cast<size_t>(k)] == 0) out.back().push_back(k);
  }
  return out;
}

SparseMatrix clamped_block_stiffness(int cells, double x0) {
  const SubdomainInput s = solid_block(x0, {1, 1, 1}, {cells, cells, cells}, {0, 0, 0});
  SparseMatrix K = eliminate_dirichlet(s.K, s.dirichlet_dofs);
  K.makeCompressed();
  return K;
}

}  // namespace ffeti
