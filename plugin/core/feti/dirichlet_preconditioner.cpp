#include "feti/dirichlet_preconditioner.h"

#include "feti/dual_operator.h"
#include "feti/held_bytes.h"
#include "factor/lower_triangle.h"
#include "factor/shared_factors.h"
#include "base/errors.h"
#include "base/parallel_for.h"
#include "base/stopwatch.h"

#include <exception>
#include <map>
#include <string>
#include <unordered_set>

namespace ffeti {
namespace {

/// The rows `rows` x the columns `cols` of the symmetric K, from its lower triangle (an entry
/// below the diagonal stands for its mirror above it too; the upper triangle, where K is
/// given in full, is skipped).
SparseMatrix symmetric_block(const SparseMatrix& K, const std::vector<int>& rows, const std::vector<int>& cols) {
  SparseMatrix block(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
  if (rows.empty() || cols.empty()) return block;  // the lumped preconditioner's K_ib: no pass over K
  std::vector<int> row_position(static_cast<size_t>(K.rows()), -1), column_position(static_cast<size_t>(K.cols()), -1);
  for (size_t k = 0; k < rows.size(); ++k) row_position[static_cast<size_t>(rows[k])] = static_cast<int>(k);
  for (size_t k = 0; k < cols.size(); ++k) column_position[static_cast<size_t>(cols[k])] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double, int>> entries;
  const auto add = [&](int row, int column, double value) {
    if (row_position[static_cast<size_t>(row)] >= 0 && column_position[static_cast<size_t>(column)] >= 0)
      entries.emplace_back(row_position[static_cast<size_t>(row)], column_position[static_cast<size_t>(column)], value);
  };
  for (int j = 0; j < K.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(K, j); it; ++it) {
      if (it.row() < j) continue;
      add(it.row(), j, it.value());
      if (it.row() != j) add(j, it.row(), it.value());
    }
  block.setFromTriplets(entries.begin(), entries.end());
  block.makeCompressed();
  return block;
}

/// B W B' over all rows (entries of the same (subdomain, dof) are the same column of B), W
/// the diagonal of `weight` per entry (all ones: B B').
SparseMatrix row_gram(const Constraints& c, const std::vector<double>& weight) {
  // Columns numbered in order of first appearance, looked up per subdomain in a table over
  // its dofs (a map of a million (subdomain, dof) keys took 0.3 s).
  std::vector<std::vector<int>> column;  // [subdomain][dof] -> column of B, -1: none yet
  for (const ConstraintEntry& entry : c.entries) {
    if (entry.subdomain >= static_cast<int>(column.size())) column.resize(static_cast<size_t>(entry.subdomain) + 1);
    auto& of_subdomain = column[static_cast<size_t>(entry.subdomain)];
    if (entry.dof >= static_cast<int>(of_subdomain.size())) of_subdomain.resize(static_cast<size_t>(entry.dof) + 1, -1);
  }
  int columns = 0;
  std::vector<double> column_weight;
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(c.entries.size());
  for (int r = 0; r < c.rows(); ++r)
    for (int e = c.row_start[static_cast<size_t>(r)]; e < c.row_start[static_cast<size_t>(r) + 1]; ++e) {
      const ConstraintEntry& entry = c.entries[static_cast<size_t>(e)];
      int& at = column[static_cast<size_t>(entry.subdomain)][static_cast<size_t>(entry.dof)];
      if (at < 0) {
        at = columns++;
        column_weight.push_back(weight[static_cast<size_t>(e)]);
      }
      entries.emplace_back(r, at, entry.coefficient);
    }
  SparseMatrix B(c.rows(), columns);
  B.setFromTriplets(entries.begin(), entries.end());
  const Vec w = Eigen::Map<const Vec>(column_weight.data(), columns);
  SparseMatrix gram = B * w.asDiagonal() * SparseMatrix(B.transpose());
  gram.makeCompressed();
  return gram;
}

/// The weight of each constraint entry: 1, or with stiffness scaling 1 / K_s(dof, dof) of
/// its subdomain, found on the rank that holds it and gathered (every rank builds B D^-1 B').
std::vector<double> entry_weights(const std::vector<const SparseMatrix*>& operator_matrices,
                                  const std::vector<int>& global_ids, const Constraints& c,
                                  const Communicator& comm, InterfaceScaling scaling) {
  std::vector<double> weight(c.entries.size(), 1.0);
  if (scaling == InterfaceScaling::multiplicity) return weight;
  std::map<int, size_t> local_of;
  for (size_t k = 0; k < global_ids.size(); ++k) local_of[global_ids[k]] = k;
  std::vector<double> mine;  // (entry, weight) pairs of this rank's subdomains
  std::exception_ptr failure;  // thrown on every rank before the gather, none left waiting in it
  try {
    for (size_t e = 0; e < c.entries.size(); ++e) {
      const auto at = local_of.find(c.entries[e].subdomain);
      if (at == local_of.end()) continue;
      const double diagonal = operator_matrices[at->second]->coeff(c.entries[e].dof, c.entries[e].dof);
      if (!(diagonal > 0))
        throw InputError("K[" + std::to_string(c.entries[e].subdomain) + "]: diagonal entry " +
                         std::to_string(c.entries[e].dof) + " is not positive (scaling = \"stiffness\")");
      mine.insert(mine.end(), {static_cast<double>(e), 1.0 / diagonal});
    }
  } catch (...) {
    failure = std::current_exception();
  }
  rethrow_on_every_rank(comm, failure);
  const std::vector<double> all = comm.allgather(mine);
  for (size_t t = 0; t + 1 < all.size(); t += 2) weight[static_cast<size_t>(all[t])] = all[t + 1];
  return weight;
}

}  // namespace

/// S_s of one subdomain on its constrained dofs.
struct DirichletPreconditioner::Block {
  std::vector<int> boundary, interior;
  SparseMatrix Kbb, Kib;  // K_bb: its lower triangle
  std::shared_ptr<const CholmodFactor> Kii;  // shared by subdomains of equal K_ii
  mutable CholmodSolveWorkspace workspace;   // this subdomain's solves of Kii
  Vec weight;                                 // D^{-1} per boundary dof (empty: multiplicity scaling)
  mutable Vec gathered, xb, t, ti, yb, full;  // buffers of apply()
};

DirichletPreconditioner::DirichletPreconditioner(const std::vector<const SparseMatrix*>& operator_matrices,
                                                 const std::vector<LocalConstraints>& local,
                                                 const std::vector<int>& global_ids, const Constraints& constraints,
                                                 const SubdomainSum& sum, int threads, bool lumped,
                                                 bool share_factors, InterfaceScaling scaling)
    : local_(local), sum_(sum), threads_(resolve_thread_count(threads)) {
  // B has full row rank, so B D^-1 B' is positive definite (block diagonal: rows meet only
  // at the nodes they share).
  const std::vector<double> weight =
      entry_weights(operator_matrices, global_ids, constraints, sum.communicator(), scaling);
  if (constraints.rows() > 0 && (row_gram_.compute(row_gram(constraints, weight)), row_gram_.info() != Eigen::Success))
    throw InputError("constraints: B D^-1 B' is not positive definite (Dirichlet preconditioner; D = I but with "
                     "scaling = \"stiffness\")");
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
    block->Kbb = lower_block(K, block->boundary);
    if (scaling == InterfaceScaling::stiffness) {  // positive: entry_weights checked it
      block->weight.resize(static_cast<Eigen::Index>(block->boundary.size()));
      for (size_t i = 0; i < block->boundary.size(); ++i)
        block->weight[static_cast<Eigen::Index>(i)] = 1.0 / K.coeff(block->boundary[i], block->boundary[i]);
    }
    if (lumped) block->interior.clear();  // S_s ~ K_bb: the K_ii correction is what it leaves out
    block->Kib = symmetric_block(K, block->interior, block->boundary);
    // K_ii is K with every constrained dof fixed: regular whenever some dof is constrained.
    if (!block->interior.empty()) {
      interior_blocks[k] = lower_block(K, block->interior);
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
  scaled_ = row_gram_.solve(x);  // A x, A = (B D^-1 B')^{-1} (D = I: multiplicity scaling)
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
    if (b.weight.size()) b.xb.array() *= b.weight.array();  // D^-1 on both sides of S
    b.yb.noalias() = b.Kbb.selfadjointView<Eigen::Lower>() * b.xb;  // S x_b = K_bb x_b - K_bi K_ii^{-1} K_ib x_b
    if (!b.interior.empty()) {
      b.t.noalias() = b.Kib * b.xb;
      b.Kii->solve(b.t, b.ti, b.workspace);
      b.yb.noalias() -= b.Kib.transpose() * b.ti;
    }
    if (b.weight.size()) b.yb.array() *= b.weight.array();
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

double DirichletPreconditioner::held_bytes() const {
  double bytes = dense_bytes(scaled_) + dense_bytes(summed_) + vector_bytes(flat_);
  if (row_gram_.rows() > 0) bytes += sparse_bytes(row_gram_.matrixL().nestedExpression());  // factored only with rows
  for (const Vec& r : results_) bytes += dense_bytes(r);
  std::unordered_set<const CholmodFactor*> counted;
  for (const auto& b : blocks_) {
    bytes += vector_bytes(b->boundary) + vector_bytes(b->interior) + sparse_bytes(b->Kbb) + sparse_bytes(b->Kib);
    for (const Vec* v : {&b->weight, &b->gathered, &b->xb, &b->t, &b->ti, &b->yb, &b->full}) bytes += dense_bytes(*v);
    if (b->Kii && counted.insert(b->Kii.get()).second) bytes += b->Kii->factor_bytes();
  }
  return bytes;
}

}  // namespace ffeti
