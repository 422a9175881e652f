#include "feti/coulomb_newton.h"

#include "qp/gmres.h"

#include <Eigen/SparseLU>

#include <algorithm>
#include <cmath>
#include <vector>

namespace ffeti {
namespace {

/// Which rows a step solves for and how the slipping pairs follow their normal rows.
struct ActiveSets {
  std::vector<char> closed;       ///< per contact row (index from equality_rows)
  std::vector<char> sticks;       ///< per friction pair (index t / tangent_directions)
  std::vector<double> direction;  ///< per friction row: s of a slipping pair (unit)
  std::vector<double> ratio;      ///< per friction pair: mu lambda_n / |tau| of a slipping pair (<= 1)
  bool operator==(const ActiveSets& o) const { return closed == o.closed && sticks == o.sticks; }
};

/// A step's unknowns y and its equations: lambda = T y (each unknown a column of (row,
/// coefficient) entries), the equations W'(P F lambda - P d + G'alpha) + beta y = 0 (each a
/// test of (row, coefficient) entries). Ordinary unknowns are one row's multiplier (equality
/// rows, closed contact rows, the friction rows of sticking pairs); a closed row whose pair
/// slips carries mu lambda_n s on its friction rows. In 3D a slipping pair also has the
/// component of lambda_t across its direction, e'lambda_t, whose equation is Coulomb's law
/// linearized round the last iterate: e'grad_t + beta e'lambda_t = 0, beta = (1 - rho) / (rho c)
/// with rho = mu lambda_n / |tau| (semismooth Newton; 0 = 0 across the direction in a plane).
class StepMap {
 public:
  using Entries = std::vector<std::pair<int, double>>;
  StepMap(const Constraints& c, const ActiveSets& sets, double weight) {
    std::vector<int> column_of(static_cast<size_t>(c.rows()), -1);
    const auto add = [&](int row) {
      column_of[static_cast<size_t>(row)] = size();
      columns_.push_back({{row, 1.0}});
      tests_.push_back({{row, 1.0}});
      beta_.push_back(0.0);
    };
    for (int r = 0; r < c.equality_rows; ++r) add(r);
    for (int i = 0; i < c.contact_rows(); ++i)
      if (sets.closed[static_cast<size_t>(i)]) add(c.equality_rows + i);
    const int d = c.tangent_directions;
    for (int t = 0; t < c.friction_rows; t += d) {
      const int normal = c.normal_row[static_cast<size_t>(t)], row = c.first_friction_row() + t;
      if (!sets.closed[static_cast<size_t>(normal - c.equality_rows)]) continue;
      if (sets.sticks[static_cast<size_t>(t / d)]) {
        for (int k = 0; k < d; ++k) add(row + k);
        continue;
      }
      const double mu = c.coulomb_coefficient[static_cast<size_t>(t)];
      for (int k = 0; k < d; ++k)
        columns_[static_cast<size_t>(column_of[static_cast<size_t>(normal)])].push_back(
            {row + k, mu * sets.direction[static_cast<size_t>(t + k)]});
      if (d == 2) {  // across the direction: e = (-s2, s1)
        const Entries across = {{row, -sets.direction[static_cast<size_t>(t + 1)]},
                                {row + 1, sets.direction[static_cast<size_t>(t)]}};
        columns_.push_back(across);
        tests_.push_back(across);
        const double rho = sets.ratio[static_cast<size_t>(t / d)];
        beta_.push_back(rho > 0 && weight > 0 ? (1 - rho) / (rho * weight) : 0.0);
      }
    }
  }
  int size() const { return static_cast<int>(columns_.size()); }
  const Entries& column(int j) const { return columns_[static_cast<size_t>(j)]; }
  const Entries& test(int j) const { return tests_[static_cast<size_t>(j)]; }
  Eigen::Map<const Vec> betas() const { return {beta_.data(), static_cast<Eigen::Index>(beta_.size())}; }

  Vec lambda(const Vec& y, int rows) const {  // T y
    Vec l = Vec::Zero(rows);
    for (int j = 0; j < size(); ++j)
      for (const auto& [row, a] : column(j)) l[row] += a * y[j];
    return l;
  }
  Vec embed(const Vec& z, int rows) const {  // W z
    Vec v = Vec::Zero(rows);
    for (int j = 0; j < size(); ++j)
      for (const auto& [row, a] : test(j)) v[row] += a * z[j];
    return v;
  }
  Vec restrict(const Vec& v) const {  // W'v
    Vec y = Vec::Zero(size());
    for (int j = 0; j < size(); ++j)
      for (const auto& [row, a] : test(j)) y[j] += a * v[row];
    return y;
  }

 private:
  std::vector<Entries> columns_, tests_;
  std::vector<double> beta_;
};

/// The next sets from lambda and the gradient of the Lagrangian at it (the gap on contact
/// rows, minus the slip on friction rows), by the complementarity functions with weight c:
/// closed where lambda_n - c grad_n > 0; of a closed row's pair, tau = lambda_t - c grad_t
/// slips where ||tau|| reaches mu lambda_n (within 1e-10: a Tresca solution puts a slipping
/// pair on its bound to rounding), along tau, rho = mu lambda_n / ||tau||. With c = 0, the
/// sets of a Tresca solution: rows with a force closed, pairs at the bound slipping along it.
ActiveSets next_sets(const Constraints& c, const Vec& lambda, const Vec& gradient, double weight) {
  ActiveSets sets;
  sets.closed.assign(static_cast<size_t>(c.contact_rows()), 0);
  for (int i = 0; i < c.contact_rows(); ++i) {
    const int row = c.equality_rows + i;
    sets.closed[static_cast<size_t>(i)] = lambda[row] - weight * gradient[row] > 0;
  }
  const size_t pairs = static_cast<size_t>(c.friction_rows / std::max(1, c.tangent_directions));
  sets.sticks.assign(pairs, 1);
  sets.ratio.assign(pairs, 1.0);
  sets.direction.assign(static_cast<size_t>(c.friction_rows), 0.0);
  for (int t = 0; t < c.friction_rows; t += c.tangent_directions) {
    const int row = c.first_friction_row() + t;
    const double g = c.coulomb_coefficient[static_cast<size_t>(t)] * std::max(lambda[c.normal_row[static_cast<size_t>(t)]], 0.0);
    const Vec trial = lambda.segment(row, c.tangent_directions) - weight * gradient.segment(row, c.tangent_directions);
    const double norm = trial.norm();
    if (norm >= g * (1 - 1e-10) && norm > 0) {
      sets.sticks[static_cast<size_t>(t / c.tangent_directions)] = 0;
      sets.ratio[static_cast<size_t>(t / c.tangent_directions)] = std::min(1.0, g / norm);
      for (int d = 0; d < c.tangent_directions; ++d) sets.direction[static_cast<size_t>(t + d)] = trial[d] / norm;
    }
  }
  return sets;
}

/// (CD)^{-1} for the coarse matrix C D (k x k, sparse: a rigid mode meets the rows of its
/// subdomain only), by a sparse LU factorization; nothing where k = 0. Singular where some
/// rigid mode meets no unknown (a body held along a tangent by slipping rows alone).
class CoarseSolve {
 public:
  explicit CoarseSolve(const SparseMatrix& CD) : empty_(CD.rows() == 0) {
    if (empty_) return;
    lu_.analyzePattern(CD);
    lu_.factorize(CD);
  }
  bool singular() const { return !empty_ && lu_.info() != Eigen::Success; }
  Vec operator()(const Vec& v) const { return empty_ ? v : Vec(lu_.solve(v)); }

 private:
  bool empty_;
  Eigen::SparseLU<SparseMatrix> lu_;
};

/// A step's linear solve reduces its residual by this factor while the sets move: it only has
/// to tell the next sets (1e-2 and 1e-3 cost 14 to 50 % more on the onset pulls, 0.2 and 0.5
/// more in 3D: docs/log.md, 2026-12-08) ...
constexpr double kLooseReduction = 0.1;
/// ... once they repeat, by this factor times the slip directions' last turn (an inexact
/// Newton step's forcing term), and to kFinalTolerance tol once the turn is below
/// kLooseReduction times it.
constexpr double kForcing = 0.1;
/// The last solve's residual, relative to ||W'P d||: the fixed point's Tresca solve at tol then
/// gives back the bounds within tol (at tol itself, the error of lambda a few times tol, it
/// took one or two more Tresca solves: 2752-3419 multiplications on the onset pulls against
/// 2213).
constexpr double kFinalTolerance = 0.1;
/// GMRES applications per step at most (a step whose system is far from its solution gives
/// way to the next sets), its restart length, and Newton steps at most.
constexpr int kStepApplications = 100, kRestart = 40, kMaxSteps = 30;

/// A step's residual reduction from the sets' change and the directions' last turn.
double next_reduction(bool sets_repeat, double turned, double tol) {
  if (!sets_repeat) return std::max(tol, kLooseReduction);
  if (turned <= kForcing * kLooseReduction) return tol;
  return std::clamp(kForcing * turned, tol, kLooseReduction);
}

}  // namespace

CoulombNewtonResult coulomb_newton(const DualSystem& dual, const DualData& data, const Vec& start, double tol,
                                   qp::Budget& budget) {
  const Constraints& c = dual.constraints();
  const CoarseSpace* coarse = dual.coarse() && !dual.coarse()->empty() ? dual.coarse() : nullptr;
  CoulombNewtonResult result;
  result.lambda = start;
  Vec scratch(c.rows());
  const auto PF = [&](const Vec& x, Vec& y) {  // P F x: one application of F
    dual.F().apply(x, scratch);
    ++result.hessian;
    if (coarse) coarse->project(scratch, y);
    else y = scratch;
  };
  Vec Pd = data.b;  // P d, from b = P(d - F lambda~)
  if (coarse) {
    Vec t(c.rows());
    PF(data.lambda_tilde, t);
    Pd += t;
  }
  const SparseMatrix G = coarse ? SparseMatrix(coarse->G()) : SparseMatrix(0, c.rows());
  const Eigen::Index k = G.rows();
  const LinearOperator M = dual.preconditioner_operator();
  ActiveSets sets = next_sets(c, start, Vec::Zero(c.rows()), 0.0);
  std::vector<ActiveSets> seen;
  double weight = 0, reduction = std::max(tol, kLooseReduction);
  for (int step = 0; step < kMaxSteps && budget.remaining() > result.hessian + 2; ++step) {
    ++result.steps;
    const StepMap T(c, sets, weight);
    const int m = T.size();
    // C = G T, D = W'G' (k x m, m x k): the balance of the step's unknowns, and where the
    // rigid modes' multipliers act in its equations.
    std::vector<Eigen::Triplet<double>> C_entries, D_entries;
    for (int j = 0; j < m; ++j) {
      for (const auto& [row, a] : T.column(j))
        for (SparseMatrix::InnerIterator it(G, row); it; ++it) C_entries.emplace_back(static_cast<int>(it.row()), j, a * it.value());
      for (const auto& [row, a] : T.test(j))
        for (SparseMatrix::InnerIterator it(G, row); it; ++it) D_entries.emplace_back(j, static_cast<int>(it.row()), a * it.value());
    }
    SparseMatrix C(k, m), D(m, k);
    C.setFromTriplets(C_entries.begin(), C_entries.end());
    D.setFromTriplets(D_entries.begin(), D_entries.end());
    const CoarseSolve coarse_solve(SparseMatrix(C * D));
    if (coarse_solve.singular()) break;  // the fixed point goes on
    const auto Pi = [&](const Vec& v) -> Vec { return k ? Vec(v - D * coarse_solve(C * v)) : v; };
    Vec full(c.rows()), applied(c.rows());
    const auto A = [&](const Vec& z, Vec& Az) {  // W'P F T z + beta z
      PF(T.lambda(z, c.rows()), full);
      Az = T.restrict(full) + (T.betas().array() * z.array()).matrix();
    };
    const auto precondition = [&](const Vec& z) -> Vec {  // Pi W'M W Pi, M the lumped preconditioner
      if (!M) return z;
      M(T.embed(Pi(z), c.rows()), applied);
      ++result.preconditioner;
      return Pi(T.restrict(applied));
    };
    Vec Az(m);  // operator_of_step's product, reused by every GMRES iteration
    const LinearOperator operator_of_step = [&](const Vec& z, Vec& out) {  // Pi A Pi M~, right-preconditioned
      A(Pi(precondition(z)), Az);
      out = Pi(Az);
    };
    // From the last iterate's coordinates, balanced (C y = e) along D.
    Vec y = T.restrict(result.lambda);
    if (k) y += D * coarse_solve(data.e - C * y);
    Vec Ay(m);
    A(y, Ay);
    const Vec rhs = Pi(T.restrict(Pd) - Ay);
    const double rhs_norm = rhs.norm();
    const double target = reduction > tol ? reduction * rhs_norm : kFinalTolerance * tol * T.restrict(Pd).norm();
    qp::GmresResult solved;
    solved.converged = rhs_norm <= target;
    if (!solved.converged) {
      Vec w = Vec::Zero(m);
      const int left = budget.remaining() - result.hessian - 1;
      solved = qp::gmres(operator_of_step, rhs, w, target / rhs_norm, std::max(1, std::min(kStepApplications, left)),
                         kRestart);
      y += Pi(precondition(w));
    }
    result.lambda = T.lambda(y, c.rows());
    // The Lagrangian's gradient at the new lambda: P F lambda - P d + G'alpha, alpha from the
    // step's equations (D alpha = their residual).
    Vec PFl(c.rows());
    PF(result.lambda, PFl);
    Vec gradient = PFl - Pd;
    if (k) gradient -= G.transpose() * coarse_solve(C * (T.restrict(gradient) + (T.betas().array() * y.array()).matrix()));
    if (weight == 0) {  // c ~ 1/||F||: the Rayleigh quotient of the first step's lambda
      const double curvature = result.lambda.dot(PFl);
      weight = curvature > 0 ? result.lambda.squaredNorm() / curvature : 1.0;
    }
    const ActiveSets next = next_sets(c, result.lambda, gradient, weight);
    double turned = 0;
    for (size_t r = 0; r < next.direction.size(); ++r)
      turned = std::max(turned, std::abs(next.direction[r] - sets.direction[r]));
    const bool repeat = next == sets;
    // Sets seen before, not the last: the iteration cycles (near the onset of sliding a stick
    // zone of a node or two went in and out): given up, the fixed point goes on.
    bool cycles = false;
    if (!repeat)
      for (const ActiveSets& earlier : seen) cycles = cycles || earlier == next;
    if (cycles) break;
    seen.push_back(sets);
    const bool final_solve = reduction <= tol;
    if (final_solve && !solved.converged) break;  // tol below what GMRES reaches: the fixed point reports it
    reduction = next_reduction(repeat, turned, tol);
    sets = next;
    if (repeat && turned <= tol && solved.converged && final_solve) {
      result.converged = true;
      break;
    }
  }
  budget.charge(result.hessian);
  return result;
}

}  // namespace ffeti
