#include "feti/coarse_space.h"

#include "feti/held_bytes.h"
#include "factor/upper_gram.h"

#include "base/errors.h"
#include "base/parallel_for.h"
#include "factor/semidefinite_kernel.h"
#include "qp/mprgp.h"
#include "qp/norm_estimate.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

namespace ffeti {

void CoarseSpace::assemble_local_rows(const std::vector<Eigen::MatrixXd>& BR, const std::vector<LocalConstraints>& local,
                                      const std::vector<int>& global_ids, int rows) {
  // One rank holds every subdomain, in ascending global order: G's rows are its kernel
  // vectors in that order, filled on threads with no packing (0.1 s at 6144 rigid modes).
  std::vector<int> first_row(BR.size() + 1, 0);  // G's row of (k, 0)
  for (size_t k = 0; k < BR.size(); ++k) first_row[k + 1] = first_row[k] + static_cast<int>(BR[k].cols());
  const int g_rows = first_row.back();
  std::vector<int> row_nonzeros(static_cast<size_t>(g_rows));
  parallel_for_each(static_cast<int>(BR.size()), 0, [&](int k) {
    const auto kk = static_cast<size_t>(k);
    for (Eigen::Index j = 0; j < BR[kk].cols(); ++j)
      row_nonzeros[static_cast<size_t>(first_row[kk] + j)] = static_cast<int>((BR[kk].col(j).array() != 0).count());
  });
  G_.resize(g_rows, rows);
  long nonzeros = 0;
  for (int n : row_nonzeros) nonzeros += n;
  G_.resizeNonZeros(nonzeros);
  G_.outerIndexPtr()[0] = 0;
  for (int r = 0; r < g_rows; ++r) G_.outerIndexPtr()[r + 1] = G_.outerIndexPtr()[r] + row_nonzeros[static_cast<size_t>(r)];
  parallel_for_each(static_cast<int>(BR.size()), 0, [&](int k) {
    const auto kk = static_cast<size_t>(k);
    for (Eigen::Index j = 0; j < BR[kk].cols(); ++j) {
      int at = G_.outerIndexPtr()[first_row[kk] + j];
      for (size_t i = 0; i < local[kk].rows.size(); ++i)
        if (const double value = BR[kk](static_cast<Eigen::Index>(i), j); value != 0)
          G_.innerIndexPtr()[at] = local[kk].rows[i], G_.valuePtr()[at++] = value;
    }
  });
  for (size_t k = 0; k < BR.size(); ++k)
    for (int j = 0; j < static_cast<int>(BR[k].cols()); ++j) {
      owner_.push_back({global_ids[k], j});
      local_rows_.emplace_back(first_row[k] + j, static_cast<int>(k));
    }
}

void CoarseSpace::assemble_gathered_rows(const std::vector<Eigen::MatrixXd>& BR, const std::vector<LocalConstraints>& local,
                                         const std::vector<int>& global_ids, int rows, int subdomain_count,
                                         const Communicator& comm) {
  // Each rank packs, per kernel vector of its floating subdomains, (s, j, nonzeros, then
  // row/value pairs of the nonzeros of B_s R_s e_j); every rank unpacks all of them in the
  // same order, straight into G's compressed rows (the rows of a block ascend).
  size_t most = 0;  // the packed size if no entry of B_s R_s is zero
  for (size_t k = 0; k < BR.size(); ++k) most += static_cast<size_t>(BR[k].cols()) * (3 + 2 * local[k].rows.size());
  std::vector<double> packed;
  packed.reserve(most);
  for (size_t k = 0; k < BR.size(); ++k)
    for (Eigen::Index j = 0; j < BR[k].cols(); ++j) {
      packed.insert(packed.end(), {double(global_ids[k]), double(j), 0.0});
      const size_t count_at = packed.size() - 1;
      for (size_t i = 0; i < local[k].rows.size(); ++i)
        if (const double value = BR[k](static_cast<Eigen::Index>(i), j); value != 0)
          packed.insert(packed.end(), {double(local[k].rows[i]), value});
      packed[count_at] = static_cast<double>((packed.size() - count_at - 1) / 2);
    }
  const std::vector<double> all = comm.allgather(packed);
  struct Block {
    std::pair<int, int> owner;  // (s, j)
    size_t offset;              // of its (s, j, nonzeros) header in `all`
  };
  std::vector<Block> blocks;
  for (size_t p = 0; p < all.size(); p += 3 + 2 * static_cast<size_t>(all[p + 2]))
    blocks.push_back({{static_cast<int>(all[p]), static_cast<int>(all[p + 1])}, p});
  std::sort(blocks.begin(), blocks.end(), [](const Block& a, const Block& b) { return a.owner < b.owner; });
  std::vector<int> local_index(static_cast<size_t>(subdomain_count), -1);
  for (size_t k = 0; k < global_ids.size(); ++k) local_index[static_cast<size_t>(global_ids[k])] = static_cast<int>(k);
  long nonzeros = 0;
  for (const Block& b : blocks) nonzeros += static_cast<long>(all[b.offset + 2]);
  G_.resize(static_cast<Eigen::Index>(blocks.size()), rows);
  G_.resizeNonZeros(nonzeros);
  G_.outerIndexPtr()[0] = 0;
  for (size_t g_row = 0; g_row < blocks.size(); ++g_row) {
    const auto [s, j] = blocks[g_row].owner;
    owner_.push_back({s, j});
    if (local_index[static_cast<size_t>(s)] >= 0) local_rows_.emplace_back(static_cast<int>(g_row), local_index[static_cast<size_t>(s)]);
    const size_t p = blocks[g_row].offset;
    const int start = G_.outerIndexPtr()[g_row];
    const auto count = static_cast<int>(all[p + 2]);
    for (int i = 0; i < count; ++i) {
      G_.innerIndexPtr()[start + i] = static_cast<int>(all[p + 3 + 2 * static_cast<size_t>(i)]);
      G_.valuePtr()[start + i] = all[p + 4 + 2 * static_cast<size_t>(i)];
    }
    G_.outerIndexPtr()[g_row + 1] = start + count;
  }
}

CoarseSpace::CoarseSpace(const SubdomainList& subdomains, const std::vector<LocalConstraints>& local,
                         const std::vector<int>& global_ids, int rows, int first_bounded,
                         const std::vector<int>& bodies, const Communicator& comm, GramLayout layout)
    : subdomains_(subdomains), comm_(comm) {
  std::vector<Eigen::MatrixXd> BR(subdomains.size());
  parallel_for_each(static_cast<int>(subdomains.size()), 0, [&](int k) {
    const auto s = static_cast<size_t>(k);
    if (subdomains[s]->floating()) BR[s] = local[s].B * subdomains[s]->kernel();
  });
  if (comm.size() == 1)
    assemble_local_rows(BR, local, global_ids, rows);
  else
    assemble_gathered_rows(BR, local, global_ids, rows, static_cast<int>(bodies.size()), comm);
  if (owner_.empty()) return;

  const Eigen::SparseMatrix<double> GGt_upper = upper_gram(G_);
  gram_ = std::make_unique<CoarseGram>(G_, first_bounded, GGt_upper, layout);
  const bool factored = gram_->factored();
  // Regularity is judged on the sparse factor: its diagonal's cheap condition estimate
  // clears the regular cases; only when it is in doubt does the null space of GG' decide
  // and name the bodies of a singular GG' (semidefinite_kernel: sparse above 2500 rows, as a
  // dense GG' of 8192 floating 3D subdomains takes 19 GB).
  if (factored && gram_->reciprocal_condition() > 1e-10) return;  // (min diag L / max diag L)^2
  const SemidefiniteKernel kernel =
      semidefinite_kernel(Eigen::SparseMatrix<double>(GGt_upper.selfadjointView<Eigen::Upper>()), 1e-12);
  if (factored && kernel.basis.cols() == 0) return;

  // Singular GG': some combination of rigid modes meets no constraint. Name the bodies.
  std::set<int> unrestrained;
  for (Eigen::Index k = 0; k < kernel.basis.cols(); ++k)
    for (Eigen::Index i = 0; i < kernel.basis.rows(); ++i)
      if (std::abs(kernel.basis(i, k)) > 1e-6)
        unrestrained.insert(bodies[static_cast<size_t>(owner_[static_cast<size_t>(i)].first)]);
  std::string names;
  for (int b : unrestrained) names += (names.empty() ? "" : ", ") + std::to_string(b);
  throw InputError("body: some rigid body motion of body " + names +
                   " meets no Dirichlet, gluing or contact row (GG' is singular): either the body has no condition "
                   "at all (add a Dirichlet condition or a contact zone), or its conditions leave a motion free, "
                   "e.g. sliding along or turning on its contact surface, which contact rows do not hold (they act "
                   "along their normals only; add Dirichlet conditions on the tangential components)");
}

int CoarseSpace::floating_subdomains() const {
  std::set<int> floating;
  for (const auto& [s, j] : owner_) floating.insert(s);
  return static_cast<int>(floating.size());
}

Vec CoarseSpace::kernel_load(const std::vector<Vec>& f) const {
  std::vector<double> local;  // (row of G, value) pairs of this rank
  for (const auto& [g_row, k] : local_rows_) {
    const int j = owner_[static_cast<size_t>(g_row)].second;
    local.insert(local.end(), {double(g_row), subdomains_[static_cast<size_t>(k)]->kernel().col(j).dot(f[static_cast<size_t>(k)])});
  }
  const std::vector<double> all = comm_.allgather(local);
  Vec e = Vec::Zero(G_.rows());
  for (size_t p = 0; p < all.size(); p += 2) e[static_cast<Eigen::Index>(all[p])] = all[p + 1];
  return e;
}

double CoarseSpace::equilibrium_residual_norm(const Vec& defect) const {
  std::map<int, std::vector<std::pair<int, double>>> by_subdomain;  // local index -> (kernel column, defect)
  for (const auto& [g_row, k] : local_rows_)
    by_subdomain[k].emplace_back(owner_[static_cast<size_t>(g_row)].second, defect[g_row]);
  double squares = 0;
  for (const auto& [k, entries] : by_subdomain) {
    const Subdomain& s = *subdomains_[static_cast<size_t>(k)];
    const Eigen::Index r = s.kernel().cols();
    Vec d = Vec::Zero(r);
    for (const auto& [j, value] : entries) d[j] = value;
    Eigen::MatrixXd RF(r, r);  // R at the fixing dofs
    for (Eigen::Index i = 0; i < r; ++i) RF.row(i) = s.kernel().row(s.fixing()[static_cast<size_t>(i)]);
    squares += RF.transpose().partialPivLu().solve(d).squaredNorm();
  }
  return std::sqrt(comm_.sum(squares));
}

void CoarseSpace::add_kernel_component(const Vec& alpha, std::vector<Vec>& u) const {
  for (const auto& [g_row, k] : local_rows_) {
    const int j = owner_[static_cast<size_t>(g_row)].second;
    u[static_cast<size_t>(k)] += alpha[g_row] * subdomains_[static_cast<size_t>(k)]->kernel().col(j);
  }
}

void CoarseSpace::project_range(const Vec& x, Vec& y) const {
  if (empty()) {
    y.setZero(x.size());
    return;
  }
  coarse_rhs_.noalias() = G_ * x;
  gram_->solve(coarse_rhs_, coarse_solution_);  // (GG')^{-1} G x
  y.noalias() = G_.transpose() * coarse_solution_;
}

void CoarseSpace::project(const Vec& x, Vec& y) const {
  if (empty()) {
    y = x;
    return;
  }
  coarse_rhs_.noalias() = G_ * x;
  gram_->solve(coarse_rhs_, coarse_solution_);
  y = x;
  y.noalias() -= G_.transpose() * coarse_solution_;
}

Vec CoarseSpace::least_norm_solution(const Vec& e) const {
  if (empty()) return Vec::Zero(G_.cols());
  Vec coarse;
  gram_->solve(e, coarse);
  return G_.transpose() * coarse;
}

double CoarseSpace::feasibility_residual(const Vec& e, const qp::ConstraintSet& bounds, double enough) const {
  const double e_norm = e.norm();
  if (empty() || !(e_norm > 0)) return 0.0;
  const Eigen::Index m = G_.cols();
  Vec lambda = least_norm_solution(e);
  if (bounds.contains(lambda)) return 0.0;  // G lambda = e already
  // min 1/2 ||G lambda - e||^2 = 1/2 lambda'G'G lambda - (G'e)'lambda + const, within the bounds.
  Vec Gv;
  qp::Problem distance_qp;
  distance_qp.hessian = [&](const Vec& v, Vec& y) {
    Gv = G_ * v;
    y = G_.transpose() * Gv;  // y = G'G v
  };
  distance_qp.b = G_.transpose() * e;
  distance_qp.hessian_norm = estimate_norm(distance_qp.hessian, m).norm;
  distance_qp.constraints = bounds;
  const double stop_at = 1e-12 * distance_qp.b.norm();
  double distance = -1.0;  // of the last iterate, relative
  // G'G is small (r x m, r the rigid modes): a generous fixed budget, whatever maxit.
  qp::Budget budget(20000);
  const MprgpResult r = mprgp(distance_qp, MprgpSettings{}, lambda, budget, [&](const Vec& x, const Vec&, double gp) {
    distance = (G_ * x - e).norm() / e_norm;
    return distance <= enough || gp <= stop_at;
  });
  return r.status == SolveStatus::converged ? distance : -1.0;
}

double CoarseSpace::held_bytes() const {
  return sparse_bytes(G_) + vector_bytes(owner_) + vector_bytes(local_rows_) + dense_bytes(coarse_rhs_) +
         dense_bytes(coarse_solution_) + (gram_ ? gram_->held_bytes() : 0.0);
}

}  // namespace ffeti
