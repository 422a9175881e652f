// Numerically hard scenes stay stable under default options: extreme scaling of K and f,
// large stiffness contrast between bodies, many small subdomains (small H/h, many cross
// points), an infeasible scene, a gap sweep and zero load, and Total FETI on all of them. Each is checked against an independent answer
// (a scaled solution, the other FETI variant, or the monolithic active-set reference).
#include "feti/feti_problem.h"
#include "membrane_model.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ffeti {
namespace {

FetiResult solve_membranes(std::vector<SubdomainInput> subs, FetiVariant variant, double tolerance) {
  const ContactInput contact = test::membrane_contact(subs);
  FetiSetupSettings setup;
  setup.variant = variant;
  const FetiProblem problem(std::move(subs), contact, setup);
  DualSolveSettings settings;
  settings.tolerance = tolerance;
  return problem.solve(settings);
}

double relative_difference(const std::vector<Vec>& a, const std::vector<Vec>& b, double scale_b) {
  double difference = 0, norm = 0;
  for (size_t s = 0; s < a.size(); ++s) {
    difference += (a[s] - scale_b * b[s]).squaredNorm();
    norm += a[s].squaredNorm();
  }
  return std::sqrt(difference / norm);
}

class ExtremeScaling : public ::testing::TestWithParam<double> {};

TEST_P(ExtremeScaling, StiffnessAndLoadScaledTogetherLeaveUUnchanged) {
  const double factor = GetParam();
  auto reference_subs = test::membrane_subdomains(test::membrane_options(16, 2));
  auto scaled_subs = reference_subs;
  for (auto& s : scaled_subs) {
    s.K *= factor;
    s.f *= factor;
  }
  const FetiResult reference = solve_membranes(reference_subs, FetiVariant::feti1, 1e-10);
  const FetiResult scaled = solve_membranes(scaled_subs, FetiVariant::feti1, 1e-10);
  ASSERT_EQ(scaled.status, SolveStatus::converged);
  EXPECT_LT(relative_difference(scaled.u, reference.u, 1.0), 1e-7);
  EXPECT_LT((scaled.lambda - factor * reference.lambda).norm(), 1e-7 * factor * reference.lambda.norm());
  EXPECT_EQ(scaled.active_contact, reference.active_contact);
}

TEST_P(ExtremeScaling, LoadScaledAloneScalesU) {
  const double factor = GetParam();
  auto reference_subs = test::membrane_subdomains(test::membrane_options(16, 2));
  auto scaled_subs = reference_subs;
  for (auto& s : scaled_subs) s.f *= factor;
  const FetiResult reference = solve_membranes(reference_subs, FetiVariant::feti1, 1e-10);
  const FetiResult scaled = solve_membranes(scaled_subs, FetiVariant::feti1, 1e-10);
  ASSERT_EQ(scaled.status, SolveStatus::converged);
  EXPECT_LT(relative_difference(scaled.u, reference.u, factor), 1e-7);  // contact with zero gap is homogeneous
}

INSTANTIATE_TEST_SUITE_P(Factors, ExtremeScaling, ::testing::Values(1e-12, 1e-6, 1e6, 1e12),
                         [](const auto& info) {
                           const int exponent = static_cast<int>(std::lround(std::log10(info.param)));
                           return std::string(exponent < 0 ? "1e_minus" : "1e") + std::to_string(std::abs(exponent));
                         });

TEST(HardCases, StiffnessContrastOfSixOrdersOfMagnitude) {
  auto subs = test::membrane_subdomains(test::membrane_options(16, 2));
  for (auto& s : subs)
    if (s.body == 1) s.K *= 1e6;  // a nearly rigid right membrane on a soft left one
  const FetiResult feti1 = solve_membranes(subs, FetiVariant::feti1, 1e-10);
  const FetiResult total = solve_membranes(subs, FetiVariant::tfeti, 1e-10);
  ASSERT_EQ(feti1.status, SolveStatus::converged);
  ASSERT_EQ(total.status, SolveStatus::converged);
  EXPECT_LT(feti1.kkt.max(), 1e-6) << feti1.kkt.equilibrium << " " << feti1.kkt.equality;
  EXPECT_NEAR(feti1.energy, total.energy, 1e-8 * std::abs(feti1.energy));
  EXPECT_EQ(feti1.active_contact, total.active_contact);
}

TEST(HardCases, ManySmallSubdomainsMatchTheMonolithicReference) {
  // H/h = 4: 128 subdomains of 4 x 4 cells, 49 interior cross points per body.
  const int n = 32;
  const test::ReferenceSolution reference = test::membrane_reference(n);
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti}) {
    const FetiResult result = solve_membranes(test::membrane_subdomains(test::membrane_options(n, 8)), variant, 1e-10);
    ASSERT_EQ(result.status, SolveStatus::converged);
    EXPECT_NEAR(result.energy, reference.energy, 1e-8 * std::abs(reference.energy));
    EXPECT_EQ(result.active_contact, static_cast<int>(reference.active_y.size()));
  }
}

TEST(HardCases, InfeasibleSceneIsReportedNotIterated) {
  // The floating membrane's load reversed (pulling it off the contact line, the only thing
  // that could hold it): no equilibrium. Detected before any dual iteration, for a strong
  // pull and one of 1e-3, with both variants; the original load converges.
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti})
    for (double factor : {-1.0, -1e-3, 1.0}) {
      auto subs = test::membrane_subdomains(test::membrane_options(32, 2));
      for (auto& s : subs)
        if (s.body == 1) s.f *= factor;
      const FetiResult r = solve_membranes(std::move(subs), variant, 1e-6);
      if (factor > 0) {
        EXPECT_EQ(r.status, SolveStatus::converged);
        continue;
      }
      EXPECT_EQ(r.status, SolveStatus::infeasible) << "factor " << factor << ": " << to_string(r.status);
      EXPECT_EQ(r.counts.hessian, 0);
      EXPECT_GT(r.equality_norm, 1e-6 * r.equality_reference);  // the distance that cannot be closed
    }
}

TEST(HardCases, GapSweepShiftsTheFloatingMembraneExactly) {
  // The floating membrane rests on the contact line only, so a gap g (from penetrating to
  // separated) shifts it rigidly by -g: u_2 -> u_2 - g, the energy by g times its total
  // load, the contact set unchanged. Zero load: u = 0 at once.
  const auto solve_with_gap = [](double gap, double load_factor) {
    auto subs = test::membrane_subdomains(test::membrane_options(32, 2));
    for (auto& s : subs) s.f *= load_factor;
    ContactInput contact = test::membrane_contact(subs);
    contact.gap = gap;
    const FetiProblem problem(subs, contact, FetiSetupSettings{});
    DualSolveSettings settings;
    settings.tolerance = 1e-10;
    return std::make_pair(problem.solve(settings), subs);
  };
  const auto [reference, subs] = solve_with_gap(0.0, 1.0);
  ASSERT_EQ(reference.status, SolveStatus::converged);
  double load_on_floating = 0;
  for (const auto& s : subs)
    if (s.body == 1) load_on_floating += s.f.sum();
  for (double gap : {-0.01, 0.01, 0.1, 1.0}) {
    const FetiResult r = solve_with_gap(gap, 1.0).first;
    ASSERT_EQ(r.status, SolveStatus::converged) << "gap " << gap;
    EXPECT_NEAR(r.energy, reference.energy + gap * load_on_floating, 1e-9) << "gap " << gap;
    EXPECT_EQ(r.active_contact, reference.active_contact) << "gap " << gap;
    double shift_error = 0;
    for (size_t s = 0; s < subs.size(); ++s) {
      const Vec expected = subs[s].body == 1 ? Vec(reference.u[s].array() - gap) : reference.u[s];
      shift_error = std::max(shift_error, (r.u[s] - expected).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(shift_error, 1e-7 * (1 + std::abs(gap))) << "gap " << gap;
  }
  const FetiResult unloaded = solve_with_gap(0.0, 0.0).first;
  EXPECT_EQ(unloaded.status, SolveStatus::converged);
  EXPECT_LE(unloaded.counts.hessian, 1);
  for (const Vec& u : unloaded.u) EXPECT_EQ(u.cwiseAbs().maxCoeff(), 0.0);
}

}  // namespace
}  // namespace ffeti
