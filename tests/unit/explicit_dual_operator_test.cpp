// Explicit local dual operators (factor/dense_interface_inverse, Subdomain::form_explicit_block):
// the dense block of K_s^+ on the interface applies the same generalized inverse as the
// factor's solves, on semidefinite and coercive subdomains, 2D and 3D, simplicial and
// supernodal, interface last or not; the dual operator and a whole solve agree with the
// implicit path to round-off; the automatic choice follows its byte rule; fetiInfo's keys.
#include "feti/dual_operator.h"
#include "feti/held_bytes.h"
#include "feti/kernel.h"
#include "service/statistics.h"
#include "membrane_model.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <map>
#include <numeric>
#include <random>

namespace ffeti {
namespace {

Eigen::MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd M(rows, cols);
  for (Eigen::Index k = 0; k < M.size(); ++k) M.data()[k] = uniform(generator);
  return M;
}

TEST(PackedSymmetric, AppliesItsLowerTriangleAsTheSymmetricMatrix) {
  // Within one panel, exactly one, and several with a partial last one.
  const Eigen::Index width = PackedSymmetric::kPanelWidth;
  for (const Eigen::Index t : {width - 1, width, 2 * width + 3}) {
    const Eigen::MatrixXd A = random_matrix(t, t, 1);
    const Eigen::MatrixXd S = A + A.transpose();
    Eigen::MatrixXd with_other_upper = S;
    with_other_upper.triangularView<Eigen::StrictlyUpper>().setConstant(99);  // not read
    const PackedSymmetric packed(with_other_upper);
    EXPECT_DOUBLE_EQ(packed.bytes(), static_cast<double>(t * (t + 1) / 2 * 8)) << "t = " << t;
    EXPECT_DOUBLE_EQ(packed.bytes(), packed_symmetric_bytes(t));
    EXPECT_LT((packed.full() - S).norm(), 1e-15 * S.norm()) << "t = " << t;
    const Eigen::VectorXd x = random_matrix(t, 1, 2);
    Eigen::VectorXd y;
    packed.apply(x, y);
    EXPECT_LT((y - S * x).norm(), 1e-14 * (S * x).norm()) << "t = " << t;
    const Eigen::MatrixXd X = random_matrix(t, 3, 3);
    Eigen::MatrixXd Y;
    packed.apply(X, Y);
    EXPECT_LT((Y - S * X).norm(), 1e-14 * (S * X).norm()) << "t = " << t;
  }
}

TEST(ExplicitInversePays, WhenTheBlockFormsFromTheInterfaceBlockAndHoldsAtMostOneSolvePass) {
  EXPECT_TRUE(explicit_inverse_pays(100, 100, true));
  EXPECT_TRUE(explicit_inverse_pays(99, 100, true));
  EXPECT_FALSE(explicit_inverse_pays(101, 100, true));
  EXPECT_FALSE(explicit_inverse_pays(0, 100, true));  // no interface: nothing to form
  EXPECT_FALSE(explicit_inverse_pays(50, 100, false));  // by block solves: too dear to form
}

/// Both forms of K_s^+ on the interface, column by column of the identity: the implicit
/// solve (interface block or whole factor) and the explicit block, and the whole solve's
/// values on the interface.
void expect_explicit_equals_implicit(const SparseMatrix& K, const Eigen::MatrixXd& candidates, FactorKind kind,
                                     InterfaceOrdering ordering, const std::vector<int>& interface) {
  Subdomain implicit(0, K, candidates, kind, ordering, nullptr, interface);
  Subdomain explicit_form(0, K, candidates, kind, ordering, nullptr, interface);
  ASSERT_TRUE(explicit_form.form_explicit_block(DualOperatorForm::explicit_block));
  ASSERT_FALSE(implicit.form_explicit_block(DualOperatorForm::implicit));
  EXPECT_TRUE(explicit_form.solves_on_interface());
  EXPECT_DOUBLE_EQ(explicit_form.operator_bytes(), packed_symmetric_bytes(static_cast<Eigen::Index>(interface.size())));
  const auto t = static_cast<Eigen::Index>(interface.size());
  const Eigen::MatrixXd b = random_matrix(t, 3, 4);
  Eigen::MatrixXd explicit_block;
  explicit_form.apply_pseudo_inverse_on_interface(b, explicit_block);
  for (Eigen::Index j = 0; j < b.cols(); ++j) {
    Vec full_b = Vec::Zero(K.rows()), full_x, x;
    for (Eigen::Index k = 0; k < t; ++k) full_b[interface[static_cast<size_t>(k)]] = b(k, j);
    implicit.apply_pseudo_inverse(full_b, full_x);  // the factor's whole solve
    Vec on_interface(t);
    for (Eigen::Index k = 0; k < t; ++k) on_interface[k] = full_x[interface[static_cast<size_t>(k)]];
    const double scale = on_interface.norm();
    EXPECT_LT((explicit_block.col(j) - on_interface).norm(), 1e-11 * scale) << "column " << j;
    explicit_form.apply_pseudo_inverse_on_interface(Vec(b.col(j)), x);
    EXPECT_LT((x - on_interface).norm(), 1e-11 * scale) << "column " << j;
    if (implicit.interface_solves()) {
      implicit.apply_pseudo_inverse_on_interface(Vec(b.col(j)), x);
      EXPECT_LT((x - on_interface).norm(), 1e-11 * scale) << "column " << j;
    }
  }
  // Fixing dofs on the interface stay zero: the same generalized inverse, not another one.
  for (int dof : explicit_form.fixing()) {
    const auto at = std::find(interface.begin(), interface.end(), dof);
    if (at != interface.end()) EXPECT_EQ(explicit_block.row(at - interface.begin()).norm(), 0.0);
  }
}

class ExplicitMembrane : public ::testing::TestWithParam<InterfaceOrdering> {};

TEST_P(ExplicitMembrane, FloatingAndCoerciveSubdomainsAgreeWithTheFactor) {
  const std::vector<SubdomainInput> subs = test::membrane_subdomains(test::membrane_options(8, 2));
  const Constraints c = build_constraints(subs, test::membrane_contact(subs), FetiVariant::tfeti);
  std::vector<Eigen::Index> sizes;
  for (const auto& s : subs) sizes.push_back(s.K.rows());
  const auto local = split_by_subdomain(c, sizes);
  for (size_t s = 0; s < subs.size(); ++s) {  // TFETI: every subdomain floats
    const Eigen::MatrixXd candidates = candidate_kernel(subs[s].x, subs[s].y, subs[s].component);
    expect_explicit_equals_implicit(subs[s].K, candidates, FactorKind::simplicial, GetParam(), touched_dofs(local[s].B));
    SparseMatrix coercive = subs[s].K;
    for (Eigen::Index i = 0; i < coercive.rows(); ++i) coercive.coeffRef(i, i) += 0.1;
    expect_explicit_equals_implicit(coercive, candidates, FactorKind::simplicial, GetParam(), touched_dofs(local[s].B));
  }
}

INSTANTIATE_TEST_SUITE_P(BothOrderings, ExplicitMembrane,
                         ::testing::Values(InterfaceOrdering::fill_reducing, InterfaceOrdering::interface_last));

TEST(ExplicitSolid, FloatingElasticBlockAgreesWithSupernodalAndSimplicialFactors) {
  const SubdomainInput block = solid_block(0, {1, 1, 1}, {3, 3, 3}, {0, 0, 0});
  std::vector<int> faces;  // the dofs on x = 0 and z = 0: an interface with fixing dofs among it
  for (size_t k = 0; k < block.x.size(); ++k)
    if (block.x[k] == 0 || block.z[k] == 0) faces.push_back(static_cast<int>(k));
  const Eigen::MatrixXd candidates = candidate_kernel(block.x, block.y, block.component, block.z);
  for (FactorKind kind : {FactorKind::supernodal, FactorKind::simplicial})
    expect_explicit_equals_implicit(block.K, candidates, kind, InterfaceOrdering::fill_reducing, faces);
}

/// The membranes of `o` with the dual operator in `form`.
FetiProblem membranes(DualOperatorForm form, bool share = true) {
  auto subs = test::membrane_subdomains(test::membrane_options(16, 3));
  const ContactInput contact = test::membrane_contact(subs);
  FetiSetupSettings setup;
  setup.variant = FetiVariant::tfeti;
  setup.dual_operator = form;
  setup.share_factors = share;
  return FetiProblem(std::move(subs), contact, setup);
}

TEST(ExplicitDualOperator, AppliesAndSolvesLikeTheImplicitOne) {
  const FetiProblem implicit = membranes(DualOperatorForm::implicit);
  const FetiProblem explicit_form = membranes(DualOperatorForm::explicit_block);
  EXPECT_EQ(implicit.explicit_operators(), 0);
  EXPECT_EQ(explicit_form.explicit_operators(), explicit_form.subdomain_count());
  const int m = implicit.dual_dimension();
  const Eigen::MatrixXd X = random_matrix(m, 3, 5);
  Vec y_implicit, y_explicit;
  implicit.dual().F().apply(Vec(X.col(0)), y_implicit);
  explicit_form.dual().F().apply(Vec(X.col(0)), y_explicit);
  EXPECT_LT((y_explicit - y_implicit).norm(), 1e-12 * y_implicit.norm());
  Eigen::MatrixXd Y_implicit, Y_explicit;
  implicit.dual().F().apply(X, Y_implicit);
  explicit_form.dual().F().apply(X, Y_explicit);
  EXPECT_LT((Y_explicit - Y_implicit).norm(), 1e-12 * Y_implicit.norm());
  DualSolveSettings settings;
  settings.tolerance = 1e-8;
  const FetiResult a = implicit.solve(settings), b = explicit_form.solve(settings);
  EXPECT_EQ(a.status, SolveStatus::converged);
  EXPECT_EQ(b.status, SolveStatus::converged);
  EXPECT_NEAR(a.energy, b.energy, 1e-9 * std::abs(a.energy));
  EXPECT_EQ(a.counts.hessian, b.counts.hessian);
}

TEST(ExplicitDualOperator, IdenticalSubdomainsShareOneBlockAndItIsCountedOnce) {
  const FetiProblem shared = membranes(DualOperatorForm::explicit_block);
  const FetiProblem own = membranes(DualOperatorForm::explicit_block, false);
  ASSERT_GT(shared.shared_factors(), 0);
  std::map<const CholmodFactor*, const PackedSymmetric*> block_of_factor;
  double distinct = 0;
  for (const auto& s : shared.subdomains()) {
    const auto [at, fresh] = block_of_factor.emplace(&s->factor(), s->explicit_block());
    EXPECT_EQ(at->second, s->explicit_block());  // one block per factor
    if (fresh) distinct += s->explicit_block()->bytes();
  }
  EXPECT_DOUBLE_EQ(shared.explicit_bytes(), distinct);
  EXPECT_DOUBLE_EQ(explicit_block_bytes(shared.subdomains()), distinct);
  EXPECT_LT(shared.explicit_bytes(), own.explicit_bytes());
}

TEST(ExplicitDualOperator, AutomaticChoiceFollowsTheByteRuleAndTheReportSaysSo) {
  const FetiProblem automatic = membranes(DualOperatorForm::automatic);
  long expected = 0;
  for (const auto& s : automatic.subdomains()) {
    const double packed = packed_symmetric_bytes(static_cast<Eigen::Index>(s->interface().size()));
    const double pass = s->interface_solves() ? s->factor().interface_bytes() : s->factor().factor_bytes();
    EXPECT_EQ(s->has_explicit_block(), explicit_inverse_pays(packed, pass, s->interface_solves() && !s->supernodal()));
    expected += s->has_explicit_block() ? 1 : 0;
  }
  EXPECT_EQ(automatic.explicit_operators(), expected);
  EXPECT_GT(expected, 0);  // 2D membranes, interface last by default: the blocks pay
  std::map<std::string, double> keys;
  for (const auto& [name, value] : statistics(automatic, nullptr)) keys[name] = value;
  ASSERT_TRUE(keys.count("explicit_operators") && keys.count("explicit_bytes") && keys.count("time_explicit"));
  EXPECT_EQ(keys["explicit_operators"], static_cast<double>(expected));
  EXPECT_DOUBLE_EQ(keys["explicit_bytes"], automatic.explicit_bytes());
  EXPECT_GE(keys["time_explicit"], 0.0);
  const FetiProblem implicit = membranes(DualOperatorForm::implicit);
  for (const auto& [name, value] : statistics(implicit, nullptr))
    if (name == "explicit_operators" || name == "explicit_bytes" || name == "time_explicit") EXPECT_EQ(value, 0.0) << name;
}

}  // namespace
}  // namespace ffeti
