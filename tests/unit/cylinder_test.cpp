// The rigid cylinder (constraints/contact/cylinder.h), a kind that owns its input: its rows'
// normal and gap outside and inside, the slip rows in its tangent plane, the rows' motion
// derivative against the analytic one, FETI with friction against the undivided problem's
// dual written here from the nodes' positions (another formula for the distance from the
// axis, another tangent basis: the axis and the turn about it), the sensitivity of a block
// pressed onto a shaft against finite differences of re-solves, its place in the registry
// and the refusals of bad input naming obstacleCylinder.
#include "constraints/contact/cylinder.h"
#include "constraints/contact/obstacle.h"
#include "constraints/input_checks.h"
#include "feti/feti_problem.h"
#include "sens/sensitivity.h"
#include "friction_scenes.h"
#include "refusal.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace ffeti {
namespace {

const ContactDiscretization& cylinder_unit() {
  for (const ContactDiscretization* unit : kinds_with_input())
    if (std::string(unit->input()->argument) == "obstacleCylinder") return *unit;
  throw std::logic_error("no obstacleCylinder in the registry");
}

/// [px, py, pz, ax, ay, az, radius, inside] through the unit, as both front ends read it.
ContactInput on_cylinder(const std::vector<SubdomainInput>& subdomains, const std::vector<double>& values) {
  ContactInput contact;
  contact.slave_dofs = bottom_dofs(subdomains);
  cylinder_unit().read_input(values, 3, contact);
  return contact;
}

Point3 unit(const Point3& v) {
  const double length = std::sqrt(dot(v, v));
  return {v[0] / length, v[1] / length, v[2] / length};
}

TEST(CylinderRows, TheNormalPointsFromTheAxisOutsideAndTowardsItInside) {
  // Axis through (1, 0, 0) along e_y + e_z: s's distance vector from it is r = (2, 0.5, -0.5).
  const Point3 s{3, 1, 0};
  for (const bool inside : {false, true}) {
    SCOPED_TRACE(inside ? "inside" : "outside");
    const CylinderShape shape{{1, 0, 0}, unit({0, 1, 1}), 2.5, inside};
    const CylinderGeometry g(ContactKind{0}, {{{0, 0}, {0, 1}, {0, 2}}}, s, shape);
    const double rho = std::sqrt(4.5), sign = inside ? -1 : 1;
    const Point3 n = g.normal(), expected{sign * 2 / rho, sign * 0.5 / rho, -sign * 0.5 / rho};
    for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(n[i], expected[i], 1e-15);
    const RowAt row = g.row_at({}, 0);
    EXPECT_NEAR(row.gap, inside ? 2.5 - rho : rho - 2.5, 1e-15);
    for (size_t i = 0; i < 3; ++i) EXPECT_NEAR(row.coefficients[i], -n[i], 1e-15);
    EXPECT_EQ(row.dofs, (std::vector<DofRef>{{0, 0}, {0, 1}, {0, 2}}));
    // Moving along the axis changes nothing.
    const RowAt along = g.row_at({shape.axis}, 0.7);
    EXPECT_NEAR(along.gap, row.gap, 1e-14);
  }
}

TEST(CylinderRows, TheSlipRowsSpanItsTangentPlane) {
  const CylinderShape shape{{0, 0, -1}, unit({1, 2, 0}), 0.5, false};
  const CylinderGeometry g(ContactKind{0}, {{{0, 0}, {0, 1}, {0, 2}}}, {0.3, 0.1, 0.2}, shape);
  const std::vector<RowAt> rows = g.slip_rows();
  ASSERT_EQ(rows.size(), 2u);
  const Point3 n = g.normal();
  std::vector<Point3> t;
  for (const RowAt& row : rows) {
    ASSERT_EQ(row.coefficients.size(), 3u);
    t.push_back({row.coefficients[0], row.coefficients[1], row.coefficients[2]});
    EXPECT_NEAR(dot(t.back(), n), 0, 1e-14);
    EXPECT_NEAR(dot(t.back(), t.back()), 1, 1e-14);
    EXPECT_EQ(row.gap, 0);
  }
  EXPECT_NEAR(dot(t[0], t[1]), 0, 1e-14);
}

TEST(CylinderRows, TheRowsMotionDerivativeIsTheAnalyticOne) {
  // n = sign r/rho: dn = sign (Pv - (n.Pv) n)/rho with P = I - e e', d gap = n.v.
  const Point3 s{0.4, -0.3, 0.9}, v{0.2, -0.7, 0.5};
  for (const bool inside : {false, true}) {
    SCOPED_TRACE(inside ? "inside" : "outside");
    const CylinderShape shape{{0.1, 0.2, -0.3}, unit({0.3, 1, -0.4}), 0.8, inside};
    const CylinderGeometry g(ContactKind{0}, {{{0, 0}, {0, 1}, {0, 2}}}, s, shape);
    const double h = difference_step(g, {v});
    ASSERT_GT(h, 0);
    const RowAt plus = g.row_at({v}, h), minus = g.row_at({v}, -h);
    const Point3 n = g.normal(), e = shape.axis;
    const double rho = shape.axis_distance(s), sign = inside ? -1 : 1;
    Point3 pv = v;
    for (size_t i = 0; i < 3; ++i) pv[i] -= dot(v, e) * e[i];
    EXPECT_NEAR((plus.gap - minus.gap) / (2 * h), dot(n, v), 1e-8);
    for (size_t i = 0; i < 3; ++i) {
      const double dn = sign * (pv[i] - dot(n, pv) * n[i]) / rho;
      EXPECT_NEAR((plus.coefficients[i] - minus.coefficients[i]) / (2 * h), -dn, 1e-8) << i;
    }
  }
}

// ---- FETI with friction against the undivided dual ----------------------------------------

std::vector<SubdomainInput> block_halves() {
  return {solid_block(0, {0.5, 0.5, 0.25}, {2, 2, 1}, kTop3), solid_block(0.5, {0.5, 0.5, 0.25}, {2, 2, 1}, kTop3)};
}

/// A shaft of radius 5 under the block, its axis tilted in the horizontal plane, the block's
/// bottom centre kGap above it; and a hole of radius 5 along x, the block on its floor.
const std::vector<double> kShaft{0.5, 0.25, -5 - kGap, 0.3, 1, 0, 5};
const std::vector<double> kHole{0, 0.25, 5 - kGap, 1, 0, 0, 5, 1};

/// The dual of the whole block (one subdomain) with the rows written from each bottom node's
/// position p: its distance vector from the axis r = e x ((p - a) x e), the normal +-r/|r|,
/// the gap +-(|r| - R), the tangents e and n x e.
std::vector<NodeForces> cylinder_reference(const std::vector<double>& c, const RowBound& bound) {
  const SubdomainInput block = solid_block(0, {1, 0.5, 0.25}, {4, 2, 1}, kTop3);
  const Point3 a{c[0], c[1], c[2]}, e = unit({c[3], c[4], c[5]});
  const double radius = c[6], sign = c.size() > 7 && c[7] == 1 ? -1 : 1;
  std::vector<ReferenceRow> rows;
  std::vector<std::array<double, 2>> at;
  std::vector<std::vector<Point3>> tangents;
  for (int node = 0; node < 15; ++node) {  // the face z = 0
    const auto dof = static_cast<size_t>(3 * node);
    at.push_back({block.x[dof], block.y[dof]});
    const Point3 r = cross(e, cross(minus({block.x[dof], block.y[dof], 0}, a), e));
    const double distance = std::sqrt(dot(r, r));
    const Point3 normal{sign * r[0] / distance, sign * r[1] / distance, sign * r[2] / distance};
    const Point3 around = cross(normal, e);
    const auto on_slave = [&](const Point3& v, double factor) {
      Vec row = Vec::Zero(block.K.rows());
      for (size_t i = 0; i < 3; ++i) row[static_cast<Eigen::Index>(dof + i)] = factor * v[i];
      return row;
    };
    rows.push_back({on_slave(normal, -1), sign * (distance - radius), {on_slave(e, 1), on_slave(around, 1)},
                    bound(at.back())});
    tangents.push_back({e, around});
  }
  return reference_forces(
      friction_dual(Eigen::MatrixXd(block.K.get()), block.f, block.dirichlet_dofs, block.dirichlet_values, rows), at,
      tangents);
}

class CylinderFriction : public FrictionVariants {};

TEST_P(CylinderFriction, AShaftAndAHoleMatchTheUndividedDual) {
  const auto subdomains = block_halves();
  for (const auto* cylinder : {&kShaft, &kHole}) {
    SCOPED_TRACE(cylinder == &kShaft ? "shaft" : "hole");
    const auto tangents = [&](const FetiProblem& p) {
      return [&p](int row) {
        const auto pair = p.constraints().geometry[static_cast<size_t>(row)]->tangents();
        return std::vector<Point3>{pair[0], pair[1]};
      };
    };
    const auto reference = [&](const RowBound& bound) { return cylinder_reference(*cylinder, bound); };
    for (const double bound : {0.2, 100.0}) {
      SCOPED_TRACE("slip bound " + std::to_string(bound));
      ContactInput contact = on_cylinder(subdomains, *cylinder);
      tresca(bound)(contact);
      const FetiProblem p(subdomains, contact, setup());
      ASSERT_GT(p.constraints().count(RowKind::contact), 0);
      expect_reference(p, false, bound, tangents(p), reference, false);
    }
    ContactInput contact = on_cylinder(subdomains, *cylinder);
    coulomb(0.1)(contact);
    const FetiProblem p(subdomains, contact, setup());
    expect_reference(p, true, 0.1, tangents(p), reference, false);
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, CylinderFriction, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

// ---- sensitivity: the block's nodes moved, the shaft still ----------------------------------

TEST(CylinderSensitivity, MovingTheSlavesMatchesFiniteDifferencesOfReSolves) {
  // V = (0, 0, 0.2 x): the bottom tilts over the shaft (K is the design's data, unchanged).
  const auto base = block_halves();
  const ContactInput contact = on_cylinder(base, kShaft);
  const auto velocity = [&](size_t s) {
    std::vector<double> v;
    for (double x : base[s].x) v.push_back(0.2 * x);
    return v;
  };
  const auto at = [&](double t) {
    auto subs = base;
    for (size_t s = 0; s < subs.size(); ++s)
      for (size_t k = 0; k < subs[s].z.size(); ++k) subs[s].z[k] += t * velocity(s)[k];
    return subs;
  };
  const FetiProblem problem(at(0), contact);
  const FetiResult state = problem.solve(tight());
  ASSERT_EQ(state.status, SolveStatus::converged);
  SensitivityProblem sensitivity(problem, state, 1e-8);
  ASSERT_GT(sensitivity.classification().strong.size(), 2u);
  EXPECT_TRUE(sensitivity.classification().weak.empty());
  DesignDerivative d;
  for (size_t s = 0; s < base.size(); ++s) {
    d.velocity_x.emplace_back(base[s].x.size(), 0.0);
    d.velocity_y.emplace_back(base[s].x.size(), 0.0);
    d.velocity_z.push_back(velocity(s));
  }
  const SensitivityResult z = sensitivity.direct(d, tight());
  ASSERT_EQ(z.status, SolveStatus::converged);
  const double h = 1e-5;
  const auto plus = FetiProblem(at(h), contact).solve(tight()).u, minus = FetiProblem(at(-h), contact).solve(tight()).u;
  double difference = 0, size = 0;
  for (size_t s = 0; s < plus.size(); ++s) {
    const Vec fd = (plus[s] - minus[s]) / (2 * h);
    difference += (z.z[s] - fd).squaredNorm();
    size += fd.squaredNorm();
  }
  ASSERT_GT(size, 0);
  EXPECT_LT(std::sqrt(difference / size), 1e-5);
}

// ---- the registry and bad input ------------------------------------------------------------

TEST(CylinderRegistry, ItsRowItsArgumentAndItsKeyComeFromItsUnit) {
  const ContactDiscretization& cylinder = cylinder_unit();
  const KindCapabilities& row = capability_table().at(static_cast<size_t>(cylinder.kind()));
  EXPECT_STREQ(row.name, "cylinder");
  EXPECT_TRUE(supports(cylinder.kind(), Feature::friction, 3));
  EXPECT_TRUE(supports(cylinder.kind(), Feature::ffeti_solve, 3));
  EXPECT_FALSE(supports(cylinder.kind(), Feature::rows, 2));
  EXPECT_STREQ(cylinder.input()->file_key, "cylinder");
  EXPECT_NE(capability_table_markdown().find("| cylinder | `contactSlave, obstacleCylinder` | — | yes |"),
            std::string::npos);
}

TEST(CylinderInput, BadEntriesAreErrorsNamingObstacleCylinder) {
  const auto check = [](std::vector<double> values, int dimension = 3) {
    ContactInput contact;
    return refusal([&] { cylinder_unit().read_input(values, dimension, contact); });
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(check({0, 0, 0, 0, 0, 0, 1}), "obstacleCylinder: the axis [ax, ay, az] must not be zero");
  EXPECT_EQ(check({0, 0, 0, 0, 0, 1, -1}), "obstacleCylinder: the radius must be > 0, got -1.000000");
  EXPECT_EQ(check({0, 0, 0, 0, 0, 1, 0}), "obstacleCylinder: the radius must be > 0, got 0.000000");
  EXPECT_EQ(check({0, nan, 0, 0, 0, 1, 1}), "obstacleCylinder: entry 1 (py) is nan, it must be finite");
  EXPECT_EQ(check({0, 0, 0, 0, 0, 1, 1, 2}),
            "obstacleCylinder: inside must be 1 (the bodies in the cylinder) or 0 (outside it), got 2.000000");
  EXPECT_EQ(check({0, 0, 0, 0, 0, 1}).rfind("obstacleCylinder: needs [px, py, pz, ax, ay, az, radius]", 0), 0u);
  EXPECT_EQ(check({0, 0, 0, 0, 0, 1, 1}, 2),
            "obstacleCylinder: cylinder contact does not support plane problems yet (see the capability table in "
            "docs/reference.md)");
  // Given twice; with another kind for the same slaves (validate_input).
  ContactInput twice;
  cylinder_unit().read_input(kShaft, 3, twice);
  EXPECT_EQ(refusal([&] { cylinder_unit().read_input(kShaft, 3, twice); }),
            "obstacleCylinder: given twice (one cylinder per problem)");
  auto subdomains = block_halves();
  ContactInput with_plane = on_cylinder(subdomains, kShaft);
  with_plane.input_of<ObstacleInput>().given = true;
  with_plane.input_of<ObstacleInput>().normal = {0, 0, 1};
  EXPECT_EQ(refusal([&] { validate_input(subdomains, with_plane); }),
            "obstacleCylinder, obstacle: the slave nodes of contactSlave take one kind of contact; give one");
  // Parameters set directly (not through read_input) are checked by validate_input as well.
  ContactInput direct;
  direct.kind_parameters[cylinder_unit().kind()] = {0, 0, 0, 0, 0, 1, -2};
  EXPECT_EQ(refusal([&] { validate_input(subdomains, direct); }), "obstacleCylinder: the radius must be > 0, got -2.000000");
}

TEST(CylinderInput, ASlaveOnTheAxisIsRefused) {
  const auto subdomains = block_halves();
  // The axis along x through the bottom's edge y = 0, z = 0: those slaves have no normal.
  EXPECT_EQ(refusal([&] { FetiProblem(subdomains, on_cylinder(subdomains, {0, 0, 0, 1, 0, 0, 1})); }),
            "obstacleCylinder: the slave node at (0, 0, 0) lies on the cylinder's axis: it has no normal");
}

}  // namespace
}  // namespace ffeti
