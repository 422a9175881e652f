#include "feti/dirichlet_preconditioner.h"

#include "feti/dual_operator.h"
#include "factor/shared_factors.h"
#include "base/errors.h"
#include "base/parallel_for.h"
#include "base/stopwatch.h"

#include <string>

namespace ffeti {
namespace {

/// The rows and columns `rows` x `cols` of K.
SparseMatrix submatrix(const SparseMatrix& K, const std::vector<int>& rows, const std::vector<int>& cols) {
  std::vector<int> row_position(static_cast<size_t>(K.rows()), -1), column_position(static_cast<size_t>(K.cols()), -1);
  for (size_t k = 0; k < rows.size(); ++k) row_position[static_cast<size_t>(rows[k])] = static_cast<int>(k);
  for (size_t k = 0; k < cols.size(); ++k) column_position[static_cast<size_t>(cols[k])] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int j = 0; j < K.outerSize(); ++j) {
    if (column_position[static_cast<size_t>(j)] < 0) continue;
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (row_position[static_cast<size_t>(it.row())] >= 0)
        entries.emplace_back(row_position[static_cast<size_t>(it.row())], column_position[static_cast<size_t>(j)],
                             it.value());
  }
  SparseMatrix block(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
  block.setFromTriplets(entries.begin(), entries.end());
  block.makeCompressed();
  return block;
}

/// B B' over all rows (entries of the same (subdomain, dof) are the same column of B).
SparseMatrix row_gram(const Constraints& c) {
  // Columns numbered in order of first appearance, looked up per subdomain in a table over
  // its dofs (a map of a million (subdomain, dof) keys took 0.3 s).
  std::vector<std::vector<int>> column;  // [subdomain][dof] -> column of B, -1: none yet
  for (const ConstraintEntry& entry : c.entries) {
    if (entry.subdomain >= static_cast<int>(column.size())) column.resize(static_cast<size_t>(entry.subdomain) + 1);
    auto& of_subdomain = column[static_cast<size_t>(entry.subdomain)];
    if (entry.dof >= static_cast<int>(of_subdomain.size())) of_subdomain.resize(static_cast<size_t>(entry.dof) + 1, -1);
  }
  int columns = 0;
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(c.entries.size());
  for (int r = 0; r < c.rows(); ++r)
    for (int e = c.row_start[static_cast<size_t>(r)]; e < c.row_start[static_cast<size_t>(r) + 1]; ++e) {
      const ConstraintEntry& entry = c.entries[static_cast<size_t>(e)];
      int& at = column[static_cast<size_t>(entry.subdomain)][static_cast<size_t>(entry.dof)];
      if (at < 0) at = columns++;
      entries.emplace_back(r, at, entry.coefficient);
    }
  SparseMatrix B(c.rows(), columns);
  B.setFromTriplets(entries.begin(), entries.end());
  SparseMatrix gram = B * SparseMatrix(B.transpose());
  gram.makeCompressed();
  return gram;
}

}  // namespace

/// S_s of one subdomain on its constrained dofs.
struct DirichletPreconditioner::Block {
  std::vector<int> boundary, interior;
  SparseMatrix Kbb, Kib;
  std::shared_ptr<const CholmodFactor> Kii;  // shared by subdomains of equal K_ii
  mutable CholmodSolveWorkspace workspace;   // this subdomain's solves of Kii
  mutable Vec gathered, xb, t, ti, yb, full;  // buffers of apply()
};

DirichletPreconditioner::DirichletPreconditioner(const std::vector<const SparseMatrix*>& operator_matrices,
                                                 const std::vector<LocalConstraints>& local,
                                                 const std::vector<int>& global_ids, const Constraints& constraints,
                                                 const SubdomainSum& sum, int threads, bool lumped,
                                                 bool share_factors)
    : local_(local), sum_(sum), threads_(resolve_thread_count(threads)) {
  // B has full row rank, so B B' is positive definite (block diagonal: rows meet only at
  // the nodes they share).
  if (constraints.rows() > 0 && (row_gram_.compute(row_gram(constraints)), row_gram_.info() != Eigen::Success))
    throw InputError("constraints: B B' is not positive definite (Dirichlet preconditioner)");
  blocks_.resize(local.size());
  results_.resize(local.size());
  const int count = static_cast<int>(local.size());
  std::vector<SparseMatrix> interior_blocks(local.size());  // K_ii, compared by reference in `shared`
  SharedFactors shared;                                      // declared after them: destroyed first
  parallel_for_each(count, threads_, [&](int s) {  // an error leaves the threads' region first
    const auto k = static_cast<size_t>(s);
    auto block = std::make_unique<Block>();
    const SparseMatrix& K = *operator_matrices[k];
    std::vector<char> constrained(static_cast<size_t>(K.rows()), 0);
    for (int j = 0; j < local[k].B.outerSize(); ++j)
      if (SparseMatrix::InnerIterator(local[k].B, j)) constrained[static_cast<size_t>(j)] = 1;
    for (int i = 0; i < K.rows(); ++i) (constrained[static_cast<size_t>(i)] ? block->boundary : block->interior).push_back(i);
    block->Kbb = submatrix(K, block->boundary, block->boundary);
    if (lumped) block->interior.clear();  // S_s ~ K_bb: the K_ii correction is what it leaves out
    block->Kib = submatrix(K, block->interior, block->boundary);
    // K_ii is K with every constrained dof fixed: regular whenever some dof is constrained.
    if (!block->interior.empty()) {
      interior_blocks[k] = submatrix(K, block->interior, block->interior);
      bool built = false;
      const auto build = [&] {
        built = true;
        auto factor = std::make_shared<CholmodFactor>();
        FactorOutcome outcome;
        outcome.failed = factor->factorize(interior_blocks[k]);
        outcome.factor = std::move(factor);
        return outcome;
      };
      const FactorOutcome outcome = share_factors ? shared.obtain(interior_blocks[k], {}, {}, build) : build();
      if (!share_factors || !built) interior_blocks[k] = SparseMatrix();  // only a builder's is compared later
      if (outcome.failed >= 0)
        throw InputError("K[" + std::to_string(global_ids[k]) + "]: its interior block is not positive definite "
                         "(Dirichlet preconditioner)");
      block->Kii = outcome.factor;
    }
    blocks_[k] = std::move(block);
  });
}

DirichletPreconditioner::~DirichletPreconditioner() = default;

void DirichletPreconditioner::apply(const Vec& x, Vec& y) const {
  Stopwatch clock;
  scaled_ = row_gram_.solve(x);  // (B B')^{-1} x
  // A failure (a K_ii solve out of memory) reaches every rank before the sum below.
  parallel_for_each_on_every_rank(sum_.communicator(), static_cast<int>(local_.size()), threads_, [&](int s) {
    const auto k = static_cast<size_t>(s);
    const LocalConstraints& L = local_[k];
    if (L.rows.empty()) return;
    Block& b = *blocks_[k];
    b.gathered.resize(static_cast<Eigen::Index>(L.rows.size()));
    for (size_t r = 0; r < L.rows.size(); ++r) b.gathered[static_cast<Eigen::Index>(r)] = scaled_[L.rows[r]];
    b.full.noalias() = L.B.transpose() * b.gathered;
    b.xb.resize(static_cast<Eigen::Index>(b.boundary.size()));
    for (size_t i = 0; i < b.boundary.size(); ++i) b.xb[static_cast<Eigen::Index>(i)] = b.full[b.boundary[i]];
    b.yb.noalias() = b.Kbb * b.xb;  // S x_b = K_bb x_b - K_bi K_ii^{-1} K_ib x_b
    if (!b.interior.empty()) {
      b.t.noalias() = b.Kib * b.xb;
      b.Kii->solve(b.t, b.ti, b.workspace);
      b.yb.noalias() -= b.Kib.transpose() * b.ti;
    }
    b.full.setZero();
    for (size_t i = 0; i < b.boundary.size(); ++i) b.full[b.boundary[i]] = b.yb[static_cast<Eigen::Index>(i)];
    results_[k].noalias() = L.B * b.full;
  });
  flat_.clear();
  for (size_t k = 0; k < local_.size(); ++k)
    flat_.insert(flat_.end(), results_[k].data(), results_[k].data() + results_[k].size());
  sum_.sum(flat_, summed_);
  y = row_gram_.solve(summed_);
  application_seconds_ += clock.seconds();
}

}  // namespace ffeti
