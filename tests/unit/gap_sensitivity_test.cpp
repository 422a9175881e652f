// A gap per contact row (ContactInput::gap_field) and a design that moves the gaps
// (DesignDerivative::dgap): the rows carry the gaps, z and lambda' match central
// differences of re-solves, the adjoint of a cost of (u, lambda) matches the direct mode,
// and the contact pressure divides each force by the share of all copies of its node.
#include "service/contact_pressure.h"
#include "base/errors.h"
#include "feti/feti_problem.h"
#include "membrane_model.h"
#include "sens/sensitivity.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ffeti {
namespace {

using test::tight;

/// The seed's membranes with a gap profile alpha * phi(y) on the slave dofs at x = 1,
/// phi(y) = 0.02 (1 + cos(pi y)): a design that opens the contact towards y = 0.
struct GapDesign {
  std::vector<SubdomainInput> subdomains = test::membrane_subdomains(test::membrane_options(16, 2));
  ContactInput contact = test::membrane_contact(subdomains);

  std::vector<std::vector<double>> profile() const {
    std::vector<std::vector<double>> field;
    for (const SubdomainInput& sub : subdomains) {
      field.emplace_back(sub.x.size(), 0.0);
      for (size_t i = 0; i < sub.x.size(); ++i) field.back()[i] = 0.02 * (1 + std::cos(M_PI * sub.y[i]));
    }
    return field;
  }
  FetiProblem at(double alpha, FetiVariant variant) const {
    ContactInput c = contact;
    c.gap_field = profile();
    for (auto& values : c.gap_field)
      for (double& v : values) v *= alpha;
    FetiSetupSettings setup;
    setup.variant = variant;
    return FetiProblem(subdomains, c, setup);
  }
};

class GapSensitivity : public ::testing::TestWithParam<FetiVariant> {};

TEST_P(GapSensitivity, RowsCarryTheGapsAndLambdaRateMatchesFiniteDifferences) {
  const GapDesign design;
  const double alpha = 1.0;
  const FetiProblem problem = design.at(alpha, GetParam());
  const Constraints& c = problem.constraints();
  const auto profile = design.profile();
  for (int i = c.equality_rows; i < c.rows(); ++i) {  // each row's right-hand side is its slave's gap
    const auto [s, dof] = c.geometry[static_cast<size_t>(i - c.equality_rows)]->slave_dof();
    EXPECT_NEAR(c.rhs[static_cast<size_t>(i)], alpha * profile[static_cast<size_t>(s)][static_cast<size_t>(dof)], 1e-15);
  }
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  SensitivityProblem sensitivity(problem, state, 1e-8);
  ASSERT_TRUE(sensitivity.classification().weak.empty());
  ASSERT_GT(sensitivity.classification().strong.size(), 3u);
  ASSERT_GE(sensitivity.classification().inactive.size(), 2u);  // the gap opened part of the line

  DesignDerivative direction;
  direction.dgap = profile;
  const SensitivityResult direct = sensitivity.direct(direction, tight());
  ASSERT_EQ(direct.status, SolveStatus::converged);
  const double h = 1e-3;  // lambda and u are linear in alpha while the contact set stays: no truncation error
  const FetiResult plus = design.at(alpha + h, GetParam()).solve(tight());
  const FetiResult minus = design.at(alpha - h, GetParam()).solve(tight());
  double error = 0, scale = 0;
  for (int i = 0; i < c.inequality_rows(); ++i) {
    const double fd = (plus.lambda[c.equality_rows + i] - minus.lambda[c.equality_rows + i]) / (2 * h);
    error = std::max(error, std::abs(fd - direct.contact_multipliers[i]));
    scale = std::max(scale, std::abs(fd));
  }
  EXPECT_GT(scale, 0);
  EXPECT_LT(error, 1e-6 * scale);
  double z_error = 0, z_scale = 0;
  for (size_t s = 0; s < direct.z.size(); ++s) {
    const Vec fd = (plus.u[s] - minus.u[s]) / (2 * h);
    z_error = std::max(z_error, (fd - direct.z[s]).cwiseAbs().maxCoeff());
    z_scale = std::max(z_scale, fd.cwiseAbs().maxCoeff());
  }
  EXPECT_LT(z_error, 1e-6 * z_scale);

  // J = g'u + r'lambda: one adjoint solve gives g'z + r'lambda'.
  std::vector<Vec> g;
  for (size_t s = 0; s < state.u.size(); ++s) g.push_back(Vec::LinSpaced(state.u[s].size(), 1.0, 2.0 + double(s)));
  const Vec r = Vec::LinSpaced(c.inequality_rows(), -1.0, 3.0);
  ASSERT_EQ(sensitivity.adjoint(g, tight(), r).status, SolveStatus::converged);
  double through_direct = r.dot(direct.contact_multipliers);
  for (size_t s = 0; s < g.size(); ++s) through_direct += g[s].dot(direct.z[s]);
  EXPECT_NEAR(sensitivity.adjoint_gradient(direction), through_direct, 1e-8 * std::abs(through_direct));
}

INSTANTIATE_TEST_SUITE_P(Variants, GapSensitivity, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti));

TEST(ContactPressure, DividesEachForceByTheShareOfAllCopiesOfItsNode) {
  const GapDesign design;
  const FetiProblem problem = design.at(0.0, FetiVariant::feti1);
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  // Every dof of every subdomain gets a share of 0.5: a node held by two subdomains has 1.
  std::vector<Vec> share;
  for (const SubdomainInput& sub : problem.inputs()) share.push_back(Vec::Constant(sub.K.rows(), 0.5));
  const ContactPressure p = contact_pressure(problem, state.lambda, share);
  const Constraints& c = problem.constraints();
  int shared = 0;
  for (int i = 0; i < c.inequality_rows(); ++i) {
    const double copies = p.share_per_row[i] / 0.5;
    EXPECT_TRUE(copies == 1 || copies == 2);
    shared += copies == 2;
    EXPECT_DOUBLE_EQ(p.per_row[i], state.lambda[c.equality_rows + i] / p.share_per_row[i]);
  }
  EXPECT_EQ(shared, 1);  // the node at y = 1/2 lies on two subdomains of body 0
  // Zero shares where a force acts: an error naming the argument.
  std::vector<Vec> none;
  for (const SubdomainInput& sub : problem.inputs()) none.push_back(Vec::Zero(sub.K.rows()));
  EXPECT_THROW(
      {
        try {
          contact_pressure(problem, state.lambda, none);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("Share"), std::string::npos);
          throw;
        }
      },
      InputError);
}

TEST(Overflow, AGapOfMinus1e300IsReportedAsAnOverflowNotConverged) {
  // Finite data whose products overflow: never "converged".
  const GapDesign design;
  const FetiResult state = design.at(-1e300, FetiVariant::tfeti).solve();
  EXPECT_EQ(state.status, SolveStatus::overflow) << to_string(state.status);
}

}  // namespace
}  // namespace ffeti
