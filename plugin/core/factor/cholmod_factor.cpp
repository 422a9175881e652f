#include "factor/cholmod_factor.h"

#include "factor/cholmod_analysis.h"
#include "factor/supernodal_factorize.h"
#include "factor/supernodal_solve.h"
#include "parallel/process.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <stdexcept>
#include <string>

namespace ffeti {
namespace {

std::atomic<long> numeric_factorizations{0};

/// The most extra factorization flops per factor entry that a pass of the dual operator no
/// longer reads for which `automatic` orders the interface last. Measured on the model
/// problem (docs/log.md, 2026-11-27): simplicial factorization ran at ~2 GFlop/s and the solves
/// read ~13 GB/s per thread, so a multiplication (two passes, 12 bytes an entry) saves about
/// what 3.5 flops per entry cost: at 300 the ordering pays for itself within ~90
/// multiplications, a solve at tight tol or a few solves on one factorization.
constexpr double kExtraFlopsPerSavedEntry = 300;

/// The least share of the fill-reducing factor's entries a pass of F must skip for the
/// interface-last ordering. The large contact zone's subdomains (92 % of their dofs on the
/// interface) skipped 0.3 to 0.9 % of it at no extra flops, and their subset solves took
/// 28.5 against 19.6 us for the whole solve: ~1.45 times per entry read, so below about
/// 1 - 1/1.45 = 0.31 the ordering loses whatever the flops.
constexpr double kLeastSavedShare = 1.0 / 3.0;

/// The error of a failed CHOLMOD solve; memory running out is named as such.
std::runtime_error solve_failure(const cholmod_common& common) {
  if (common.status == CHOLMOD_OUT_OF_MEMORY)
    return std::runtime_error("a subdomain solve ran out of memory (CHOLMOD's solve workspace)");
  return std::runtime_error("CHOLMOD solve failed (status " + std::to_string(common.status) + ")");
}

/// A cholmod_sparse header over Eigen's compressed column storage (no copy).
cholmod_sparse view_lower(const SparseMatrix& A) {
  cholmod_sparse view;
  std::memset(&view, 0, sizeof view);
  view.nrow = static_cast<size_t>(A.rows());
  view.ncol = static_cast<size_t>(A.cols());
  view.nzmax = static_cast<size_t>(A.nonZeros());
  view.p = const_cast<int*>(A.outerIndexPtr());
  view.i = const_cast<int*>(A.innerIndexPtr());
  view.x = const_cast<double*>(A.valuePtr());
  view.stype = -1;  // symmetric, lower triangle stored (upper entries ignored)
  view.itype = CHOLMOD_INT;
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  view.sorted = 1;
  view.packed = 1;
  return view;
}

/// A cholmod_dense header over a column-major block of `rows` x `cols` values (no copy).
cholmod_dense view_columns(const double* values, Eigen::Index rows, Eigen::Index cols) {
  cholmod_dense view;
  std::memset(&view, 0, sizeof view);
  view.nrow = static_cast<size_t>(rows);
  view.ncol = static_cast<size_t>(cols);
  view.nzmax = view.nrow * view.ncol;
  view.d = view.nrow;
  view.x = const_cast<double*>(values);
  view.xtype = CHOLMOD_REAL;
  view.dtype = CHOLMOD_DOUBLE;
  return view;
}

/// CHOLMOD 3's supernodal numeric factorization opens OpenMP regions of its own, of a fixed 4
/// threads (CHOLMOD_OMP_NUM_THREADS), whatever the plugin's thread count. Inside the
/// plugin's loop over subdomains on several threads they are nested, hence serial; on one
/// thread (threads = 1, or the default on a loaded machine) they are not, and their threads
/// spin for cores others hold: 9.1 s instead of 0.9 s (OMP_WAIT_POLICY=passive) for two
/// subdomains of 2187 dofs beside other processes. While it lives, and only where this
/// thread runs alone on one thread, every region it opens runs serially.
class SerialRegionsOnOneThread {
 public:
  SerialRegionsOnOneThread() {
    if (omp_get_active_level() > 0 || omp_get_max_threads() > 1) return;
    previous_ = omp_get_max_active_levels();
    omp_set_max_active_levels(0);
  }
  ~SerialRegionsOnOneThread() {
    if (previous_ >= 0) omp_set_max_active_levels(previous_);
  }
  SerialRegionsOnOneThread(const SerialRegionsOnOneThread&) = delete;
  SerialRegionsOnOneThread& operator=(const SerialRegionsOnOneThread&) = delete;

 private:
  int previous_ = -1;
};

}  // namespace

bool interface_ordering_pays(double fill_entries, double saved_entries, double extra_flops) {
  return saved_entries > 0 && saved_entries >= kLeastSavedShare * fill_entries &&
         extra_flops <= kExtraFlopsPerSavedEntry * saved_entries;
}

CholmodFactor::CholmodFactor(FactorKind kind, InterfaceOrdering ordering, FactorOf of) : ordering_(ordering), of_(of) {
  cholmod_start(&common_);
  common_.print = 0;  // the core never prints; failures are returned as values
  common_.error_handler = nullptr;
  common_.supernodal = kind == FactorKind::simplicial   ? CHOLMOD_SIMPLICIAL
                       : kind == FactorKind::supernodal ? CHOLMOD_SUPERNODAL
                                                        : CHOLMOD_AUTO;
  set_analysis_choices(common_);
}

CholmodFactor::~CholmodFactor() {
  cholmod_free_sparse(&interface_set_, &common_);
  cholmod_free_factor(&factor_, &common_);
  cholmod_finish(&common_);
}

CholmodSolveWorkspace::CholmodSolveWorkspace() {
  cholmod_start(&common_);
  common_.print = 0;
  common_.error_handler = nullptr;
}

CholmodSolveWorkspace::~CholmodSolveWorkspace() {
  for (Buffers* b : {&vector_, &block_, &interface_}) {
    cholmod_free_dense(&b->solution, &common_);
    cholmod_free_dense(&b->y, &common_);
    cholmod_free_dense(&b->e, &common_);
  }
  cholmod_free_dense(&interface_rhs_, &common_);
  cholmod_free_sparse(&reached_, &common_);
  cholmod_finish(&common_);
}

int CholmodFactor::factorize(const SparseMatrix& A, SharedAnalyses* shared, const std::vector<int>& interface) {
  if (A.rows() != A.cols()) throw std::invalid_argument("CholmodFactor: matrix is not square");
  if (!A.isCompressed()) throw std::invalid_argument("CholmodFactor: matrix is not compressed");
  cholmod_sparse view = view_lower(A);
  if (!factor_ || size_ != A.rows()) {
    cholmod_free_factor(&factor_, &common_);
    cholmod_free_sparse(&interface_set_, &common_);
    bool interface_last = false;
    if (shared)
      factor_ = shared->copy(view, common_.supernodal, interface, &common_, &analysis_flops_, &analysis_nonzeros_,
                             &interface_last);
    if (!factor_) {
      factor_ = analyze_fewest_entries(&view, &common_);
      if (!factor_) throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
      analysis_flops_ = common_.fl, analysis_nonzeros_ = common_.lnz;
      if (ordering_ != InterfaceOrdering::fill_reducing && !interface.empty() && !factor_->is_super)
        if (cholmod_factor* constrained = analyze_interface_last(view, interface)) {
          cholmod_free_factor(&factor_, &common_);
          factor_ = constrained, interface_last = true;
          analysis_flops_ = common_.fl, analysis_nonzeros_ = common_.lnz;
        }
      if (shared)
        shared->keep(view, common_.supernodal, interface, interface_last, *factor_, analysis_flops_, analysis_nonzeros_);
    }
    if (interface_last) {
      const size_t n = static_cast<size_t>(A.rows());
      interface_set_ = cholmod_allocate_sparse(n, 1, interface.size(), 1, 1, 0, CHOLMOD_PATTERN, &common_);
      if (!interface_set_) throw std::runtime_error("CHOLMOD allocation failed (out of memory?)");
      static_cast<int*>(interface_set_->p)[0] = 0;
      static_cast<int*>(interface_set_->p)[1] = static_cast<int>(interface.size());
      std::copy(interface.begin(), interface.end(), static_cast<int*>(interface_set_->i));
    }
    size_ = A.rows();
  }
  return factorize_numeric(view);
}

int CholmodFactor::factorize_numeric(cholmod_sparse& view) {
  if (of_ == FactorOf::subdomain) ++numeric_factorizations;
  if (factor_->is_super) {  // CHOLMOD's analysis, Eigen's dense kernels (supernodal_factorize.h)
    if (factor_->xtype == CHOLMOD_PATTERN &&
        !cholmod_change_factor(CHOLMOD_REAL, true, true, true, true, factor_, &common_))
      throw std::runtime_error("CHOLMOD allocation failed (out of memory?)");
    // One thread: Eigen runs a product of more than ~50,000 flops on every OpenMP thread
    // where no parallel region is open (the coarse problem's factor): forking for each small
    // supernode cost ten times the work, and its blocking, hence the rounding, would depend
    // on the thread count (two ranks must give the serial answer to the digit).
    const ThreadLimit one_thread(1);
    if (supernodal_factorize(view, *factor_)) {
      factor_->minor = factor_->n;
      return -1;
    }
    // Not positive definite: CHOLMOD's own factorization names the column, as for any factor.
  }
  {
    const SerialRegionsOnOneThread serial;
    cholmod_factorize(&view, factor_, &common_);
  }
  if (common_.status == CHOLMOD_NOT_POSDEF) return static_cast<int>(factor_->minor);
  if (common_.status == CHOLMOD_OUT_OF_MEMORY) throw std::runtime_error("a factorization ran out of memory (CHOLMOD)");
  if (common_.status < CHOLMOD_OK)
    throw std::runtime_error("CHOLMOD factorize failed (status " + std::to_string(common_.status) + ")");
  if (interface_set_ && !factor_->IPerm) {
    // cholmod_solve2 with a Bset builds the inverse permutation into L on its first call:
    // a write into a factor that identical subdomains solve with from several threads at
    // once (SharedFactors). Built here, every solve only reads L.
    factor_->IPerm = cholmod_malloc(factor_->n, sizeof(int), &common_);
    if (!factor_->IPerm) throw std::runtime_error("CHOLMOD allocation failed (out of memory?)");
    const auto* permutation = static_cast<const int*>(factor_->Perm);
    auto* inverse = static_cast<int*>(factor_->IPerm);
    for (size_t k = 0; k < factor_->n; ++k) inverse[permutation[k]] = static_cast<int>(k);
  }
  // A simplicial factor is LDL' by default, which completes on an indefinite matrix with
  // negative entries in D (CHOLMOD reports NOT_POSDEF only for LL'): check D, the first
  // entry of each column, so that an indefinite stiffness is an error, not a saddle point.
  if (!factor_->is_ll && !factor_->is_super) {
    const auto* start = static_cast<const int*>(factor_->p);
    const auto* values = static_cast<const double*>(factor_->x);
    for (size_t j = 0; j < factor_->n; ++j)
      if (!(values[start[j]] > 0)) return static_cast<int>(j);
  }
  return -1;
}

int CholmodFactor::factorize_with_last(const SparseMatrix& A, const std::vector<int>& last) {
  if (A.rows() != A.cols()) throw std::invalid_argument("CholmodFactor: matrix is not square");
  if (!A.isCompressed()) throw std::invalid_argument("CholmodFactor: matrix is not compressed");
  const auto n = static_cast<size_t>(A.rows());
  std::vector<char> is_last(n, 0);
  for (int column : last) is_last[static_cast<size_t>(column)] = 1;
  std::vector<int> first;  // the other columns, ascending
  for (size_t j = 0; j < n; ++j)
    if (!is_last[j]) first.push_back(static_cast<int>(j));
  // The first block's own fill-reducing order (CHOLMOD's choice of AMD or METIS, postordered),
  // then `last`: with postordering off the given order stands, so the last columns stay last.
  std::vector<int> order;
  order.reserve(n);
  if (!first.empty()) {
    std::vector<int> position(n, -1);
    for (size_t k = 0; k < first.size(); ++k) position[static_cast<size_t>(first[k])] = static_cast<int>(k);
    std::vector<Eigen::Triplet<double, int>> entries;
    for (Eigen::Index j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (position[static_cast<size_t>(it.row())] >= 0 && position[static_cast<size_t>(j)] >= 0)
          entries.emplace_back(position[static_cast<size_t>(it.row())], position[static_cast<size_t>(j)], it.value());
    SparseMatrix block(static_cast<Eigen::Index>(first.size()), static_cast<Eigen::Index>(first.size()));
    block.setFromTriplets(entries.begin(), entries.end());
    cholmod_sparse block_view = view_lower(block);
    cholmod_factor* analysis = analyze_alone(&block_view, &common_);
    if (!analysis) throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
    const auto* block_order = static_cast<const int*>(analysis->Perm);
    for (size_t k = 0; k < first.size(); ++k) order.push_back(first[static_cast<size_t>(block_order[k])]);
    cholmod_free_factor(&analysis, &common_);
  }
  order.insert(order.end(), last.begin(), last.end());
  cholmod_sparse view = view_lower(A);
  cholmod_free_factor(&factor_, &common_);
  cholmod_free_sparse(&interface_set_, &common_);
  {
    const OneOrdering given(common_, CHOLMOD_GIVEN);
    common_.postorder = 0;
    common_.supernodal = CHOLMOD_SUPERNODAL;  // LL': trailing_block reads L's last columns
    factor_ = cholmod_analyze_p(&view, order.data(), nullptr, 0, &common_);
  }
  if (!factor_) throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
  if (!std::equal(order.begin(), order.end(), static_cast<const int*>(factor_->Perm)))
    throw std::logic_error("CholmodFactor::factorize_with_last: CHOLMOD did not keep the given order");
  analysis_flops_ = common_.fl, analysis_nonzeros_ = common_.lnz;
  size_ = A.rows();
  last_columns_ = static_cast<Eigen::Index>(last.size());
  return factorize_numeric(view);
}

Eigen::MatrixXd CholmodFactor::trailing_block() const {
  if (!factor_ || !factor_->is_super || !factor_->is_ll)
    throw std::logic_error("CholmodFactor::trailing_block: no supernodal LL' factor");
  const auto n = static_cast<Eigen::Index>(factor_->n), first = n - last_columns_;
  Eigen::MatrixXd block = Eigen::MatrixXd::Zero(last_columns_, last_columns_);
  const auto* super = static_cast<const int*>(factor_->super);
  const auto* row_start = static_cast<const int*>(factor_->pi);
  const auto* value_start = static_cast<const int*>(factor_->px);
  const auto* rows = static_cast<const int*>(factor_->s);
  const auto* values = static_cast<const double*>(factor_->x);
  // Supernode k: columns super[k] .. super[k+1]-1, a dense column-major block of its rows
  // s[pi[k] .. pi[k+1]-1] (the first of them its own columns) by its columns.
  for (size_t k = 0; k < factor_->nsuper; ++k) {
    if (super[k + 1] <= first) continue;
    const int height = row_start[k + 1] - row_start[k];
    for (int j = std::max<int>(super[k], static_cast<int>(first)); j < super[k + 1]; ++j) {
      const double* column = values + value_start[k] + static_cast<long>(j - super[k]) * height;
      for (int i = 0; i < height; ++i)
        if (const int row = rows[row_start[k] + i]; row >= j) block(row - first, j - first) = column[i];
    }
  }
  return block;
}

void CholmodFactor::forward(const Vec& b, Vec& y) const {
  const auto* permutation = static_cast<const int*>(factor_->Perm);
  permuted_.resize(b.size());
  for (Eigen::Index k = 0; k < b.size(); ++k) permuted_[k] = b[permutation[k]];
  if (factor_->is_super) {
    y = permuted_;
    supernodal_forward(*factor_, y, own_workspace_.supernodal_below_);
    return;
  }
  triangular_solve(CHOLMOD_L, permuted_, y);
}

void CholmodFactor::backward(const Vec& y, Vec& x) const {
  if (factor_->is_super) {
    permuted_ = y;
    supernodal_backward(*factor_, permuted_, own_workspace_.supernodal_below_);
  } else {
    triangular_solve(CHOLMOD_Lt, y, permuted_);
  }
  const auto* permutation = static_cast<const int*>(factor_->Perm);
  x.resize(y.size());
  for (Eigen::Index k = 0; k < y.size(); ++k) x[permutation[k]] = permuted_[k];
}

void CholmodFactor::triangular_solve(int system, const Vec& b, Vec& x) const {
  if (!factor_ || !factor_->is_ll) throw std::logic_error("CholmodFactor: triangular solves need an LL' factor");
  cholmod_dense rhs = view_columns(b.data(), b.size(), 1);
  CholmodSolveWorkspace::Buffers& buffers = own_workspace_.vector_;
  if (!cholmod_solve2(system, factor_, &rhs, nullptr, &buffers.solution, nullptr, &buffers.y, &buffers.e,
                      &own_workspace_.common_))
    throw solve_failure(own_workspace_.common_);
  x.resize(b.size());
  std::memcpy(x.data(), buffers.solution->x, sizeof(double) * static_cast<size_t>(b.size()));
}

cholmod_factor* CholmodFactor::analyze_interface_last(cholmod_sparse& A, const std::vector<int>& interface) {
  const double unconstrained_nonzeros = common_.lnz, unconstrained_flops = common_.fl;
  std::vector<int> member(A.nrow, 0), order(A.nrow);
  for (int column : interface) member[static_cast<size_t>(column)] = 1;
  if (!cholmod_camd(&A, nullptr, 0, member.data(), order.data(), &common_))
    throw std::runtime_error("CHOLMOD's CAMD ordering failed (out of memory?)");
  cholmod_factor* constrained = nullptr;
  {
    const OneOrdering given(common_, CHOLMOD_GIVEN);
    common_.supernodal = CHOLMOD_SIMPLICIAL;  // CHOLMOD solves on a subset of columns of simplicial factors only
    constrained = cholmod_analyze_p(&A, order.data(), nullptr, 0, &common_);
  }
  if (!constrained) throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
  // The interface columns are closed under the elimination tree's ancestors (they come last
  // and postordering keeps ancestors), so a solve on them reads exactly their columns of L.
  const auto* permutation = static_cast<const int*>(constrained->Perm);
  const auto* column_counts = static_cast<const int*>(constrained->ColCount);
  double interface_nonzeros = 0;
  for (size_t k = 0; k < A.nrow; ++k)
    if (member[static_cast<size_t>(permutation[k])]) interface_nonzeros += column_counts[k];
  // automatic: the factor entries a pass of F no longer reads, and the factorization's extra
  // flops for them. The 2D model problem's subdomains skip 80 to 92 % at 42 to 233 flops
  // each; 3D boxes need 390 and more (H/h = 8 scalar boxes, 1700 for H/h = 16; elastic boxes
  // are supernodal and never get here under factor = "auto"); the large contact zone's
  // subdomains, nearly all interface, skip under 1 %.
  if (ordering_ == InterfaceOrdering::automatic &&
      !interface_ordering_pays(unconstrained_nonzeros, unconstrained_nonzeros - interface_nonzeros,
                               common_.fl - unconstrained_flops))
    cholmod_free_factor(&constrained, &common_);
  return constrained;
}

void CholmodFactor::solve_on_interface(const Eigen::VectorXd& b_on_interface, Eigen::VectorXd& x_on_interface,
                                       CholmodSolveWorkspace& w) const {
  if (!w.interface_rhs_ || w.interface_rhs_->nrow != factor_->n) {
    cholmod_free_dense(&w.interface_rhs_, &w.common_);
    w.interface_rhs_ = cholmod_zeros(factor_->n, 1, CHOLMOD_REAL, &w.common_);
    if (!w.interface_rhs_) throw std::runtime_error("CHOLMOD allocation failed (out of memory?)");
  }
  const auto* columns = static_cast<const int*>(interface_set_->i);
  const auto count = static_cast<Eigen::Index>(interface_set_->nzmax);
  auto* rhs = static_cast<double*>(w.interface_rhs_->x);
  for (Eigen::Index k = 0; k < count; ++k) rhs[columns[k]] = b_on_interface[k];
  CholmodSolveWorkspace::Buffers& buffers = w.interface_;
  if (!cholmod_solve2(CHOLMOD_A, factor_, w.interface_rhs_, interface_set_, &buffers.solution, &w.reached_,
                      &buffers.y, &buffers.e, &w.common_))
    throw solve_failure(w.common_);
  const auto* solution = static_cast<const double*>(buffers.solution->x);
  x_on_interface.resize(count);
  for (Eigen::Index k = 0; k < count; ++k) x_on_interface[k] = solution[columns[k]];
  for (Eigen::Index k = 0; k < count; ++k) rhs[columns[k]] = 0;  // zero again: the workspace may serve another factor
}

void CholmodFactor::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, CholmodSolveWorkspace& w) const {
  x.resize(b.size());
  solve_columns(b.data(), b.size(), 1, x.data(), w, w.vector_);
}

void CholmodFactor::solve(const Eigen::MatrixXd& b, Eigen::MatrixXd& x, CholmodSolveWorkspace& w) const {
  x.resize(b.rows(), b.cols());
  solve_columns(b.data(), b.rows(), b.cols(), x.data(), w, w.block_);
}

void CholmodFactor::solve_columns(const double* b, Eigen::Index rows, Eigen::Index cols, double* x,
                                  CholmodSolveWorkspace& w, CholmodSolveWorkspace::Buffers& buffers) const {
  if (factor_->is_super) {  // A = P'LL'P: x = P'L^{-T}L^{-1}P b, the triangles through Eigen (supernodal_solve.h)
    const ThreadLimit one_thread(cols > 1 ? 1 : 0);  // as in factorize_numeric: a block's products on this thread
    const auto* permutation = static_cast<const int*>(factor_->Perm);
    Eigen::MatrixXd& permuted = w.supernodal_rhs_;
    permuted.resize(rows, cols);
    for (Eigen::Index j = 0; j < cols; ++j)
      for (Eigen::Index k = 0; k < rows; ++k) permuted(k, j) = b[j * rows + permutation[k]];
    supernodal_forward(*factor_, permuted, w.supernodal_below_);
    supernodal_backward(*factor_, permuted, w.supernodal_below_);
    for (Eigen::Index j = 0; j < cols; ++j)
      for (Eigen::Index k = 0; k < rows; ++k) x[j * rows + permutation[k]] = permuted(k, j);
    return;
  }
  cholmod_dense rhs = view_columns(b, rows, cols);
  if (!cholmod_solve2(CHOLMOD_A, factor_, &rhs, nullptr, &buffers.solution, nullptr, &buffers.y, &buffers.e,
                      &w.common_))
    throw solve_failure(w.common_);
  std::memcpy(x, buffers.solution->x, sizeof(double) * static_cast<size_t>(rows * cols));
}

long CholmodFactor::factorizations_in_process() { return numeric_factorizations.load(); }

double CholmodFactor::reciprocal_condition() const {
  return factor_ ? cholmod_rcond(factor_, &common_) : 0.0;
}

double CholmodFactor::factor_nonzeros() const {
  if (!factor_) return 0;
  if (factor_->is_super) return static_cast<double>(factor_->xsize);
  const int* column_counts = static_cast<const int*>(factor_->nz);
  double total = 0;
  for (size_t j = 0; j < factor_->n; ++j) total += column_counts[j];
  return total;
}

double CholmodFactor::interface_bytes() const {
  if (!interface_set_ || !factor_) return 0;
  std::vector<char> on_interface(factor_->n, 0);
  const auto* columns = static_cast<const int*>(interface_set_->i);
  for (size_t k = 0; k < interface_set_->nzmax; ++k) on_interface[static_cast<size_t>(columns[k])] = 1;
  const auto* permutation = static_cast<const int*>(factor_->Perm);
  const auto* column_counts = static_cast<const int*>(factor_->nz);
  const double value = sizeof(double), index = sizeof(int);
  double bytes = 0;
  for (size_t j = 0; j < factor_->n; ++j)
    if (on_interface[static_cast<size_t>(permutation[j])]) bytes += column_counts[j] * (value + index) + 2 * index;
  return bytes;
}

double CholmodFactor::factor_bytes() const {
  if (!factor_) return 0;
  const double value = sizeof(double), index = sizeof(int);  // CHOLMOD_INT factors (view_lower)
  if (factor_->is_super)  // blocks x, row indices s, and per supernode super, pi and px
    return static_cast<double>(factor_->xsize) * value + static_cast<double>(factor_->ssize) * index +
           3.0 * static_cast<double>(factor_->nsuper + 1) * index;
  return factor_nonzeros() * (value + index) + 2.0 * static_cast<double>(factor_->n) * index;  // x, i; p, nz
}

}  // namespace ffeti
