// The dual operator F = B K+ B' (projected and coercive) against its dense explicit form,
// with each subdomain's interface ordered by the fill-reducing permutation or forced last.
#include "feti/coarse_space.h"
#include "feti/dual_operator.h"
#include "base/errors.h"
#include "feti/feti_problem.h"
#include "feti/kernel.h"
#include "service/options.h"
#include "feti/primal.h"
#include "parallel/process.h"
#include "membrane_model.h"
#include "input_error.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numeric>

namespace ffeti {
namespace {

/// The pieces of the dual operator built by hand, for dense comparisons.
struct DualPieces {
  std::vector<SubdomainInput> subs;
  Constraints constraints;
  std::vector<LocalConstraints> local;
  SubdomainList subdomains;
  Eigen::MatrixXd B, Kplus_dense, R;
};

/// `ordering`: where each subdomain's factor puts its interface (forced last: the dual
/// operator's solves on the interface alone, fixing dofs among it).
DualPieces dual_pieces(const test::MembraneOptions& o, InterfaceOrdering ordering = InterfaceOrdering::fill_reducing) {
  DualPieces p;
  p.subs = test::membrane_subdomains(o);
  // Total FETI: Dirichlet conditions as rows, every subdomain floats (the hardest case).
  p.constraints = build_constraints(p.subs, test::membrane_contact(p.subs), FetiVariant::tfeti);
  std::vector<Eigen::Index> sizes;
  int n = 0, r = 0;
  for (const auto& s : p.subs) sizes.push_back(s.K.rows()), n += static_cast<int>(s.K.rows());
  p.local = split_by_subdomain(p.constraints, sizes);
  for (size_t s = 0; s < p.subs.size(); ++s)
    p.subdomains.push_back(std::make_unique<Subdomain>(
        static_cast<int>(s), p.subs[s].K, candidate_kernel(p.subs[s].x, p.subs[s].y, p.subs[s].component),
        FactorKind::simplicial, ordering, nullptr, touched_dofs(p.local[s].B)));
  for (const auto& s : p.subdomains) r += static_cast<int>(s->kernel().cols());
  p.B = Eigen::MatrixXd::Zero(p.constraints.rows(), n);
  p.Kplus_dense = Eigen::MatrixXd::Zero(n, n);  // Moore-Penrose, independent of fixing dofs
  p.R = Eigen::MatrixXd::Zero(n, r);
  int offset = 0, column = 0;
  for (size_t s = 0; s < p.subs.size(); ++s) {
    const auto ns = static_cast<int>(p.subs[s].K.rows());
    p.B.middleCols(offset, ns) = Eigen::MatrixXd::Zero(p.constraints.rows(), ns);
    for (size_t k = 0; k < p.local[s].rows.size(); ++k)
      for (int j = 0; j < ns; ++j) p.B(p.local[s].rows[k], offset + j) = p.local[s].B.coeff(static_cast<int>(k), j);
    p.Kplus_dense.block(offset, offset, ns, ns) =
        Eigen::MatrixXd(p.subs[s].K.get()).completeOrthogonalDecomposition().pseudoInverse();
    const Eigen::MatrixXd& Rs = p.subdomains[s]->kernel();
    p.R.block(offset, column, ns, Rs.cols()) = Rs;
    offset += ns, column += static_cast<int>(Rs.cols());
  }
  return p;
}

class DualOperatorOrdering : public ::testing::TestWithParam<InterfaceOrdering> {};

TEST_P(DualOperatorOrdering, ProjectedOperatorMatchesDenseExplicit) {
  DualPieces p = dual_pieces(test::membrane_options(8, 2), GetParam());
  const auto on_interface = std::count_if(p.subdomains.begin(), p.subdomains.end(),
                                          [](const auto& s) { return s->interface_solves(); });
  EXPECT_EQ(on_interface, GetParam() == InterfaceOrdering::interface_last ? static_cast<long>(p.subdomains.size()) : 0);
  std::vector<int> bodies;
  for (const auto& s : p.subs) bodies.push_back(s.body);
  const int m = p.constraints.rows();
  const int S = static_cast<int>(p.subs.size());
  const SerialCommunicator comm;
  std::vector<int> ids(S);
  std::iota(ids.begin(), ids.end(), 0);
  const SubdomainSum sum(rows_by_subdomain(p.constraints, S), std::vector<int>(S, 0), m, comm);
  const DualOperator F(p.subdomains, p.local, sum, m, 1);
  const CoarseSpace coarse(p.subdomains, p.local, ids, m, p.constraints.equality_rows, bodies, comm);
  // G = R'B' and P = I - G'(GG')^{-1}G built densely; P F P does not depend on which
  // generalized inverse K^+ is, so the fixing-dof inverse must agree with Moore-Penrose.
  const Eigen::MatrixXd G = p.R.transpose() * p.B.transpose();
  EXPECT_LT((Eigen::MatrixXd(coarse.G()) - G).norm(), 1e-12 * G.norm());
  const Eigen::MatrixXd P =
      Eigen::MatrixXd::Identity(m, m) - G.transpose() * (G * G.transpose()).ldlt().solve(G);
  const Eigen::MatrixXd PFP_dense = P * p.B * p.Kplus_dense * p.B.transpose() * P;
  Eigen::MatrixXd PFP(m, m);
  Vec Px(m), FPx(m), y(m);
  for (int j = 0; j < m; ++j) {
    coarse.project(Vec::Unit(m, j), Px);
    F.apply(Px, FPx);
    coarse.project(FPx, y);
    PFP.col(j) = y;
  }
  EXPECT_LT((PFP - PFP_dense).norm(), 1e-9 * PFP_dense.norm());
  // The projector is symmetric, idempotent and annihilates G'.
  Eigen::MatrixXd P_applied(m, m);
  for (int j = 0; j < m; ++j) {
    coarse.project(Vec::Unit(m, j), y);
    P_applied.col(j) = y;
  }
  EXPECT_LT((P_applied - P).norm(), 1e-12 * m);
  EXPECT_LT((P_applied * P_applied - P_applied).norm(), 1e-12 * m);
  EXPECT_LT((G * P_applied).norm(), 1e-12 * G.norm());
}

TEST_P(DualOperatorOrdering, CoerciveOperatorMatchesDenseExplicit) {
  test::MembraneOptions o = test::membrane_options(8, 2);
  o.with_contact = false;
  o.body2 = false;
  std::vector<SubdomainInput> subs = test::membrane_subdomains(o);
  // Regularize every subdomain with a mass-like diagonal so that none floats.
  for (auto& s : subs) {
    for (Eigen::Index i = 0; i < s.K.rows(); ++i) s.K.edit().coeffRef(i, i) += 0.1;
    s.dirichlet_dofs.clear();
  }
  const Constraints c = build_constraints(subs, {}, FetiVariant::feti1);
  std::vector<Eigen::Index> sizes;
  for (const auto& s : subs) sizes.push_back(s.K.rows());
  const auto local = split_by_subdomain(c, sizes);
  SubdomainList subdomains;
  for (size_t s = 0; s < subs.size(); ++s)
    subdomains.push_back(std::make_unique<Subdomain>(static_cast<int>(s), subs[s].K,
        candidate_kernel(subs[s].x, subs[s].y, subs[s].component), FactorKind::simplicial, GetParam(), nullptr,
        touched_dofs(local[s].B)));
  const int m = c.rows();
  const SerialCommunicator comm;
  const int S = static_cast<int>(subs.size());
  const SubdomainSum sum(rows_by_subdomain(c, S), std::vector<int>(S, 0), m, comm);
  const DualOperator F(subdomains, local, sum, m, 2);
  Eigen::MatrixXd F_dense = Eigen::MatrixXd::Zero(m, m);
  for (size_t s = 0; s < subs.size(); ++s) {
    const Eigen::MatrixXd Bs = Eigen::MatrixXd(local[s].B);
    const Eigen::MatrixXd block = Bs * Eigen::MatrixXd(subs[s].K.get()).inverse() * Bs.transpose();
    for (size_t a = 0; a < local[s].rows.size(); ++a)
      for (size_t b = 0; b < local[s].rows.size(); ++b)
        F_dense(local[s].rows[a], local[s].rows[b]) += block(a, b);
  }
  Vec y(m);
  for (int j = 0; j < m; ++j) {
    F.apply(Vec::Unit(m, j), y);
    EXPECT_LT((y - F_dense.col(j)).norm(), 1e-10 * F_dense.norm());
  }
  // Blocks: of every column (block solves on the whole factor) and of one or two columns
  // (with the interface last: a solve on the interface per column, cheaper there).
  for (int width : {m, 1, 2}) {
    const Eigen::MatrixXd X = Eigen::MatrixXd::Identity(m, m).leftCols(width);
    Eigen::MatrixXd Y;
    F.apply(X, Y);
    EXPECT_LT((Y - F_dense.leftCols(width)).norm(), 1e-10 * F_dense.norm()) << "block of " << width;
  }
}

INSTANTIATE_TEST_SUITE_P(BothOrderings, DualOperatorOrdering,
                         ::testing::Values(InterfaceOrdering::fill_reducing, InterfaceOrdering::interface_last));

}  // namespace
}  // namespace ffeti
