#include "feti/subdomain.h"

#include "base/errors.h"
#include "base/parallel_for.h"
#include "base/stopwatch.h"
#include "factor/lower_triangle.h"
#include "feti/kernel.h"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace ffeti {
namespace {

/// Below this reciprocal condition estimate a factor that completed counts as singular.
constexpr double kSingularReciprocalCondition = 1e-14;

/// The dofs of 0..n-1 not in `removed` (sorted), in order.
std::vector<int> kept_dofs(Eigen::Index n, const std::vector<int>& removed) {
  std::vector<int> kept;
  kept.reserve(static_cast<size_t>(n) - removed.size());
  size_t next_removed = 0;
  for (int i = 0; i < n; ++i) {
    if (next_removed < removed.size() && removed[next_removed] == i)
      ++next_removed;
    else
      kept.push_back(i);
  }
  return kept;
}

}  // namespace

Subdomain::Subdomain(int index, const SparseMatrix& K, const Eigen::MatrixXd& kernel_candidates,
                     FactorKind factor_kind, InterfaceOrdering ordering, SharedAnalyses* shared,
                     const std::vector<int>& interface, SharedFactors* shared_factors)
    : index_(index), size_(K.rows()), interface_(interface) {
  const std::string name = "K[" + std::to_string(index_) + "]";
  R_ = kernel_in_span(K, kernel_candidates);
  fixing_ = fixing_dofs(R_);
  reduced_to_full_ = kept_dofs(K.rows(), fixing_);
  std::vector<int> reduced_interface;  // reduced_to_full_ is sorted: a binary search per dof
  interface_columns_.assign(interface_.size(), -1);
  for (size_t k = 0; k < interface_.size(); ++k) {
    const auto at = std::lower_bound(reduced_to_full_.begin(), reduced_to_full_.end(), interface_[k]);
    if (at == reduced_to_full_.end() || *at != interface_[k]) continue;  // a fixing dof: K_s^+ is zero there
    interface_kept_.push_back(static_cast<int>(k));
    reduced_interface.push_back(static_cast<int>(at - reduced_to_full_.begin()));
    interface_columns_[k] = reduced_interface.back();
  }
  interface_rhs_.resize(static_cast<Eigen::Index>(reduced_interface.size()));
  const auto kept = static_cast<Eigen::Index>(reduced_to_full_.size());
  reduced_rhs_.resize(kept);
  reduced_solution_.resize(kept);
  const auto build = [&] {  // run by the first subdomain of each set of identical ones
    auto factor = std::make_shared<CholmodFactor>(factor_kind, ordering);
    FactorOutcome outcome;
    outcome.failed = factor->factorize(lower_block(K, reduced_to_full_), shared, reduced_interface);
    // A singular block may factor with a tiny positive pivot instead of failing outright.
    outcome.reciprocal_condition = outcome.failed < 0 ? factor->reciprocal_condition() : 0.0;
    factor_ = factor;
    outcome.factor = std::move(factor);
    if (outcome.failed < 0 && outcome.reciprocal_condition >= kSingularReciprocalCondition)
      outcome.residual = pseudo_inverse_residual(K);
    return outcome;
  };
  const FactorOutcome outcome = shared_factors ? shared_factors->obtain(K, fixing_, interface_, build) : build();
  factor_ = outcome.factor;
  // Some candidate modes outside the kernel of a matrix that is still singular: the modes
  // built from the coordinates do not fit the matrix (Z scaled by 1000 gave this), more
  // likely than a wrong matrix.
  const std::string coordinates_hint =
      R_.cols() > 0 && R_.cols() < kernel_candidates.cols()
          ? " Only " + std::to_string(R_.cols()) + " of the " + std::to_string(kernel_candidates.cols()) +
                " rigid modes built from X, Y, Z and component lie in its kernel: check that the coordinates are "
                "those of this matrix's dofs (not scaled, swapped or another mesh's)."
          : "";
  if (outcome.failed < 0 && outcome.reciprocal_condition < kSingularReciprocalCondition)
    throw InputError(name + ": singular outside its kernel (reciprocal condition estimate " +
                     std::to_string(outcome.reciprocal_condition) + " with kernel dimension " +
                     std::to_string(R_.cols()) +
                     "): the matrix has a kernel outside the candidate rigid modes, e.g. a "
                     "disconnected subdomain mesh or a mechanism." + coordinates_hint);
  if (outcome.failed >= 0)
    throw InputError(name + ": not positive definite outside its kernel (Cholesky pivot " +
                     std::to_string(outcome.failed) + " of " + std::to_string(kept) +
                     " fails; kernel dimension found " + std::to_string(R_.cols()) +
                     "). Is the subdomain mesh connected and the matrix a stiffness matrix?" + coordinates_hint);
  factor_operator_bytes_ = interface_solves() ? factor_->interface_bytes() : factor_->factor_bytes();
  if (!(outcome.residual <= 1e-6))
    throw InputError(name + ": the generalized inverse does not verify (||K K+ K v - K v|| / "
                     "||K v|| = " + std::to_string(outcome.residual) +
                     "): the matrix has a kernel outside the candidate rigid modes");
}

void Subdomain::apply_pseudo_inverse(const Vec& b, Vec& x) const {
  for (size_t k = 0; k < reduced_to_full_.size(); ++k)
    reduced_rhs_[static_cast<Eigen::Index>(k)] = b[reduced_to_full_[k]];
  factor_->solve(reduced_rhs_, reduced_solution_, workspace_);
  x.setZero(size_);
  for (size_t k = 0; k < reduced_to_full_.size(); ++k)
    x[reduced_to_full_[k]] = reduced_solution_[static_cast<Eigen::Index>(k)];
}

void Subdomain::solve_interface_column(Eigen::Ref<const Vec> b, Eigen::Ref<Vec> x) const {
  for (size_t j = 0; j < interface_kept_.size(); ++j)
    interface_rhs_[static_cast<Eigen::Index>(j)] = b[interface_kept_[j]];
  factor_->solve_on_interface(interface_rhs_, interface_solution_, workspace_);
  x.setZero();
  for (size_t j = 0; j < interface_kept_.size(); ++j)
    x[interface_kept_[j]] = interface_solution_[static_cast<Eigen::Index>(j)];
}

void Subdomain::apply_pseudo_inverse_on_interface(const Vec& b, Vec& x) const {
  if (explicit_block_) {
    explicit_block_->apply(b, x);
    return;
  }
  x.resize(static_cast<Eigen::Index>(interface_.size()));
  solve_interface_column(b, x);
}

void Subdomain::apply_pseudo_inverse_on_interface(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) const {
  if (explicit_block_) {
    explicit_block_->apply(b, x);
    return;
  }
  // Column by column through the subdomain's own buffers: no allocation per application.
  x.resize(static_cast<Eigen::Index>(interface_.size()), b.cols());
  for (Eigen::Index j = 0; j < b.cols(); ++j) solve_interface_column(b.col(j), x.col(j));
}

bool Subdomain::form_explicit_block(DualOperatorForm form) {
  if (form == DualOperatorForm::implicit || interface_.empty()) return false;
  const auto t = static_cast<Eigen::Index>(interface_.size());
  const bool from_interface_block = interface_solves() && !supernodal();
  if (form == DualOperatorForm::automatic &&
      !explicit_inverse_pays(packed_symmetric_bytes(t), factor_operator_bytes_, from_interface_block))
    return false;
  explicit_block_ = std::make_shared<const PackedSymmetric>(dense_interface_inverse(*factor_, interface_columns_, workspace_));
  return true;
}

void Subdomain::share_explicit_block(const Subdomain& identical) {
  if (&identical.factor() != &factor())
    throw std::logic_error("Subdomain::share_explicit_block: the subdomains do not share a factor");
  explicit_block_ = identical.explicit_block_;
}

void Subdomain::apply_pseudo_inverse(const Eigen::MatrixXd& b, Eigen::MatrixXd& x) const {
  const auto kept = static_cast<Eigen::Index>(reduced_to_full_.size());
  reduced_block_rhs_.resize(kept, b.cols());
  for (Eigen::Index k = 0; k < kept; ++k) reduced_block_rhs_.row(k) = b.row(reduced_to_full_[static_cast<size_t>(k)]);
  factor_->solve(reduced_block_rhs_, reduced_block_solution_, workspace_);
  x.setZero(size_, b.cols());
  for (Eigen::Index k = 0; k < kept; ++k) x.row(reduced_to_full_[static_cast<size_t>(k)]) = reduced_block_solution_.row(k);
}

double Subdomain::pseudo_inverse_residual(const SparseMatrix& K) const {
  std::mt19937 generator(7u + static_cast<unsigned>(index_));
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Vec v(K.rows());
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = uniform(generator);
  const Vec Kv = K.selfadjointView<Eigen::Lower>() * v;
  Vec z;
  apply_pseudo_inverse(Kv, z);
  const double denominator = Kv.norm();
  return denominator > 0 ? (K.selfadjointView<Eigen::Lower>() * z - Kv).norm() / denominator : 0.0;
}

ExplicitBlocks form_explicit_blocks(SubdomainList& subdomains, DualOperatorForm form, int threads) {
  ExplicitBlocks made;
  if (form == DualOperatorForm::implicit) return made;
  const Stopwatch clock;
  std::unordered_map<const CholmodFactor*, size_t> first;  // each distinct factor's first subdomain
  std::vector<size_t> distinct;
  for (size_t s = 0; s < subdomains.size(); ++s)
    if (first.emplace(&subdomains[s]->factor(), s).second) distinct.push_back(s);
  parallel_for_each(static_cast<int>(distinct.size()), threads,
                    [&](int k) { subdomains[distinct[static_cast<size_t>(k)]]->form_explicit_block(form); });
  for (size_t s = 0; s < subdomains.size(); ++s) {
    const size_t owner = first.at(&subdomains[s]->factor());
    if (owner != s) subdomains[s]->share_explicit_block(*subdomains[owner]);
    made.subdomains += subdomains[s]->has_explicit_block() ? 1 : 0;
  }
  made.seconds = clock.seconds();
  return made;
}

}  // namespace ffeti
