#include "feti/dual_operator.h"

#include "base/stopwatch.h"
#include "feti/held_bytes.h"

#include <algorithm>

namespace ffeti {
namespace {

/// B with its columns renumbered to positions in `interface` (sorted dofs), or an empty
/// matrix when B touches a dof outside it (rows built after the factorization, e.g. a
/// sensitivity problem's).
SparseMatrix columns_on_interface(const SparseMatrix& B, const std::vector<int>& interface) {
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int j = 0; j < B.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(B, j); it; ++it) {
      const auto at = std::lower_bound(interface.begin(), interface.end(), j);
      if (at == interface.end() || *at != j) return {};
      entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(at - interface.begin()), it.value());
    }
  SparseMatrix on_interface(B.rows(), static_cast<Eigen::Index>(interface.size()));
  on_interface.setFromTriplets(entries.begin(), entries.end());
  on_interface.makeCompressed();
  return on_interface;
}

}  // namespace

DualOperator::DualOperator(const SubdomainList& subdomains, const std::vector<LocalConstraints>& local,
                           const SubdomainSum& sum, int rows, int threads)
    : subdomains_(subdomains), local_(local), sum_(sum), rows_(rows), threads_(resolve_thread_count(threads)) {
  const size_t count = subdomains.size();
  gathered_.resize(count), local_rhs_.resize(count), interface_B_.resize(count);
  interface_rhs_.resize(count), interface_solution_.resize(count);
  local_solution_.resize(count), local_result_.resize(count);
  for (size_t s = 0; s < count; ++s) {
    gathered_[s].resize(static_cast<Eigen::Index>(local[s].rows.size()));
    local_rhs_[s].resize(subdomains[s]->size());
    local_solution_[s].resize(subdomains[s]->size());
    local_result_[s].resize(static_cast<Eigen::Index>(local[s].rows.size()));
    if (subdomains[s]->solves_on_interface() && !local[s].rows.empty())
      interface_B_[s] = columns_on_interface(local[s].B, subdomains[s]->interface());
    interface_rhs_[s].resize(interface_B_[s].cols()), interface_solution_[s].resize(interface_B_[s].cols());
  }
}

template <class Body>
void DualOperator::on_subdomains(Body&& body) const {
  parallel_for_each_on_every_rank(sum_.communicator(), static_cast<int>(subdomains_.size()), threads_,
                                  [&](int s) { body(static_cast<size_t>(s)); });
}

double DualOperator::apply_on_subdomain(size_t i, const Vec& x, Eigen::Ref<Vec> result) const {
  for (size_t k = 0; k < local_[i].rows.size(); ++k)
    gathered_[i][static_cast<Eigen::Index>(k)] = x[local_[i].rows[k]];
  const bool on_interface = interface_B_[i].rows() > 0;
  const SparseMatrix& B = on_interface ? interface_B_[i] : local_[i].B;
  Vec& rhs = on_interface ? interface_rhs_[i] : local_rhs_[i];
  Vec& solution = on_interface ? interface_solution_[i] : local_solution_[i];
  rhs.noalias() = B.transpose() * gathered_[i];  // B_s' x
  const Stopwatch solve_clock;
  if (on_interface)
    subdomains_[i]->apply_pseudo_inverse_on_interface(rhs, solution);
  else
    subdomains_[i]->apply_pseudo_inverse(rhs, solution);
  const double seconds = solve_clock.seconds();
  result.noalias() = B * solution;  // B_s K_s^+ B_s' x
  return seconds;
}

void DualOperator::apply(const Vec& x, Vec& y) const {
  Stopwatch clock;
  std::vector<double>& solves = subdomain_solve_seconds_;
  solves.assign(subdomains_.size(), 0.0);  // no allocation after the first application
  on_subdomains([&](size_t i) {
    if (!local_[i].rows.empty()) solves[i] = apply_on_subdomain(i, x, local_result_[i]);
  });
  sum_local_results(y);
  application_seconds_ += clock.seconds();
  for (double seconds : solves) solve_seconds_ += seconds;
  ++applications_;
}

void DualOperator::apply(const Eigen::MatrixXd& x, Eigen::MatrixXd& y) const {
  Stopwatch clock;
  block_gathered_.resize(subdomains_.size()), block_rhs_.resize(subdomains_.size());
  block_solution_.resize(subdomains_.size()), block_result_.resize(subdomains_.size());
  std::vector<double>& solves = subdomain_solve_seconds_;
  solves.assign(subdomains_.size(), 0.0);  // no allocation after the first application
  on_subdomains([&](size_t i) {
    if (local_[i].rows.empty()) return;
    Eigen::MatrixXd& gathered = block_gathered_[i];
    gathered.resize(static_cast<Eigen::Index>(local_[i].rows.size()), x.cols());
    for (size_t k = 0; k < local_[i].rows.size(); ++k)
      gathered.row(static_cast<Eigen::Index>(k)) = x.row(local_[i].rows[k]);
    // An explicit block is read once for all columns. Otherwise a block solve reads the
    // whole factor once for all columns, interface solves read the interface block once per
    // column: the cheaper of the two.
    const Subdomain& subdomain = *subdomains_[i];
    const bool on_interface =
        interface_B_[i].rows() > 0 &&
        (subdomain.has_explicit_block() ||
         static_cast<double>(x.cols()) * subdomain.operator_bytes() < subdomain.factor_bytes());
    const SparseMatrix& B = on_interface ? interface_B_[i] : local_[i].B;
    block_rhs_[i].noalias() = B.transpose() * gathered;
    const Stopwatch solve_clock;
    if (on_interface) {
      subdomain.apply_pseudo_inverse_on_interface(block_rhs_[i], block_solution_[i]);
    } else {
      subdomain.apply_pseudo_inverse(block_rhs_[i], block_solution_[i]);
    }
    solves[i] = solve_clock.seconds();
    block_result_[i].noalias() = B * block_solution_[i];
  });
  sum_block_results(x.cols(), y);
  application_seconds_ += clock.seconds();
  for (double seconds : solves) solve_seconds_ += seconds;
  applications_ += x.cols();
}

void DualOperator::apply_B_pseudo_inverse(const std::vector<Vec>& v, Vec& y) const {
  on_subdomains([&](size_t i) {
    if (!local_[i].rows.empty()) B_pseudo_inverse_on_subdomain(i, v[i], local_result_[i]);
  });
  sum_local_results(y);
}

void DualOperator::B_pseudo_inverse_on_subdomain(size_t i, const Vec& v, Eigen::Ref<Vec> result) const {
  // K^+ 0 = 0 exactly: an unloaded subdomain (most of a large scene's) solves nothing.
  if (!(v.array() != 0).any()) {
    result.setZero();
    return;
  }
  subdomains_[i]->apply_pseudo_inverse(v, local_solution_[i]);
  result.noalias() = local_[i].B * local_solution_[i];
}

void DualOperator::apply_B_pseudo_inverse_and_F(const std::vector<Vec>& v, const Vec& x, Vec& Bv, Vec& Fx) const {
  block_result_.resize(subdomains_.size());
  on_subdomains([&](size_t i) {
    if (local_[i].rows.empty()) return;
    Eigen::MatrixXd& result = block_result_[i];
    result.resize(static_cast<Eigen::Index>(local_[i].rows.size()), 2);
    B_pseudo_inverse_on_subdomain(i, v[i], result.col(0));
    apply_on_subdomain(i, x, result.col(1));
  });
  Eigen::MatrixXd both;
  sum_block_results(2, both);
  Bv = both.col(0);
  Fx = both.col(1);
}

void DualOperator::apply_B(const std::vector<Vec>& u, Vec& y) const {
  for (size_t s = 0; s < subdomains_.size(); ++s)
    if (!local_[s].rows.empty()) local_result_[s].noalias() = local_[s].B * u[s];
  sum_local_results(y);
}

void DualOperator::pseudo_inverse_of_residual(const std::vector<Vec>& v, const Vec& x,
                                              std::vector<Vec>& w) const {
  w.resize(subdomains_.size());
  on_subdomains([&](size_t i) {
    Vec rhs = v[i];
    for (size_t k = 0; k < local_[i].rows.size(); ++k)
      gathered_[i][static_cast<Eigen::Index>(k)] = x[local_[i].rows[k]];
    if (!local_[i].rows.empty()) rhs.noalias() -= local_[i].B.transpose() * gathered_[i];
    subdomains_[i]->apply_pseudo_inverse(rhs, w[i]);
  });
}

double DualOperator::local_transpose_squared_norm(const Vec& x) const {
  double squares = 0;
  for (size_t i = 0; i < subdomains_.size(); ++i) {
    if (local_[i].rows.empty()) continue;
    Vec xs(static_cast<Eigen::Index>(local_[i].rows.size()));
    for (size_t k = 0; k < local_[i].rows.size(); ++k) xs[static_cast<Eigen::Index>(k)] = x[local_[i].rows[k]];
    squares += (local_[i].B.transpose() * xs).squaredNorm();
  }
  return squares;
}

void DualOperator::sum_block_results(Eigen::Index cols, Eigen::MatrixXd& y) const {
  y.resize(rows_, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    flat_.clear();
    for (size_t s = 0; s < subdomains_.size(); ++s)
      if (!local_[s].rows.empty())
        flat_.insert(flat_.end(), block_result_[s].col(j).data(), block_result_[s].col(j).data() + block_result_[s].rows());
    sum_.sum(flat_, column_);
    y.col(j) = column_;
  }
}

void DualOperator::sum_local_results(Vec& y) const {
  flat_.clear();
  for (size_t s = 0; s < subdomains_.size(); ++s)
    flat_.insert(flat_.end(), local_result_[s].data(), local_result_[s].data() + local_result_[s].size());
  sum_.sum(flat_, y);
}

double DualOperator::held_bytes() const {
  double bytes = dense_bytes(column_);
  for (const SparseMatrix& B : interface_B_) bytes += sparse_bytes(B);
  for (const auto* vectors :
       {&gathered_, &local_rhs_, &local_solution_, &local_result_, &interface_rhs_, &interface_solution_})
    for (const Vec& v : *vectors) bytes += dense_bytes(v);
  for (const auto* blocks : {&block_gathered_, &block_rhs_, &block_solution_, &block_result_})
    for (const Eigen::MatrixXd& m : *blocks) bytes += dense_bytes(m);
  return bytes;
}

}  // namespace ffeti
