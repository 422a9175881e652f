// Numerically hard scenes stay stable under default options: extreme scaling of K and f,
// large stiffness contrast between bodies, H/h from 4 to 256, subdomains one element thick,
// cells of aspect ratio 100, a chain of floating bodies held only by contact, every couple
// active and none, an infeasible scene, a gap sweep and zero load, and Total FETI on them.
// Each is checked against an independent answer (a scaled solution, the other FETI
// variant, the bodies' equilibrium, or the monolithic active-set reference). Each case
// records a row of docs/results/hard-cases.md (scripts/hard_cases_table.py reads the rows
// from the XML output of `ffeti_unit_tests --gtest_filter=HardCases*:Extreme*`).
#include "feti/feti_problem.h"
#include "constraints/contact/node_to_node.h"
#include "hard_case_record.h"
#include "membrane_model.h"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

namespace ffeti {
namespace {

using test::record;

/// A number as a person writes it in a case name: 1e-12, 0.01, 1.
std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

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
    s.K.edit() *= factor;
    s.f *= factor;
  }
  const FetiResult reference = solve_membranes(reference_subs, FetiVariant::feti1, 1e-10);
  const FetiResult scaled = solve_membranes(scaled_subs, FetiVariant::feti1, 1e-10);
  ASSERT_EQ(scaled.status, SolveStatus::converged);
  record("K and f scaled by " + number(factor), scaled, relative_difference(scaled.u, reference.u, 1.0),
         "u against the unscaled solution", 1e-9);
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
  record("f scaled by " + number(factor), scaled, relative_difference(scaled.u, reference.u, factor),
         "u against factor x the unscaled solution", 1e-9);
  EXPECT_LT(relative_difference(scaled.u, reference.u, factor), 1e-7);  // contact with zero gap is homogeneous
}

INSTANTIATE_TEST_SUITE_P(Factors, ExtremeScaling, ::testing::Values(1e-12, 1e-6, 1e6, 1e12),
                         [](const auto& info) {
                           const int exponent = static_cast<int>(std::lround(std::log10(info.param)));
                           return std::string(exponent < 0 ? "1e_minus" : "1e") + std::to_string(std::abs(exponent));
                         });

TEST(HardCases, StiffnessContrastOfSixOrdersOfMagnitude) {
  // The equilibrium residual recomputed as K u - f + B'lambda has a round-off floor here:
  // K scaled by 1e6 times a floating body's rigid displacement of order 1 (1.3e-8, where
  // the solver's own check, exact from G lambda - e, sees 3e-11).
  auto subs = test::membrane_subdomains(test::membrane_options(16, 2));
  for (auto& s : subs)
    if (s.body == 1) s.K.edit() *= 1e6;  // a nearly rigid right membrane on a soft left one
  const FetiResult feti1 = solve_membranes(subs, FetiVariant::feti1, 1e-10);
  const FetiResult total = solve_membranes(subs, FetiVariant::tfeti, 1e-10);
  ASSERT_EQ(feti1.status, SolveStatus::converged);
  ASSERT_EQ(total.status, SolveStatus::converged);
  record("stiffness contrast 1e6 between bodies", feti1, std::abs(feti1.energy - total.energy) / std::abs(feti1.energy),
         "energy against Total FETI", 1e-7);
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
    record(std::string("H/h = 4, 128 subdomains, ") + (variant == FetiVariant::feti1 ? "FETI-1" : "Total FETI"), result,
           std::abs(result.energy - reference.energy) / std::abs(reference.energy), "energy against the active set reference", 1e-9);
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
      record(std::string("infeasible: floating load reversed x ") + number(-factor) +
             (variant == FetiVariant::feti1 ? ", FETI-1" : ", Total FETI"), r, 0.0, "status infeasible, no iteration", 0);
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
    contact.input_of<NodeToNodeInput>().gap = gap;
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
    record("gap " + number(gap), r, std::abs(r.energy - reference.energy - gap * load_on_floating),
           "energy against the rigid shift", 1e-9);
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
  double largest = 0;
  for (const Vec& u : unloaded.u) largest = std::max(largest, u.cwiseAbs().maxCoeff());
  record("zero load", unloaded, largest, "u = 0", 1e-9);
  EXPECT_EQ(unloaded.status, SolveStatus::converged);
  EXPECT_LE(unloaded.counts.hessian, 1);
  EXPECT_EQ(largest, 0.0);
}

TEST(HardCases, SubdomainSizeFromFourToTwoHundredFiftySixCells) {
  // The same discretization split ever finer: H/h = 256, 64, 16, 4 (2 to 2048 subdomains
  // at h = 1/128, h = 1/256 for H/h = 256), against the monolithic reference.
  for (const auto& [n, splits] : std::vector<std::pair<int, std::vector<int>>>{{256, {1}}, {128, {2, 8, 32}}}) {
    const test::ReferenceSolution reference = test::membrane_reference(n);
    for (int N : splits) {
      const FetiResult r =
          solve_membranes(test::membrane_subdomains(test::membrane_options(n, N)), FetiVariant::feti1, 1e-8);
      ASSERT_EQ(r.status, SolveStatus::converged) << "H/h " << n / N;
      const double error = std::abs(r.energy - reference.energy) / std::abs(reference.energy);
      record("H/h = " + std::to_string(n / N) + ", " + std::to_string(2 * N * N) + " subdomains", r, error,
             "energy against the active set reference", 1e-7);
      EXPECT_LT(error, 1e-7) << "H/h " << n / N;
      EXPECT_EQ(r.active_contact, static_cast<int>(reference.active_y.size())) << "H/h " << n / N;
    }
  }
}

/// The membranes on a grid of n cells across and ny cells up each body (cells of aspect
/// ratio n / ny), body 0 cut into horizontal strips `strip_cells` high, body 1 into 2 x 2
/// blocks.
std::vector<SubdomainInput> membranes_in_strips(int n, int strip_cells, int ny) {
  const auto load = [](double x, double y) {
    if (x < 1) return y > 0.75 ? -3.0 : 0.0;
    return y < 0.25 ? -1.0 : 0.0;
  };
  std::vector<SubdomainInput> subs;
  for (int j = 0; j < ny; j += strip_cells) {
    SubdomainInput s = test::p1_rectangle(0, double(j) / ny, 1, double(strip_cells) / ny, n, strip_cells, 2.0, load, 0);
    for (int k = 0; k < static_cast<int>(s.x.size()); ++k)
      if (s.x[k] == 0.0) s.dirichlet_dofs.push_back(k);
    subs.push_back(std::move(s));
  }
  for (int J = 0; J < 2; ++J)
    for (int I = 0; I < 2; ++I) subs.push_back(test::p1_rectangle(1 + 0.5 * I, 0.5 * J, 0.5, 0.5, n / 2, ny / 2, 2.0, load, 1));
  return subs;
}

TEST(HardCases, SubdomainsOneElementThick) {
  // Body 0 as 32 strips one cell high: every node of a strip lies on its boundary.
  const int n = 32;
  const test::ReferenceSolution reference = test::membrane_reference(n);
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti}) {
    const FetiResult r = solve_membranes(membranes_in_strips(n, 1, n), variant, 1e-8);
    ASSERT_EQ(r.status, SolveStatus::converged);
    const double error = std::abs(r.energy - reference.energy) / std::abs(reference.energy);
    record(std::string("32 strips one element thick, ") + (variant == FetiVariant::feti1 ? "FETI-1" : "Total FETI"), r,
           error, "energy against the active set reference", 1e-7);
    EXPECT_LT(error, 1e-7);
    EXPECT_EQ(r.active_contact, static_cast<int>(reference.active_y.size()));
  }
}

TEST(HardCases, CellsOfAspectRatioOneHundred) {
  // 200 x 2 cells per body: cells 1/200 wide and 1/2 high, split in strips of one cell
  // (left body) and 2 x 2 blocks (right body). Two variants must agree.
  const std::vector<SubdomainInput> subs = membranes_in_strips(200, 1, 2);
  const FetiResult feti1 = solve_membranes(subs, FetiVariant::feti1, 1e-8);
  const FetiResult total = solve_membranes(subs, FetiVariant::tfeti, 1e-8);
  ASSERT_EQ(feti1.status, SolveStatus::converged);
  ASSERT_EQ(total.status, SolveStatus::converged);
  const double error = std::abs(feti1.energy - total.energy) / std::abs(total.energy);
  record("cells of aspect ratio 100", feti1, error, "energy against Total FETI", 1e-7);
  EXPECT_LT(error, 1e-7);
  EXPECT_EQ(feti1.active_contact, total.active_contact);
  EXPECT_LT(feti1.kkt.max(), 1e-7);
}

TEST(HardCases, MeshGradedOneToOneThousand) {
  // Body 0 graded in x towards the contact line, its cells a thousandfold narrower there
  // than at x = 0 (x -> 1 - (e^{a(1-x)} - 1) / (e^a - 1)), 2 x 2 subdomains per body; both
  // FETI variants must agree.
  test::MembraneOptions o = test::membrane_options(64, 2);
  o.x_map = test::graded_towards_contact(64, 1000.0);
  const std::vector<SubdomainInput> subs = test::membrane_subdomains(o);
  double smallest = 1, largest = 0;
  for (const SubdomainInput& s : subs)
    if (s.body == 0)
      for (size_t k = 1; k < s.x.size(); ++k)
        if (s.x[k] > s.x[k - 1] && s.y[k] == s.y[k - 1]) {
          smallest = std::min(smallest, s.x[k] - s.x[k - 1]);
          largest = std::max(largest, s.x[k] - s.x[k - 1]);
        }
  EXPECT_GT(largest / smallest, 990);
  const FetiResult feti1 = solve_membranes(subs, FetiVariant::feti1, 1e-8);
  const FetiResult total = solve_membranes(subs, FetiVariant::tfeti, 1e-8);
  ASSERT_EQ(feti1.status, SolveStatus::converged);
  ASSERT_EQ(total.status, SolveStatus::converged);
  const double error = std::abs(feti1.energy - total.energy) / std::abs(total.energy);
  record("mesh graded 1:" + number(std::round(largest / smallest)), feti1, error, "energy against Total FETI", 1e-7);
  EXPECT_LT(error, 1e-7);
  EXPECT_EQ(feti1.active_contact, total.active_contact);
  EXPECT_LT(feti1.kkt.max(), 1e-7);
}

TEST(HardCases, EveryCoupleWeaklyActive) {
  // Mirror images: (0,1)^2 fixed at x = 0 and its mirror (1,2)x(0,1) fixed at x = 2, the
  // same load -1 on both: the membranes meet on x = 1 with zero gap and zero force, every
  // couple weakly active (closed, lambda = 0). u must be that of the bodies without
  // contact, the contact forces about zero.
  const auto membranes = [](bool with_contact) {
    const auto load = [](double, double) { return -1.0; };
    std::vector<SubdomainInput> subs;
    for (int body = 0; body < 2; ++body)
      for (int J = 0; J < 2; ++J)
        for (int I = 0; I < 2; ++I) {
          // Body 1 is body 0's mesh mirrored about x = 1 (x -> 2 - x): exact mirror images.
          SubdomainInput s = test::p1_rectangle(0.5 * I, 0.5 * J, 0.5, 0.5, 16, 16, 1.0, load, body,
                                                [body](double x) { return body == 0 ? x : 2.0 - x; });
          for (int k = 0; k < static_cast<int>(s.x.size()); ++k)
            if (s.x[k] == 2.0 * body) s.dirichlet_dofs.push_back(k);
          subs.push_back(std::move(s));
        }
    const ContactInput contact = with_contact ? test::membrane_contact(subs) : ContactInput{};
    const FetiProblem problem(subs, contact, FetiSetupSettings{});
    DualSolveSettings settings;
    settings.tolerance = 1e-8;
    FetiResult r = problem.solve(settings);
    double largest_load = 0, largest_contact_force = 0;  // nodal forces
    for (const SubdomainInput& s : subs) largest_load = std::max(largest_load, s.f.cwiseAbs().maxCoeff());
    for (int i = problem.constraints().equality_rows; i < problem.constraints().rows(); ++i)
      largest_contact_force = std::max(largest_contact_force, std::abs(r.lambda[i]));
    return std::make_tuple(std::move(r), largest_contact_force / largest_load);
  };
  const auto [touching, contact_force] = membranes(true);
  const FetiResult apart = std::get<0>(membranes(false));
  ASSERT_EQ(touching.status, SolveStatus::converged);
  ASSERT_EQ(apart.status, SolveStatus::converged);
  const double error = relative_difference(touching.u, apart.u, 1.0);
  record("every couple weakly active (closed, zero force)", touching, error, "u against the bodies without contact", 1e-7);
  EXPECT_LT(error, 1e-7);
  EXPECT_LT(contact_force, 1e-6) << "contact forces of a contact that carries nothing, relative to a nodal load";
}

TEST(HardCases, EveryCoupleActiveOrNone) {
  // Both membranes fixed (x = 0 and x = 2): with a wide gap no couple touches and the
  // bodies deform alone (against the scene without contact rows); with interference and
  // no load every couple is active and u is linear in the gap (gap -1 against gap -2).
  // (This scene starts from u = 0: it caught a stopping test that never re-measured ‖u‖.)
  const auto solve = [](double gap, double load_factor, bool with_contact) {
    test::MembraneOptions o = test::membrane_options(32, 2);
    o.fix_right_body = true;
    o.with_contact = with_contact;
    auto subs = test::membrane_subdomains(o);
    for (auto& s : subs) s.f *= load_factor;
    ContactInput contact = with_contact ? test::membrane_contact(subs) : ContactInput{};
    contact.input_of<NodeToNodeInput>().gap = gap;
    const FetiProblem problem(subs, contact, FetiSetupSettings{});
    DualSolveSettings settings;
    settings.tolerance = 1e-8;
    return std::make_pair(problem.solve(settings), problem.constraints().count(RowKind::contact));
  };
  const auto [apart, couples_apart] = solve(1.0, 1.0, true);
  const FetiResult alone = solve(0.0, 1.0, false).first;
  ASSERT_EQ(apart.status, SolveStatus::converged);
  ASSERT_EQ(alone.status, SolveStatus::converged);
  EXPECT_GT(couples_apart, 0);
  EXPECT_EQ(apart.active_contact, 0);
  const double apart_error = relative_difference(apart.u, alone.u, 1.0);
  record("no couple active (gap 1)", apart, apart_error, "u against the bodies without contact", 1e-7);
  EXPECT_LT(apart_error, 1e-7);

  const auto [pressed, couples] = solve(-1.0, 0.0, true);
  const FetiResult pressed_twice = solve(-2.0, 0.0, true).first;
  ASSERT_EQ(pressed.status, SolveStatus::converged);
  ASSERT_EQ(pressed_twice.status, SolveStatus::converged);
  EXPECT_EQ(pressed.active_contact, couples);
  const double linearity = relative_difference(pressed_twice.u, pressed.u, 2.0);
  record("every couple active (gap -1, no load)", pressed, linearity, "u against half the solution at gap -2", 1e-7);
  EXPECT_LT(linearity, 1e-7);
}

}  // namespace
}  // namespace ffeti
