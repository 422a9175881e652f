// Friction on node-to-node contact (plane and 3D) and on a rigid ball (3D): FETI in several
// subdomains against the undivided problem's dual solved densely by accelerated projected
// gradient (friction_reference.h), whose rows are written here from the nodes' positions;
// the slip rows' structure; the refusals of node-to-node friction without tangential dofs.
#include "constraints/constraints.h"
#include "constraints/contact/ball.h"
#include "constraints/contact/node_to_node.h"
#include "feti/feti_problem.h"
#include "feti/friction.h"
#include "base/errors.h"
#include "friction_scenes.h"
#include "membrane_model.h"
#include "plane_block.h"
#include "refusal.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace ffeti {
namespace {

// ---- Node to node in three dimensions: a block pressed and sheared onto another ----------

class FrictionKinds : public FrictionVariants {};

/// The lower body's dofs of component `axis` on the plane where that coordinate is 0 slave
/// (u_lower - u_upper <= kGap), the upper's master: z in 3D (axis 2), y in the plane (axis 1).
ContactInput stacked_contact(const std::vector<SubdomainInput>& subdomains, int axis, const Law& law) {
  ContactInput contact;
  const auto on_face = dofs_on_zero(subdomains, axis, axis);
  for (size_t s = 0; s < subdomains.size(); ++s) {
    contact.slave_dofs.push_back(subdomains[s].body == 1 ? on_face[s] : std::vector<int>{});
    contact.input_of<NodeToNodeInput>().masters.push_back(subdomains[s].body == 0 ? on_face[s] : std::vector<int>{});
  }
  contact.input_of<NodeToNodeInput>().gap = kGap;
  law(contact);
  return contact;
}

/// The row's normal is n = -e_z (out of the upper block, the master): t1 = e_x, t2 = n x e_x = -e_y.
std::vector<Point3> node_to_node_3d_tangents(int) { return {{1, 0, 0}, {0, -1, 0}}; }

std::vector<NodeForces> stacked_reference(const RowBound& bound) {
  const SubdomainInput upper = stacked_blocks(1)[0], lower = stacked_blocks(1)[1];
  const Undivided u = side_by_side(upper, lower);
  std::vector<ReferenceRow> rows;
  std::vector<std::array<double, 2>> at;
  std::vector<std::vector<Point3>> tangents;
  for (int node = 0; node < 15; ++node) {  // the face z = 0: nodes 0..14 of both blocks
    const Eigen::Index a = 3 * node, b = u.offset + 3 * node;
    const auto row_vector = [&](Eigen::Index lower_dof, Eigen::Index upper_dof, double sign) {
      Vec v = Vec::Zero(u.K.rows());
      v[lower_dof] = sign, v[upper_dof] = -sign;
      return v;
    };
    at.push_back({upper.x[static_cast<size_t>(a)], upper.y[static_cast<size_t>(a)]});
    rows.push_back({row_vector(b + 2, a + 2, 1), kGap, {row_vector(b, a, 1), row_vector(b + 1, a + 1, -1)}, bound(at.back())});
    tangents.push_back({{1, 0, 0}, {0, -1, 0}});
  }
  return reference_forces(friction_dual(u.K, u.f, u.fixed, u.values, rows), at, tangents);
}

TEST_P(FrictionKinds, NodeToNode3DRowsSlipAlongTheOtherTwoComponents) {
  const auto subdomains = stacked_blocks(2);
  const FetiProblem p(subdomains, stacked_contact(subdomains, 2, tresca(0.1)), setup());
  const Constraints& c = p.constraints();
  ASSERT_EQ(c.contact_rows(), 15);
  ASSERT_EQ(c.friction_rows, 30);
  for (int t = 0; t < c.friction_rows; ++t) {
    const auto row = static_cast<size_t>(c.first_friction_row() + t);
    ASSERT_EQ(c.row_start[row + 1] - c.row_start[row], 2) << "the slave's and the master's dof";
    for (int e = c.row_start[row]; e < c.row_start[row + 1]; ++e) {
      const ConstraintEntry& entry = c.entries[static_cast<size_t>(e)];
      const SubdomainInput& s = subdomains[static_cast<size_t>(entry.subdomain)];
      EXPECT_EQ(s.component[static_cast<size_t>(entry.dof)], t % 2) << "t1 = e_x, t2 = -e_y";
      EXPECT_EQ(entry.coefficient, (s.body == 1 ? 1.0 : -1.0) * (t % 2 == 0 ? 1.0 : -1.0));
    }
  }
}

TEST_P(FrictionKinds, NodeToNode3DMatchesTheUndividedDual) {
  const auto subdomains = stacked_blocks(2);
  for (const double bound : {0.05, 0.15, 100.0}) {
    SCOPED_TRACE("slip bound " + std::to_string(bound));
    const FetiProblem p(subdomains, stacked_contact(subdomains, 2, tresca(bound)), setup());
    expect_reference(p, false, bound, node_to_node_3d_tangents, stacked_reference, bound == 0.15);
  }
  const FetiProblem p(subdomains, stacked_contact(subdomains, 2, coulomb(0.1)), setup());
  expect_reference(p, true, 0.1, node_to_node_3d_tangents, stacked_reference, false);
}

// ---- Node to node in the plane: a block pressed and dragged over another -----------------

/// n = -e_y: t = (-n_y, n_x) = e_x.
std::vector<Point3> node_to_node_2d_tangent(int) { return {{1, 0, 0}}; }

std::vector<NodeForces> plate_reference(const RowBound& bound) {
  const auto plates = stacked_plates(1);
  const Undivided u = side_by_side(plates[0], plates[1]);
  std::vector<ReferenceRow> rows;
  std::vector<std::array<double, 2>> at;
  for (int node = 0; node < 5; ++node) {  // the edge y = 0: nodes 0..4 of both plates
    const Eigen::Index a = 2 * node, b = u.offset + 2 * node;
    Vec normal = Vec::Zero(u.K.rows()), slip = Vec::Zero(u.K.rows());
    normal[b + 1] = 1, normal[a + 1] = -1;
    slip[b] = 1, slip[a] = -1;
    at.push_back({plates[0].x[static_cast<size_t>(a)], 0});
    rows.push_back({normal, kGap, {slip}, bound(at.back())});
  }
  return reference_forces(friction_dual(u.K, u.f, u.fixed, u.values, rows), at,
                          std::vector<std::vector<Point3>>(5, {{1, 0, 0}}));
}

TEST_P(FrictionKinds, NodeToNodeInThePlaneMatchesTheUndividedDual) {
  const auto subdomains = stacked_plates(2);
  for (const double bound : {0.1, 0.3, 100.0}) {
    SCOPED_TRACE("slip bound " + std::to_string(bound));
    const FetiProblem p(subdomains, stacked_contact(subdomains, 1, tresca(bound)), setup());
    expect_reference(p, false, bound, node_to_node_2d_tangent, plate_reference, bound == 0.3);
  }
  const FetiProblem p(subdomains, stacked_contact(subdomains, 1, coulomb(0.2)), setup());
  expect_reference(p, true, 0.2, node_to_node_2d_tangent, plate_reference, false);
}

// ---- A rigid ball in three dimensions: a block pressed and sheared onto it ----------------

constexpr double kRadius = 10;
const Point3 kCentre{0.5, 0.25, -kRadius - kGap};

std::vector<SubdomainInput> block_halves() {
  return {solid_block(0, {0.5, 0.5, 0.25}, {2, 2, 1}, kTop3), solid_block(0.5, {0.5, 0.5, 0.25}, {2, 2, 1}, kTop3)};
}

ContactInput on_ball(const std::vector<SubdomainInput>& subdomains, const Law& law) {
  ContactInput contact;
  contact.slave_dofs = bottom_dofs(subdomains);
  contact.kind_parameters[ContactKind::ball] = {kCentre[0], kCentre[1], kCentre[2], kRadius};
  law(contact);
  return contact;
}

Point3 ball_normal(const std::array<double, 2>& at) {
  const Point3 d{at[0] - kCentre[0], at[1] - kCentre[1], -kCentre[2]};
  const double length = std::sqrt(dot(d, d));
  return {d[0] / length, d[1] / length, d[2] / length};
}

std::vector<NodeForces> ball_reference(const RowBound& bound) {
  const SubdomainInput block = solid_block(0, {1, 0.5, 0.25}, {4, 2, 1}, kTop3);
  const Eigen::Index n = block.K.rows();
  std::vector<ReferenceRow> rows;
  std::vector<std::array<double, 2>> at;
  std::vector<std::vector<Point3>> tangents;
  for (int node = 0; node < 15; ++node) {
    const auto dof = static_cast<size_t>(3 * node);
    at.push_back({block.x[dof], block.y[dof]});
    const Point3 normal = ball_normal(at.back());
    // Another orthonormal basis of the tangent plane than the rows': the disc is the same.
    Point3 a = cross({0, 1, 0}, normal);
    const double length = std::sqrt(dot(a, a));
    a = {a[0] / length, a[1] / length, a[2] / length};
    const Point3 b = cross(normal, a);
    const auto on_slave = [&](const Point3& v, double sign) {
      Vec row = Vec::Zero(n);
      for (size_t i = 0; i < 3; ++i) row[static_cast<Eigen::Index>(dof + i)] = sign * v[i];
      return row;
    };
    const double distance = std::hypot(at.back()[0] - kCentre[0], at.back()[1] - kCentre[1], kCentre[2]);
    rows.push_back({on_slave(normal, -1), distance - kRadius, {on_slave(a, 1), on_slave(b, 1)}, bound(at.back())});
    tangents.push_back({a, b});
  }
  return reference_forces(friction_dual(Eigen::MatrixXd(block.K.get()), block.f, block.dirichlet_dofs, block.dirichlet_values, rows),
                          at, tangents);
}

TEST(FrictionRowsKinds, ABallsRowsSlipAlongItsTangentPlane) {
  const Point3 s{0.3, 0.1, 0.2}, c{0, 0, -1};
  const BallGeometry ball({{{0, 0}, {0, 1}, {0, 2}}}, s, c, 0.5, true);
  const std::vector<RowAt> rows = ball.slip_rows();
  ASSERT_EQ(rows.size(), 2u);
  const Point3 d = minus(s, c);
  std::vector<Point3> t;
  for (const RowAt& row : rows) {
    ASSERT_EQ(row.coefficients.size(), 3u);
    EXPECT_EQ(row.dofs, (std::vector<DofRef>{{0, 0}, {0, 1}, {0, 2}}));
    t.push_back({row.coefficients[0], row.coefficients[1], row.coefficients[2]});
    EXPECT_NEAR(dot(t.back(), d), 0, 1e-14) << "tangent to the ball";
    EXPECT_NEAR(dot(t.back(), t.back()), 1, 1e-14);
  }
  EXPECT_NEAR(dot(t[0], t[1]), 0, 1e-14);
  const BallGeometry disc({{{0, 0}, {0, 1}, {-1, -1}}}, {0.3, 0.1, 0}, {0, -1, 0}, 0.5, false);
  const std::vector<RowAt> plane = disc.slip_rows();  // n = (0.3, 1.1)/|.|, t = (-n_y, n_x)
  ASSERT_EQ(plane.size(), 1u);
  ASSERT_EQ(plane[0].coefficients.size(), 2u);
  const double length = std::hypot(0.3, 1.1);
  EXPECT_NEAR(plane[0].coefficients[0], -1.1 / length, 1e-15);
  EXPECT_NEAR(plane[0].coefficients[1], 0.3 / length, 1e-15);
}

TEST_P(FrictionKinds, ABallMatchesTheUndividedDual) {
  const auto subdomains = block_halves();
  const auto tangents = [&](const FetiProblem& p) {
    return [&p](int row) {
      const auto pair = tangent_pair(ball_normal(p.contact_positions()[static_cast<size_t>(row)]));
      return std::vector<Point3>{pair[0], pair[1]};
    };
  };
  for (const double bound : {0.2, 0.5, 100.0}) {
    SCOPED_TRACE("slip bound " + std::to_string(bound));
    const FetiProblem p(subdomains, on_ball(subdomains, tresca(bound)), setup());
    expect_reference(p, false, bound, tangents(p), ball_reference, bound == 0.5);
  }
  const FetiProblem p(subdomains, on_ball(subdomains, coulomb(0.1)), setup());
  expect_reference(p, true, 0.1, tangents(p), ball_reference, false);
}

INSTANTIATE_TEST_SUITE_P(Variants, FrictionKinds, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

// The coarse Gram matrices from GG''s factor with the contact modes last (coarseGram =
// "contact-last"; "auto" takes it from 3000 rigid modes on, more than these scenes have): the
// primal checks drop friction pairs at their disc's bound as well as open contact rows, and
// the free rows' G_F G_F' is singular for the floating upper block. The same references.
FetiSetupSettings contact_last_setup() {
  FetiSetupSettings s;
  s.variant = FetiVariant::tfeti;
  s.coarse_gram = GramLayout::contact_last;
  return s;
}

TEST(FrictionKindsContactLast, NodeToNode3DMatchesTheUndividedDual) {
  const auto subdomains = stacked_blocks(2);
  for (const double bound : {0.05, 0.15}) {
    SCOPED_TRACE("slip bound " + std::to_string(bound));
    const FetiProblem p(subdomains, stacked_contact(subdomains, 2, tresca(bound)), contact_last_setup());
    expect_reference(p, false, bound, node_to_node_3d_tangents, stacked_reference, bound == 0.15);
  }
  const FetiProblem p(subdomains, stacked_contact(subdomains, 2, coulomb(0.1)), contact_last_setup());
  expect_reference(p, true, 0.1, node_to_node_3d_tangents, stacked_reference, false);
}

TEST(FrictionKindsContactLast, ABallMatchesTheUndividedDual) {
  const auto subdomains = block_halves();
  const FetiProblem p(subdomains, on_ball(subdomains, tresca(0.5)), contact_last_setup());
  expect_reference(
      p, false, 0.5,
      [&p](int row) {
        const auto pair = tangent_pair(ball_normal(p.contact_positions()[static_cast<size_t>(row)]));
        return std::vector<Point3>{pair[0], pair[1]};
      },
      ball_reference, true);
}

// ---- Refusals ----------------------------------------------------------------------------

TEST(FrictionKindsInput, NodeToNodeFrictionNeedsTheTangentialComponents) {
  const auto membranes = test::membrane_subdomains(test::membrane_options(4, 2));  // a scalar field
  ContactInput contact = test::membrane_contact(membranes);
  contact.friction = 0.3;
  EXPECT_NE(refusal([&] { build_constraints(membranes, contact, FetiVariant::tfeti); })
                .find("friction: node-to-node contact slips along the other components of each slave and master node"),
            std::string::npos);
}

TEST(FrictionKindsInput, NodeToNodeFrictionTakesOneSlaveDofPerNode) {
  const auto subdomains = stacked_plates(1);
  ContactInput contact = stacked_contact(subdomains, 1, coulomb(0.3));
  const auto tangential = dofs_on_zero(subdomains, 1, 0);
  contact.slave_dofs[1].insert(contact.slave_dofs[1].end(), tangential[1].begin(), tangential[1].end());
  contact.input_of<NodeToNodeInput>().masters[0].insert(contact.input_of<NodeToNodeInput>().masters[0].end(), tangential[0].begin(), tangential[0].end());
  EXPECT_NE(refusal([&] { build_constraints(subdomains, contact, FetiVariant::tfeti); })
                .find("node-to-node friction takes one slave dof per node"),
            std::string::npos);
  contact.friction = -1;  // frictionless: both components unilateral, as before
  EXPECT_EQ(build_constraints(subdomains, contact, FetiVariant::tfeti).contact_rows(), 10);
}

}  // namespace
}  // namespace ffeti
