#include "factor/supernodal_solve.h"

namespace ffeti {
namespace {

/// Supernode k: columns super[k] .. super[k+1]-1 of L, a dense column-major block of
/// pi[k+1]-pi[k] rows (s[pi[k]..]: its own columns first, then the rows below them) stored
/// from x[px[k]].
struct Supernode {
  int first_column, width, height;
  const int* rows_below;
  Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> block;

  Supernode(const cholmod_factor& f, size_t k)
      : first_column(static_cast<const int*>(f.super)[k]),
        width(static_cast<const int*>(f.super)[k + 1] - first_column),
        height(static_cast<const int*>(f.pi)[k + 1] - static_cast<const int*>(f.pi)[k]),
        rows_below(static_cast<const int*>(f.s) + static_cast<const int*>(f.pi)[k] + width),
        block(static_cast<const double*>(f.x) + static_cast<const int*>(f.px)[k], height, width,
              Eigen::OuterStride<>(height)) {}

  int below() const { return height - width; }
};

// One right-hand side as a vector (the one a Hessian multiplication solves with): Eigen then
// takes its matrix-vector kernels, which a one-column block does not reach (the solves of
// 1024 elastic boxes took 25 % longer through the block code).
void forward_vector(const cholmod_factor& factor, double* x, Eigen::MatrixXd& scratch) {
  for (size_t k = 0; k < factor.nsuper; ++k) {
    const Supernode node(factor, k);
    Eigen::Map<Eigen::VectorXd> own(x + node.first_column, node.width);
    node.block.topRows(node.width).triangularView<Eigen::Lower>().solveInPlace(own);
    if (node.below() == 0) continue;
    auto below = scratch_block(scratch, node.below(), 1).col(0);
    below.noalias() = node.block.bottomRows(node.below()) * own;
    for (int i = 0; i < node.below(); ++i) x[node.rows_below[i]] -= below[i];
  }
}

void backward_vector(const cholmod_factor& factor, double* x, Eigen::MatrixXd& scratch) {
  for (size_t k = factor.nsuper; k-- > 0;) {
    const Supernode node(factor, k);
    Eigen::Map<Eigen::VectorXd> own(x + node.first_column, node.width);
    if (node.below() > 0) {
      auto below = scratch_block(scratch, node.below(), 1).col(0);
      for (int i = 0; i < node.below(); ++i) below[i] = x[node.rows_below[i]];
      own.noalias() -= node.block.bottomRows(node.below()).transpose() * below;
    }
    node.block.topRows(node.width).transpose().triangularView<Eigen::Upper>().solveInPlace(own);
  }
}

}  // namespace

void supernodal_forward(const cholmod_factor& factor, Eigen::Ref<Eigen::MatrixXd> X, Eigen::MatrixXd& scratch) {
  if (X.cols() == 1) return forward_vector(factor, X.data(), scratch);
  for (size_t k = 0; k < factor.nsuper; ++k) {
    const Supernode node(factor, k);
    auto own = X.middleRows(node.first_column, node.width);
    node.block.topRows(node.width).triangularView<Eigen::Lower>().solveInPlace(own);
    if (node.below() == 0) continue;
    auto below = scratch_block(scratch, node.below(), X.cols());
    below.noalias() = node.block.bottomRows(node.below()) * own;
    for (int i = 0; i < node.below(); ++i) X.row(node.rows_below[i]) -= below.row(i);
  }
}

void supernodal_backward(const cholmod_factor& factor, Eigen::Ref<Eigen::MatrixXd> X, Eigen::MatrixXd& scratch) {
  if (X.cols() == 1) return backward_vector(factor, X.data(), scratch);
  for (size_t k = factor.nsuper; k-- > 0;) {
    const Supernode node(factor, k);
    auto own = X.middleRows(node.first_column, node.width);
    if (node.below() > 0) {
      auto below = scratch_block(scratch, node.below(), X.cols());
      for (int i = 0; i < node.below(); ++i) below.row(i) = X.row(node.rows_below[i]);
      own.noalias() -= node.block.bottomRows(node.below()).transpose() * below;
    }
    node.block.topRows(node.width).transpose().triangularView<Eigen::Upper>().solveInPlace(own);
  }
}

}  // namespace ffeti
