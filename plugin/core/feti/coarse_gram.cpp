#include "feti/coarse_gram.h"

#include "factor/semidefinite_kernel.h"
#include "factor/upper_gram.h"
#include "feti/held_bytes.h"

#include <stdexcept>
#include <utility>
#include <vector>

namespace ffeti {
namespace {

/// The most contact modes for which S_X is kept dense: 288 MB, a Cholesky factor in ~6 s here.
constexpr size_t kDenseSchurLimit = 6000;
/// The fewest rigid modes for which the contact-last layout is used: below it a separate sparse
/// factor of each G_X G_X' takes milliseconds, and GG' keeps CHOLMOD's own choice of factor.
constexpr Eigen::Index kContactLastFrom = 3000;
/// Pivots (or Ritz values) below this share of the largest diagonal entry count as zero in a
/// null-space search.
constexpr double kSingular = 1e-10;
/// RankDecision::factor_first trusts a factor whose (min diag L / max diag L)^2 exceeds this.
constexpr double kTrustedFactor = 1e-12;

double reciprocal_condition(const Eigen::LLT<Eigen::MatrixXd>& llt) {
  const Eigen::VectorXd d = llt.matrixLLT().diagonal();
  if (d.size() == 0) return 1.0;
  const double ratio = d.minCoeff() / d.maxCoeff();
  return ratio * ratio;
}

/// G_X G_X' factorized on its own: regular, or its null space and a regular principal block
/// (its rows of the last pivots deleted, semidefinite_kernel.h) solved instead.
class SparseGram final : public PartialGram {
 public:
  SparseGram(const CoarseGram::RowMatrix& GX, RankDecision rank) {
    const Eigen::SparseMatrix<double> upper = upper_gram(GX);
    // (A = 0, a body of one subdomain whose modes meet no free column, is singular without a try.)
    if (rank == RankDecision::factor_first && upper.nonZeros() > 0 &&
        factor_.factorize(SparseMatrix(upper.transpose())) < 0 && factor_.reciprocal_condition() > kTrustedFactor)
      return;
    const SparseMatrix whole = upper.selfadjointView<Eigen::Upper>();
    SemidefiniteKernel null_space = semidefinite_kernel(whole, kSingular);
    kernel_ = std::move(null_space.basis);
    const Eigen::Index r = whole.rows();
    std::vector<char> kept(static_cast<size_t>(r), 1);
    for (int i : null_space.deleted_rows) kept[static_cast<size_t>(i)] = 0;
    std::vector<Eigen::Triplet<double, int>> selection;
    for (Eigen::Index i = 0, column = 0; i < r; ++i)
      if (kept[static_cast<size_t>(i)]) selection.emplace_back(static_cast<int>(i), static_cast<int>(column++), 1.0);
    keep_.resize(r, static_cast<Eigen::Index>(selection.size()));
    keep_.setFromTriplets(selection.begin(), selection.end());
    if (keep_.cols() > 0 && factor_.factorize(SparseMatrix(keep_.transpose() * whole * keep_)) >= 0)
      throw std::runtime_error("coarse problem: a Gram matrix restricted to its pivots is singular");
  }

  const Vec& solve(const Vec& y) const override {
    if (keep_.rows() == 0) {  // regular, trusted without a search
      factor_.solve(y, solution_);
      return solution_;
    }
    solution_.setZero(y.size());
    if (keep_.cols() > 0) {
      kept_rhs_.noalias() = keep_.transpose() * y;
      factor_.solve(kept_rhs_, kept_solution_);
      solution_.noalias() = keep_ * kept_solution_;
    }
    remove_kernel(solution_);
    return solution_;
  }

 private:
  CoarseGram::RowMatrix keep_;  // r x rank: selects the kept rows (after a search; empty when none ran)
  CholmodFactor factor_{FactorKind::automatic, InterfaceOrdering::fill_reducing, FactorOf::coarse_problem};
  mutable Vec kept_rhs_, kept_solution_, solution_;
};

}  // namespace

/// G_X G_X' from the factor of GG' with the contact modes last and a dense factor of S_X
/// (coarse_gram.h). Singular S_X (a floating body none of whose kept columns holds it):
/// S_X + s QQ', Q an orthonormal basis of Ker S_X, equal to S_X on its range and regular.
class SchurGram final : public PartialGram {
 public:
  SchurGram(const CoarseGram& gram, Eigen::MatrixXd S, RankDecision rank) : gram_(gram) {
    if (rank == RankDecision::factor_first) {
      llt_.compute(S);
      if (llt_.info() == Eigen::Success && reciprocal_condition(llt_) > kTrustedFactor) return;
    }
    const Eigen::MatrixXd Q = semidefinite_kernel_by_iteration(S, kSingular).basis;
    if (Q.cols() > 0) S.noalias() += S.diagonal().maxCoeff() * Q * Q.transpose();
    llt_.compute(S);
    if (llt_.info() != Eigen::Success)
      throw std::runtime_error("coarse problem: the contact modes' Schur complement is singular beyond its null space");
    if (Q.cols() == 0) return;
    // Ker(G_X G_X') = P'L^{-T} [0; L_CC' Q]: the block elimination's backward half.
    const Eigen::Index r = gram.G().rows(), c = Q.rows();
    Eigen::MatrixXd W(r, Q.cols());
    Vec padded = Vec::Zero(r), x;
    for (Eigen::Index k = 0; k < Q.cols(); ++k) {
      padded.tail(c).noalias() = gram.trailing_.triangularView<Eigen::Lower>().transpose() * Q.col(k);
      gram.factor_.backward(padded, x);
      W.col(k) = x;
    }
    kernel_ = orthonormal_columns(W);
  }

  const Vec& solve(const Vec& y) const override {
    const Eigen::MatrixXd& L_CC = gram_.trailing_;
    const Eigen::Index c = L_CC.rows();
    gram_.factor_.forward(y, eliminated_);  // [z_I; L_CC^{-1} z_C]
    contact_.noalias() = L_CC.triangularView<Eigen::Lower>() * eliminated_.tail(c);  // z_C
    llt_.solveInPlace(contact_);                                                     // S_X^{-1} z_C
    eliminated_.tail(c).noalias() = L_CC.triangularView<Eigen::Lower>().transpose() * contact_;
    gram_.factor_.backward(eliminated_, solution_);
    remove_kernel(solution_);
    return solution_;
  }

 private:
  const CoarseGram& gram_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  mutable Vec eliminated_, contact_, solution_;
};

CoarseGram::CoarseGram(const RowMatrix& G, int first_bounded, const Eigen::SparseMatrix<double>& upper,
                       GramLayout layout)
    : G_(G), first_bounded_(first_bounded) {
  std::vector<int> contact;
  for (Eigen::Index i = 0; i < G.rows(); ++i)
    for (RowMatrix::InnerIterator it(G, i); it; ++it)
      if (it.col() >= first_bounded) {
        contact.push_back(static_cast<int>(i));
        break;
      }
  contact_last_ = layout == GramLayout::contact_last ||
                  (layout == GramLayout::automatic && G.rows() >= kContactLastFrom && contact.size() <= kDenseSchurLimit);
  const SparseMatrix lower(upper.transpose());  // CHOLMOD reads the lower triangle
  if (!contact_last_) {
    factored_ = factor_.factorize(lower) < 0;
    return;
  }
  contact_modes_ = std::move(contact);
  factored_ = factor_.factorize_with_last(lower, contact_modes_) < 0;
  if (!factored_) return;
  trailing_ = factor_.trailing_block();
  Eigen::MatrixXd lower_schur = Eigen::MatrixXd::Zero(trailing_.rows(), trailing_.rows());
  lower_schur.selfadjointView<Eigen::Lower>().rankUpdate(trailing_);  // one triangle of L_CC L_CC'
  schur_ = lower_schur.selfadjointView<Eigen::Lower>();
}

std::unique_ptr<PartialGram> CoarseGram::over_columns(const Vec& kept, RankDecision rank) const {
  if (!contact_last_) {
    RowMatrix GX = G_ * kept.asDiagonal();  // the dropped columns pruned, not kept as zeros
    GX.prune(0.0);
    return std::make_unique<SparseGram>(GX, rank);
  }
  // S_X = S - U_C U_C', U_C: the dropped columns on the rows of C.
  std::vector<Eigen::Triplet<double, int>> dropped;
  for (size_t k = 0; k < contact_modes_.size(); ++k)
    for (RowMatrix::InnerIterator it(G_, contact_modes_[k]); it; ++it)
      if (it.col() >= first_bounded_ && kept[it.col()] == 0)
        dropped.emplace_back(static_cast<int>(k), static_cast<int>(it.col()), it.value());
  Eigen::MatrixXd S = schur_;
  if (!dropped.empty()) {
    Eigen::SparseMatrix<double> U(static_cast<Eigen::Index>(contact_modes_.size()), G_.cols());
    U.setFromTriplets(dropped.begin(), dropped.end());
    S -= Eigen::MatrixXd(U * U.transpose());
  }
  return std::make_unique<SchurGram>(*this, std::move(S), rank);
}

double CoarseGram::held_bytes() const {
  return factor_.factor_bytes() + dense_bytes(trailing_) + dense_bytes(schur_) + vector_bytes(contact_modes_);
}

}  // namespace ffeti
