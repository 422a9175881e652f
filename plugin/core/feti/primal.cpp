#include "feti/primal.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace ffeti {
namespace {

double inf_norm(const std::vector<Vec>& u) {
  double value = 0;
  for (const Vec& us : u) value = std::max(value, us.size() ? us.cwiseAbs().maxCoeff() : 0.0);
  return value;
}

double safe_ratio(double a, double b) { return b > 0 ? a / b : a; }

/// The part of the rigid-mode coefficients that no row holding with equality fixes (Z: an
/// orthonormal basis of Ker G_S G_S'), taken from the slipping pairs in three dimensions: a
/// pair at its bound slips along its force, so the slip's component across lambda_t, n's
/// with n the unit normal to lambda_t in the tangent plane, vanishes at the solution. Near
/// the onset of sliding almost every pair slips: one sticking pair leaves the body's turn
/// about the normal free, none leaves its translations free as well, and the least-norm
/// coefficients (no turn) made slips cross their forces: the 3D block pulled at 0.9 mu W kept
/// a complementarity of 0.32 with ||gP|| at 1e-18 and ran to maxit. A change Z beta of the
/// coefficients moves the slips by G'Z beta (G' = BR); beta is the least-squares solution of
/// n's = 0 over the slipping pairs, `slip` the slips with the least-norm coefficients. In a
/// plane problem a slip's direction is its sign: nothing to align (returns 0).
Vec slip_alignment(const CoarseSpace& coarse, const Constraints& constraints, const Vec& lambda, const Vec& slip_bound,
                   const Vec& slip, const Eigen::MatrixXd& Z) {
  if (constraints.tangent_directions != 2 || slip_bound.size() != constraints.friction_rows) return Vec::Zero(Z.rows());
  std::vector<int> slipping;  // the first rows of the pairs at a finite, positive bound
  for (int t = 0; t < constraints.friction_rows; t += 2) {
    const int row = constraints.first_friction_row() + t;
    if (slip_bound[t] > 0 && std::isfinite(slip_bound[t]) && at_slip_bound(constraints, lambda, row, slip_bound[t]))
      slipping.push_back(row);
  }
  if (slipping.empty()) return Vec::Zero(Z.rows());
  const Eigen::MatrixXd GZ = coarse.G().transpose() * Z;  // the slips of the free modes
  Eigen::MatrixXd A(static_cast<Eigen::Index>(slipping.size()), Z.cols());
  Vec r(A.rows());
  for (Eigen::Index k = 0; k < A.rows(); ++k) {
    const int row = slipping[static_cast<size_t>(k)];
    const double norm = tangential_norm(constraints, lambda, row);
    const double n1 = -lambda[row + 1] / norm, n2 = lambda[row] / norm;
    A.row(k) = n1 * GZ.row(row) + n2 * GZ.row(row + 1);
    r[k] = -(n1 * slip[row] + n2 * slip[row + 1]);
  }
  // Rank-revealing: the slips need not fix every free mode (forces all parallel, at the onset
  // itself, leave the translation along them free); such modes keep their least-norm part.
  return Z * A.completeOrthogonalDecomposition().solve(r);
}

}  // namespace

double tangential_norm(const Constraints& constraints, const Vec& lambda, int row) {
  return constraints.tangent_directions == 2 ? std::hypot(lambda[row], lambda[row + 1]) : std::abs(lambda[row]);
}

bool at_slip_bound(const Constraints& constraints, const Vec& lambda, int row, double g) {
  const double norm = tangential_norm(constraints, lambda, row);
  return constraints.tangent_directions == 2 ? norm >= (1 - 1e-12) * g : norm >= g;
}

FrictionResidual friction_residual(const Constraints& constraints, const Vec& lambda, const Vec& gap, int row, double g,
                                   double lambda_scale) {
  const double norm = tangential_norm(constraints, lambda, row);
  const double slip = tangential_norm(constraints, gap, row);
  // -lambda_t s in the plane; in 3D ||lambda_t|| ||s|| - lambda_t.s, zero only when s points along lambda_t.
  const double against = constraints.tangent_directions == 2
                             ? norm * slip - (lambda[row] * gap[row] + lambda[row + 1] * gap[row + 1])
                             : -lambda[row] * gap[row];
  return {norm - g, std::max(std::min(g - norm, lambda_scale) * slip, against)};
}

double friction_force_scale(double lambda_scale, const Vec& slip_bound) {
  if (lambda_scale > 0) return lambda_scale;
  double largest = 0;
  for (Eigen::Index t = 0; t < slip_bound.size(); ++t)
    if (std::isfinite(slip_bound[t])) largest = std::max(largest, slip_bound[t]);
  return largest > 0 ? largest : 1.0;
}

bool holds_with_equality(const Constraints& constraints, const Vec& lambda, const Vec& slip_bound, int row) {
  if (row < constraints.equality_rows) return true;
  const int friction = row - constraints.first_friction_row();
  if (friction < 0) return lambda[row] > 0;
  const int first = row - friction % constraints.tangent_directions;  // the group's first row
  return !at_slip_bound(constraints, lambda, first, slip_bound[friction]);
}

std::vector<Vec> recover_primal(const DualOperator& F, const CoarseSpace* coarse,
                                const Constraints& constraints, const std::vector<Vec>& f,
                                const Vec& c, const Vec& lambda, const Vec& slip_bound) {
  std::vector<Vec> u;
  F.pseudo_inverse_of_residual(f, lambda, u);  // u~ = K^+(f - B'lambda)
  if (!coarse || coarse->empty()) return u;

  const int m = constraints.rows();
  Vec mask = Vec::Zero(m);
  for (int i = 0; i < m; ++i) mask[i] = holds_with_equality(constraints, lambda, slip_bound, i) ? 1.0 : 0.0;
  Vec Bu;
  F.apply_B(u, Bu);
  // alpha from  (G_S G_S') alpha = G_S (c - B u~)_S  over the rows S holding with equality:
  // G_S G_S' couples the rigid modes of neighbouring subdomains only and differs from GG' in
  // contact columns only (coarse_gram.h). Where it is singular (a floating body that no row
  // of S holds) the solution orthogonal to its null space is taken, and the slipping pairs
  // fix what they can of the rest (slip_alignment).
  const Vec residual = (c - Bu).cwiseProduct(mask);
  const std::unique_ptr<PartialGram> gram = coarse->gram().over_columns(mask, RankDecision::factor_first);
  Vec alpha = gram->solve(coarse->G() * residual);
  if (gram->kernel().cols() > 0)
    alpha += slip_alignment(*coarse, constraints, lambda, slip_bound, Bu - c + coarse->G().transpose() * alpha,
                            gram->kernel());
  coarse->add_kernel_component(alpha, u);
  return u;
}

double KktResiduals::max() const {
  return std::max({equilibrium, equality, inequality, dual_feasibility, complementarity});
}

bool KktResiduals::finite() const {
  for (double r : {equilibrium, equality, inequality, dual_feasibility, complementarity})
    if (!std::isfinite(r)) return false;
  return true;
}

KktResiduals kkt_residuals(const std::vector<SubdomainInput>& inputs, const std::vector<Vec>& f, const Vec& c,
                           bool homogeneous_dirichlet, const std::vector<LocalConstraints>& local, const DualOperator& F,
                           const Constraints& constraints, bool dirichlet_eliminated,
                           const std::vector<Vec>& u, const Vec& lambda, const Communicator& comm,
                           const Vec& slip_bound) {
  KktResiduals r;
  const int m = constraints.rows();
  const double u_scale = comm.max(inf_norm(u));
  const double lambda_scale = friction_force_scale(lambda.size() ? lambda.cwiseAbs().maxCoeff() : 0.0,
                                                  constraints.friction_rows ? slip_bound : Vec());

  double residual_sq = 0, load_sq = 0, reaction_sq = 0, dirichlet_violation = 0;
  for (size_t s = 0; s < inputs.size(); ++s) {
    Vec reaction = Vec::Zero(inputs[s].K.rows());  // B_s' lambda
    if (!local[s].rows.empty()) {
      Vec lambda_s(static_cast<Eigen::Index>(local[s].rows.size()));
      for (size_t k = 0; k < local[s].rows.size(); ++k) lambda_s[static_cast<Eigen::Index>(k)] = lambda[local[s].rows[k]];
      reaction = local[s].B.transpose() * lambda_s;
    }
    Vec residual = inputs[s].K.get().selfadjointView<Eigen::Lower>() * u[s] - f[s] + reaction;
    for (size_t k = 0; k < inputs[s].dirichlet_dofs.size(); ++k) {
      const int dof = inputs[s].dirichlet_dofs[k];
      const double g = homogeneous_dirichlet || inputs[s].dirichlet_values.empty() ? 0.0 : inputs[s].dirichlet_values[k];
      dirichlet_violation = std::max(dirichlet_violation, std::abs(u[s][dof] - g));
      if (dirichlet_eliminated) residual[dof] = 0.0;  // the reaction there is not in lambda
    }
    residual_sq += residual.squaredNorm();
    load_sq += f[s].squaredNorm();
    reaction_sq += reaction.squaredNorm();
  }
  residual_sq = comm.sum(residual_sq), load_sq = comm.sum(load_sq), reaction_sq = comm.sum(reaction_sq);
  r.equilibrium = safe_ratio(std::sqrt(residual_sq), std::sqrt(std::max(load_sq, reaction_sq)));

  Vec gap;
  F.apply_B(u, gap);
  gap -= c;
  double equality = comm.max(dirichlet_violation), inequality = 0, negative = 0, complementarity = 0;
  for (int i = 0; i < m; ++i) {
    if (i < constraints.equality_rows) {
      equality = std::max(equality, std::abs(gap[i]));
    } else if (const int t = i - constraints.first_friction_row(); t >= 0) {
      if (t % constraints.tangent_directions) continue;  // the second row of a pair: counted with the first
      const FrictionResidual friction = friction_residual(constraints, lambda, gap, i, slip_bound[t], lambda_scale);
      negative = std::max(negative, friction.excess);
      complementarity = std::max(complementarity, friction.complementarity);
    } else {
      inequality = std::max(inequality, gap[i]);
      negative = std::max(negative, -lambda[i]);
      complementarity = std::max(complementarity, std::abs(lambda[i] * gap[i]));
    }
  }
  r.equality = safe_ratio(equality, u_scale);
  r.inequality = safe_ratio(inequality, u_scale);
  r.dual_feasibility = safe_ratio(negative, lambda_scale);
  r.complementarity = safe_ratio(complementarity, lambda_scale * u_scale);
  return r;
}

double energy(const std::vector<SubdomainInput>& inputs, const std::vector<Vec>& u, const Communicator& comm) {
  double value = 0;
  for (size_t s = 0; s < inputs.size(); ++s)
    value += 0.5 * u[s].dot(inputs[s].K.get().selfadjointView<Eigen::Lower>() * u[s]) - inputs[s].f.dot(u[s]);
  return comm.sum(value);
}

}  // namespace ffeti
