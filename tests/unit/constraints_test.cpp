#include "feti/constraints.h"
#include "feti/errors.h"
#include "membrane_model.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace ffeti {
namespace {

/// B as a dense matrix over the concatenated subdomain dofs.
Eigen::MatrixXd dense_B(const Constraints& c, const std::vector<SubdomainInput>& subs) {
  std::vector<int> offset{0};
  for (const auto& s : subs) offset.push_back(offset.back() + static_cast<int>(s.K.rows()));
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(c.rows(), offset.back());
  for (int i = 0; i < c.rows(); ++i)
    for (int k = c.row_start[i]; k < c.row_start[i + 1]; ++k)
      B(i, offset[c.entries[k].subdomain] + c.entries[k].dof) += c.entries[k].coefficient;
  return B;
}

TEST(Constraints, SeedCountsForFeti1) {
  // n = 8, N = 2 per body: per body 1 interior vertical + 1 horizontal line of 9 nodes,
  // 1 cross point: 9 + 9 - 1 = 17 interface nodes, 16 with 2 copies and 1 with 4 -> 19 rows.
  // FETI-1 drops the row on x = 0 of body 0 (both copies fixed): 18 + 19 gluing rows,
  // plus one contact row per physical node on x = 1: 9.
  const auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
  const Constraints c = build_constraints(subs, test::membrane_contact(subs), FetiVariant::feti1);
  EXPECT_EQ(c.count(RowKind::gluing), 18 + 19);
  EXPECT_EQ(c.count(RowKind::contact), 9);
  EXPECT_EQ(c.count(RowKind::dirichlet), 0);
  EXPECT_EQ(c.equality_rows, 37);
  const Eigen::MatrixXd B = dense_B(c, subs);
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(B).rank(), c.rows());  // full row rank
}

TEST(Constraints, TotalFetiAddsDirichletRowsAndStaysFullRank) {
  const auto subs = test::membrane_subdomains(test::membrane_options(8, 2));
  const Constraints c = build_constraints(subs, test::membrane_contact(subs), FetiVariant::tfeti);
  EXPECT_EQ(c.count(RowKind::dirichlet), 10);  // 9 nodes on x = 0: two subdomains of 5
  EXPECT_EQ(c.count(RowKind::gluing), 18 + 19);
  const Eigen::MatrixXd B = dense_B(c, subs);
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(B).rank(), c.rows());
}

TEST(Constraints, GluingRowsVanishOnContinuousFields) {
  const auto subs = test::membrane_subdomains(test::membrane_options(12, 3));
  const Constraints c = build_constraints(subs, test::membrane_contact(subs), FetiVariant::tfeti);
  // u = x + 2y on every subdomain: every gluing row is satisfied exactly.
  std::vector<LocalConstraints> local;
  std::vector<Eigen::Index> sizes;
  for (const auto& s : subs) sizes.push_back(s.K.rows());
  local = split_by_subdomain(c, sizes);
  for (int i = 0; i < c.rows(); ++i) {
    if (c.kind[i] != RowKind::gluing) continue;
    double value = 0;
    for (int k = c.row_start[i]; k < c.row_start[i + 1]; ++k) {
      const auto& e = c.entries[k];
      value += e.coefficient * (subs[e.subdomain].x[e.dof] + 2 * subs[e.subdomain].y[e.dof]);
    }
    EXPECT_NEAR(value, 0.0, 1e-12);
  }
}

TEST(Constraints, ContactSlaveWithoutMasterIsAnInputError) {
  auto subs = test::membrane_subdomains(test::membrane_options(4, 1));
  ContactInput contact = test::membrane_contact(subs);
  contact.master_dofs[1].pop_back();  // one slave loses its partner
  try {
    build_constraints(subs, contact, FetiVariant::feti1);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("contactSlave[0]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ffeti
