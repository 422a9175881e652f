#include "plane_block.h"

#include <Eigen/Dense>

#include <cmath>
#include <vector>

namespace ffeti {
namespace {

constexpr double kYoung = 1000, kPoisson = 0.3;

}  // namespace

SubdomainInput elastic_block(double x0, double w, double h, int nx, int ny, double drag, double push) {
  SubdomainInput s;
  const int nodes = (nx + 1) * (ny + 1);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      for (int c = 0; c < 2; ++c) s.x.push_back(x0 + w * i / nx), s.y.push_back(h * j / ny), s.component.push_back(c);
  const double lambda = kYoung * kPoisson / ((1 + kPoisson) * (1 - 2 * kPoisson)), mu = kYoung / (2 * (1 + kPoisson));
  Eigen::Matrix3d D;
  D << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
  std::vector<Eigen::Triplet<double, int>> entries;
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  const auto triangle = [&](int a, int b, int c) {
    const int v[3] = {a, b, c};
    const double xa = s.x[2 * a], ya = s.y[2 * a];
    const double area = 0.5 * ((s.x[2 * b] - xa) * (s.y[2 * c] - ya) - (s.x[2 * c] - xa) * (s.y[2 * b] - ya));
    Eigen::Matrix<double, 3, 6> B = Eigen::Matrix<double, 3, 6>::Zero();
    for (int k = 0; k < 3; ++k) {
      const int p = v[(k + 1) % 3], q = v[(k + 2) % 3];
      const double gx = (s.y[2 * p] - s.y[2 * q]) / (2 * area), gy = (s.x[2 * q] - s.x[2 * p]) / (2 * area);
      B(0, 2 * k) = gx, B(1, 2 * k + 1) = gy, B(2, 2 * k) = gy, B(2, 2 * k + 1) = gx;
    }
    const Eigen::Matrix<double, 6, 6> Ke = std::abs(area) * B.transpose() * D * B;
    for (int k = 0; k < 6; ++k)
      for (int l = 0; l < 6; ++l) entries.emplace_back(2 * v[k / 2] + k % 2, 2 * v[l / 2] + l % 2, Ke(k, l));
  };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) triangle(id(i, j), id(i + 1, j), id(i + 1, j + 1)), triangle(id(i, j), id(i + 1, j + 1), id(i, j + 1));
  s.K.edit().resize(2 * nodes, 2 * nodes);
  s.K.edit().setFromTriplets(entries.begin(), entries.end());
  s.f = Vec::Zero(2 * nodes);
  for (int i = 0; i <= nx; ++i) {
    s.dirichlet_dofs.insert(s.dirichlet_dofs.end(), {2 * id(i, ny), 2 * id(i, ny) + 1});
    s.dirichlet_values.insert(s.dirichlet_values.end(), {drag, push});
  }
  return s;
}

}  // namespace ffeti
