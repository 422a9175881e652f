#include "disc_reference.h"

#include "qp_test_problems.h"

#include <cmath>
#include <random>

namespace ffeti::test {
namespace {

/// A pair this close to its circle (relative) counts as on it in the KKT check.
constexpr double kOnCircle = 1e-9;

}  // namespace

DiscQp random_disc_qp(double condition, unsigned seed) {
  const int n = 15;
  DiscQp qp;
  qp.H = random_spd(n, condition, seed);
  std::mt19937 random(seed + 31);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  qp.b.resize(n);
  for (int i = 0; i < n; ++i) qp.b[i] = 3 * condition * unit(random);
  const Vec unconstrained = qp.H.ldlt().solve(qp.b);
  Vec lower(3), centre(10), radius(5);
  for (int i = 0; i < 3; ++i) lower[i] = unconstrained[2 + i] + (i == 0 ? 0.5 : -1.0) * std::abs(unconstrained[2 + i]);
  for (int j = 0; j < 5; ++j) {
    centre.segment<2>(2 * j) = Eigen::Vector2d(unit(random), unit(random));
    const double distance = (unconstrained.segment<2>(5 + 2 * j) - centre.segment<2>(2 * j)).norm();
    radius[j] = j == 0 ? 0.0 : j == 1 ? 10 * distance + 1 : (0.2 + 0.2 * j) * distance;
  }
  qp.free = 2;
  qp.lower = lower;
  qp.centre = centre;
  qp.radius = radius;
  return qp;
}

qp::ConstraintSet DiscQp::set() const {
  qp::ConstraintSet set;
  set.add_free(free);
  set.add_half_line(lower);
  set.add_disc(centre, radius);
  return set;
}

Vec project_onto_set(const Vec& x, const DiscQp& qp) {
  Vec y = x;
  for (Eigen::Index k = 0; k < qp.lower.size(); ++k) y[qp.free + k] = std::max(y[qp.free + k], qp.lower[k]);
  for (Eigen::Index j = 0; j < qp.radius.size(); ++j) {
    const Eigen::Index i = qp.first_disc() + 2 * j;
    const Eigen::Vector2d c = qp.centre.segment<2>(2 * j), d = y.segment<2>(i) - c;
    if (d.norm() > qp.radius[j]) y.segment<2>(i) = c + d * (qp.radius[j] / d.norm());
  }
  return y;
}

Vec accelerated_projected_gradient(const DiscQp& qp) {
  const Eigen::Index n = qp.b.size();
  const double step = 1.0 / Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(qp.H).eigenvalues().maxCoeff();
  Eigen::MatrixXd kernel_projector = Eigen::MatrixXd::Identity(n, n);  // onto Ker C (C only on free components)
  if (qp.C.rows() > 0) kernel_projector -= qp.C.transpose() * (qp.C * qp.C.transpose()).ldlt().solve(qp.C);
  const auto project = [&](const Vec& v) { return project_onto_set(kernel_projector * v, qp); };
  Vec x = project(Vec::Zero(n)), y = x, previous;
  double t = 1;
  for (int k = 0; k < 2000000; ++k) {
    previous = x;
    const Vec gradient = qp.H * y - qp.b;
    x = project(y - step * gradient);
    if ((x - previous).norm() <= 1e-15 * (1 + x.norm())) break;
    if (gradient.dot(x - previous) > 0) {  // restart: the momentum points uphill
      t = 1;
      y = x;
      continue;
    }
    const double t_next = 0.5 * (1 + std::sqrt(1 + 4 * t * t));
    y = x + ((t - 1) / t_next) * (x - previous);
    t = t_next;
  }
  return x;
}

double kkt_violation(const DiscQp& qp, const Vec& x) {
  const Vec g0 = qp.H * x - qp.b;
  std::vector<Eigen::Index> unheld;  // components no bound or circle holds
  double violation = 0;
  const auto worse = [&](double v) { violation = std::max(violation, v / qp.b.norm()); };
  for (Eigen::Index i = 0; i < qp.free; ++i) unheld.push_back(i);
  for (Eigen::Index k = 0; k < qp.lower.size(); ++k) {
    const Eigen::Index i = qp.free + k;
    worse(std::max(qp.lower[k] - x[i], 0.0));
    if (x[i] > qp.lower[k] + kOnCircle * (1 + std::abs(qp.lower[k]))) unheld.push_back(i);
  }
  for (Eigen::Index j = 0; j < qp.radius.size(); ++j) {
    const Eigen::Index i = qp.first_disc() + 2 * j;
    const double r = qp.radius[j], norm = (x.segment<2>(i) - qp.centre.segment<2>(2 * j)).norm();
    worse(std::max(norm - r, 0.0));
    if (norm < r * (1 - kOnCircle)) unheld.insert(unheld.end(), {i, i + 1});
  }
  // C'mu from the unheld components' stationarity (least squares), then the full gradient.
  Vec g = g0;
  if (qp.C.rows() > 0) {
    Eigen::MatrixXd Ct(unheld.size(), qp.C.rows());
    Vec rhs(unheld.size());
    for (size_t a = 0; a < unheld.size(); ++a) Ct.row(a) = qp.C.col(unheld[a]).transpose(), rhs[a] = -g0[unheld[a]];
    g += qp.C.transpose() * Ct.colPivHouseholderQr().solve(rhs);
    worse((qp.C * x).norm() * qp.H.norm());  // in units of b
  }
  for (const Eigen::Index i : unheld) worse(std::abs(g[i]));
  for (Eigen::Index k = 0; k < qp.lower.size(); ++k) worse(std::max(-g[qp.free + k], 0.0));
  for (Eigen::Index j = 0; j < qp.radius.size(); ++j) {
    const Eigen::Index i = qp.first_disc() + 2 * j;
    const Eigen::Vector2d d = x.segment<2>(i) - qp.centre.segment<2>(2 * j), gi = g.segment<2>(i);
    if (qp.radius[j] == 0 || d.norm() < qp.radius[j] * (1 - kOnCircle)) continue;
    const Eigen::Vector2d normal = d / d.norm();
    worse((gi - normal.dot(gi) * normal).norm());  // g_pair = -lambda n ...
    worse(std::max(normal.dot(gi), 0.0));          // ... with lambda >= 0
  }
  return violation;
}

}  // namespace ffeti::test
