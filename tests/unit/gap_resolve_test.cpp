// New contact gaps on a set-up problem (FetiProblem::set_contact_gaps, fetiSetLoads's
// contactGap=): the re-solve equals a fresh set-up with those gaps, with no new
// factorization, for every contact kind that reads contactGap (node to node, node to
// segment, line and disc obstacles in the plane; node to node, node to face, mortar and a
// plane obstacle in three dimensions; with Tresca friction too, the gaps given before any
// new load step), in FETI-1 and Total FETI; the sensitivities of the re-solved state are
// those of the fresh one.
#include "base/errors.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/mortar.h"
#include "constraints/contact/node_to_segment.h"
#include "constraints/contact/node_to_node.h"
#include "constraints/contact/obstacle.h"
#include "factor/cholmod_factor.h"
#include "friction_scenes.h"
#include "sens/sensitivity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace ffeti {
namespace {

/// A gap per dof from its node's x: 0.003 (1 + cos(pi x)), up to 0.006 against the plates'
/// and blocks' push of 0.01: the contact forces change by far more than the comparison's
/// tolerance (the active sets of these small scenes stay).
std::vector<std::vector<double>> gap_profile(const std::vector<SubdomainInput>& subdomains) {
  std::vector<std::vector<double>> field;
  for (const SubdomainInput& s : subdomains) {
    field.emplace_back(s.x.size());
    for (size_t i = 0; i < s.x.size(); ++i) field.back()[i] = 0.003 * (1 + std::cos(M_PI * s.x[i]));
  }
  return field;
}

/// Per subdomain the dofs of every component of the nodes on the plane where coordinate
/// `axis` is 0 (slaves of the kinds that take a whole node).
std::vector<std::vector<int>> nodes_on_zero(const std::vector<SubdomainInput>& subdomains, int axis, int body) {
  const int components = axis == 2 ? 3 : 2;
  std::vector<std::vector<int>> out(subdomains.size());
  for (int c = 0; c < components; ++c) {
    const auto on = dofs_on_zero(subdomains, axis, c);
    for (size_t s = 0; s < subdomains.size(); ++s)
      if (subdomains[s].body == body) out[s].insert(out[s].end(), on[s].begin(), on[s].end());
  }
  for (auto& dofs : out) std::sort(dofs.begin(), dofs.end());
  return out;
}

struct Scene {
  std::string name;
  std::vector<SubdomainInput> subdomains;
  ContactInput contact;
};

ContactInput node_to_node(const std::vector<SubdomainInput>& subdomains, int axis) {
  ContactInput contact;
  const auto on_face = dofs_on_zero(subdomains, axis, axis);
  for (size_t s = 0; s < subdomains.size(); ++s) {
    contact.slave_dofs.push_back(subdomains[s].body == 1 ? on_face[s] : std::vector<int>{});
    contact.input_of<NodeToNodeInput>().masters.push_back(subdomains[s].body == 0 ? on_face[s] : std::vector<int>{});
  }
  return contact;
}

/// The lower plate's nodes on y = 0 slave, the upper plate's bottom edge master segments
/// (a -> b along +x: the upper body on the left).
ContactInput node_to_segment(const std::vector<SubdomainInput>& plates) {
  ContactInput contact;
  contact.slave_dofs = nodes_on_zero(plates, 1, 1);
  const auto x_dofs = dofs_on_zero(plates, 1, 0);
  for (size_t s = 0; s < plates.size(); ++s) {
    contact.input_of<NodeToSegmentInput>().segments.emplace_back();
    if (plates[s].body != 0) continue;
    for (size_t k = 0; k + 1 < x_dofs[s].size(); ++k) {
      const int a = x_dofs[s][k], b = x_dofs[s][k + 1];  // ascending x along the edge
      contact.input_of<NodeToSegmentInput>().segments.back().push_back({a, a + 1, b, b + 1});
    }
  }
  return contact;
}

/// The triangles of the face z = 0 of stacked_blocks(parts): Kuhn's cut of each square
/// along (i, j) -> (i + 1, j + 1), 9 dofs each, outward +z for the lower body (slave side of
/// mortar) and -z for the upper (master faces).
std::vector<std::array<int, 9>> face_triangles(int nx, int ny, bool upward) {
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  std::vector<std::array<int, 9>> out;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      for (std::array<int, 3> t : {std::array<int, 3>{id(i, j), id(i + 1, j), id(i + 1, j + 1)},
                                   std::array<int, 3>{id(i, j), id(i + 1, j + 1), id(i, j + 1)}}) {
        if (!upward) std::swap(t[1], t[2]);
        std::array<int, 9> dofs;
        for (size_t k = 0; k < 9; ++k) dofs[k] = 3 * t[k / 3] + static_cast<int>(k % 3);
        out.push_back(dofs);
      }
  return out;
}

/// Node to face (the lower block's nodes against the upper's faces) or mortar (the lower
/// block's faces against the upper's).
ContactInput on_faces(const std::vector<SubdomainInput>& blocks, int parts, bool mortar) {
  ContactInput contact;
  for (const SubdomainInput& s : blocks) {
    contact.input_of<NodeToFaceInput>().faces.push_back(s.body == 0 ? face_triangles(4 / parts, 2, false) : std::vector<std::array<int, 9>>{});
    if (mortar)
      contact.input_of<MortarInput>().slave_faces.push_back(s.body == 1 ? face_triangles(4 / parts, 2, true) : std::vector<std::array<int, 9>>{});
  }
  if (!mortar) contact.slave_dofs = nodes_on_zero(blocks, 2, 1);
  return contact;
}

std::vector<SubdomainInput> upper_body(std::vector<SubdomainInput> all) {
  std::vector<SubdomainInput> upper;
  for (SubdomainInput& s : all)
    if (s.body == 0) upper.push_back(std::move(s));
  return upper;
}

/// Rigid obstacles under the upper body alone: a line or plane at 0, or (radius > 0, a
/// plane problem) a disc touching it at x = 0.5.
ContactInput obstacle(const std::vector<SubdomainInput>& upper, int axis, double radius) {
  ContactInput contact;
  contact.slave_dofs = nodes_on_zero(upper, axis, 0);
  if (radius > 0) {
    contact.kind_parameters[ContactKind::ball] = {0.5, -radius, radius};
    return contact;
  }
  contact.input_of<ObstacleInput>().given = true;
  contact.input_of<ObstacleInput>().point = {0.5, 0.0, 0.0};
  contact.input_of<ObstacleInput>().normal = {0, 0, 0};
  contact.input_of<ObstacleInput>().normal[static_cast<size_t>(axis)] = 1;
  return contact;
}

/// `contact` with Tresca friction (bound 0.5 per row): the gaps then enter the contact rows
/// and leave the friction rows alone.
ContactInput with_tresca(ContactInput contact) {
  contact.slip_bound = 0.5;
  return contact;
}

std::vector<Scene> scenes() {
  const auto plates = stacked_plates(2), blocks = stacked_blocks(2);
  return {
      {"node to node, plane, Tresca", plates, with_tresca(node_to_node(plates, 1))},
      {"mortar, Tresca", blocks, with_tresca(on_faces(blocks, 2, true))},
      {"node to node, plane", plates, node_to_node(plates, 1)},
      {"node to segment", plates, node_to_segment(plates)},
      {"line obstacle", upper_body(plates), obstacle(upper_body(plates), 1, 0)},
      {"disc obstacle", upper_body(plates), obstacle(upper_body(plates), 1, 2.0)},
      {"node to node, 3D", blocks, node_to_node(blocks, 2)},
      {"node to face", blocks, on_faces(blocks, 2, false)},
      {"mortar", blocks, on_faces(blocks, 2, true)},
      {"plane obstacle", upper_body(blocks), obstacle(upper_body(blocks), 2, 0)},
  };
}

/// Largest entry of |a - b| over the subdomains, and of |b|.
std::pair<double, double> difference(const std::vector<Vec>& a, const std::vector<Vec>& b) {
  double error = 0, scale = 0;
  for (size_t s = 0; s < a.size(); ++s) {
    error = std::max(error, (a[s] - b[s]).cwiseAbs().maxCoeff());
    scale = std::max(scale, b[s].cwiseAbs().maxCoeff());
  }
  return {error, scale};
}

class GapResolve : public FrictionVariants {};

TEST_P(GapResolve, EqualsAFreshSetUpWithTheNewGapsWithoutANewFactorization) {
  for (const Scene& scene : scenes()) {
    SCOPED_TRACE(scene.name);
    FetiProblem problem(scene.subdomains, scene.contact, setup());
    const FetiResult before = problem.solve(tight());
    ASSERT_EQ(before.status, SolveStatus::converged);
    const long factorizations = CholmodFactor::factorizations_in_process();
    const long problem_factorizations = problem.factorizations();

    const auto gaps = gap_profile(scene.subdomains);
    problem.set_contact_gaps(gaps);
    const FetiResult resolved = problem.solve(tight());
    EXPECT_EQ(CholmodFactor::factorizations_in_process(), factorizations);  // nothing factorized again
    EXPECT_EQ(problem.factorizations(), problem_factorizations);

    ContactInput with_gaps = scene.contact;
    with_gaps.gap_field = gaps;
    const FetiProblem fresh(scene.subdomains, with_gaps, setup());
    const FetiResult expected = fresh.solve(tight());
    ASSERT_EQ(resolved.status, SolveStatus::converged);
    ASSERT_EQ(expected.status, SolveStatus::converged);
    EXPECT_EQ(problem.constraints().rhs, fresh.constraints().rhs);
    const double lambda_scale = expected.lambda.cwiseAbs().maxCoeff();
    EXPECT_LE((resolved.lambda - expected.lambda).cwiseAbs().maxCoeff(), 1e-10 * lambda_scale);
    const auto [u_error, u_scale] = difference(resolved.u, expected.u);
    EXPECT_LE(u_error, 1e-10 * u_scale);
    EXPECT_NEAR(resolved.energy, expected.energy, 1e-10 * std::abs(expected.energy));
    EXPECT_EQ(resolved.active_contact, expected.active_contact);
    // The gaps changed the answer: the comparison can fail.
    EXPECT_GT((resolved.lambda - before.lambda).cwiseAbs().maxCoeff(), 1e-3 * lambda_scale);
  }
}

TEST_P(GapResolve, SensitivitiesAfterAReSolveAreThoseOfTheNewState) {
  for (const Scene& scene : scenes()) {
    // Mortar rows take no sensitivities yet, and friction's follow another test (capability table).
    if (scene.name.find("mortar") != std::string::npos || scene.contact.has_friction()) continue;
    SCOPED_TRACE(scene.name);
    FetiProblem problem(scene.subdomains, scene.contact, setup());
    ASSERT_EQ(problem.solve(tight()).status, SolveStatus::converged);
    const auto gaps = gap_profile(scene.subdomains);
    problem.set_contact_gaps(gaps);
    const FetiResult resolved = problem.solve(tight());
    ContactInput with_gaps = scene.contact;
    with_gaps.gap_field = gaps;
    const FetiProblem fresh(scene.subdomains, with_gaps, setup());
    const FetiResult expected = fresh.solve(tight());

    DesignDerivative direction;  // the profile's own rate
    direction.dgap = gaps;
    SensitivityProblem of_resolved(problem, resolved, 1e-6), of_fresh(fresh, expected, 1e-6);
    EXPECT_EQ(of_resolved.classification().strong, of_fresh.classification().strong);
    EXPECT_EQ(of_resolved.classification().weak, of_fresh.classification().weak);
    const SensitivityResult a = of_resolved.direct(direction, tight()), b = of_fresh.direct(direction, tight());
    ASSERT_EQ(a.status, SolveStatus::converged);
    ASSERT_EQ(b.status, SolveStatus::converged);
    const double scale = b.contact_multipliers.cwiseAbs().maxCoeff();
    EXPECT_GT(scale, 0);
    EXPECT_LE((a.contact_multipliers - b.contact_multipliers).cwiseAbs().maxCoeff(), 1e-10 * scale);
    const auto [z_error, z_scale] = difference(a.z, b.z);
    EXPECT_LE(z_error, 1e-10 * z_scale);
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, GapResolve, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

TEST(GapResolveInput, WrongSizesAreErrorsNamingContactGap) {
  const auto plates = stacked_plates(2);
  FetiProblem problem(plates, node_to_node(plates, 1));
  auto gaps = gap_profile(plates);
  gaps.pop_back();
  EXPECT_THROW(
      {
        try {
          problem.set_contact_gaps(gaps);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("contactGap: has 3 entries for 4 subdomains"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
  gaps = gap_profile(plates);
  gaps[1].pop_back();
  EXPECT_THROW(problem.set_contact_gaps(gaps), InputError);
  gaps = gap_profile(plates);
  gaps[2][0] = NAN;
  EXPECT_THROW(problem.set_contact_gaps(gaps), InputError);
}

}  // namespace
}  // namespace ffeti
