// Isotropic friction in three dimensions: the tangent pair of each contact row, the slip
// rows of a rigid plane and of a face, the disc's KKT measures, and a block pressed on a
// rigid plane and sheared, solved by FETI in two subdomains against the undivided block's
// dual (B K^-1 B' with a dense K) solved by accelerated projected gradient onto half-lines
// and discs (friction_reference.h), which shares no code with qp/.
#include "constraints/constraints.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/obstacle.h"
#include "feti/feti_problem.h"
#include "feti/friction.h"
#include "feti/primal.h"
#include "friction_reference.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <random>
#include <stdexcept>

namespace ffeti {
namespace {

Point3 unit(const Point3& v) {
  const double length = std::sqrt(dot(v, v));
  return {v[0] / length, v[1] / length, v[2] / length};
}

TEST(TangentPair, OrthonormalRightHandedAndOrthogonalToTheNormal) {
  std::mt19937 random(36);
  std::normal_distribution<double> gauss;
  std::vector<Point3> normals = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, unit({1, 1, 1}), unit({1, 1, 0})};
  for (int k = 0; k < 200; ++k) normals.push_back(unit({gauss(random), gauss(random), gauss(random)}));
  for (const Point3& n : normals) {
    const auto [t1, t2] = tangent_pair(n);
    EXPECT_NEAR(dot(t1, t1), 1, 1e-14);
    EXPECT_NEAR(dot(t2, t2), 1, 1e-14);
    EXPECT_NEAR(dot(t1, t2), 0, 1e-14);
    EXPECT_NEAR(dot(t1, n), 0, 1e-14);
    EXPECT_NEAR(dot(t2, n), 0, 1e-14);
    EXPECT_NEAR(dot(cross(t1, t2), n), 1, 1e-14);  // (t1, t2, n) right-handed
  }
  const auto [x, y] = tangent_pair({0, 0, 1});  // the documented convention on a horizontal plane
  EXPECT_EQ(x, (Point3{1, 0, 0}));
  EXPECT_EQ(y, (Point3{0, 1, 0}));
}

TEST(FrictionRows3D, APlaneObstacleSlipsAlongItsTangentPair) {
  const Point3 n = unit({0.2, -0.3, 1});
  const ObstacleGeometry plane({{{0, 0}, {0, 1}, {0, 2}}}, {1, 2, 3}, {0, 0, 0}, n, true);
  const std::vector<RowAt> rows = plane.slip_rows();
  ASSERT_EQ(rows.size(), 2u);
  const auto pair = tangent_pair(n);
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(rows[k].dofs, (std::vector<DofRef>{{0, 0}, {0, 1}, {0, 2}}));
    for (size_t i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(rows[k].coefficients[i], pair[k][i]);
    EXPECT_EQ(rows[k].gap, 0.0);
  }
}

/// A row's value for a motion of its dofs given per node (the dof's node by DofRef).
double slip(const RowAt& row, const std::function<Point3(DofRef)>& motion_of_node, const std::function<int(DofRef)>& component) {
  double value = 0;
  for (size_t k = 0; k < row.dofs.size(); ++k)
    value += row.coefficients[k] * motion_of_node(row.dofs[k])[static_cast<size_t>(component(row.dofs[k]))];
  return value;
}

TEST(FrictionRows3D, ANodeOnAFaceSlipsRelativeToTheFace) {
  // A tilted master triangle of subdomain 1 (dofs 0..8) and a slave of subdomain 0 (dofs 0..2)
  // above an interior point: the slip is t_k.(u_s - sum w_i u_i).
  const std::array<Point3, 3> corners = {Point3{0, 0, 0}, Point3{2, 0, 0.5}, Point3{0, 2, 1}};
  const Point3 s{0.5, 0.6, 1.0};
  std::array<DofRef, 9> face;
  for (int k = 0; k < 9; ++k) face[static_cast<size_t>(k)] = {1, k};
  const FaceGeometry geometry({{{0, 0}, {0, 1}, {0, 2}}}, s, face, corners);
  const std::vector<RowAt> rows = geometry.slip_rows();
  ASSERT_EQ(rows.size(), 2u);
  const Point3 n = unit(cross(minus(corners[1], corners[0]), minus(corners[2], corners[0])));
  const auto pair = tangent_pair(n);
  const auto component = [](DofRef d) { return d[1] % 3; };
  const auto rigid = [](DofRef) { return Point3{0.3, -0.7, 1.1}; };
  const Point3 v{0.3, -0.7, 1.1};
  const auto slave_only = [&](DofRef d) { return d[0] == 0 ? v : Point3{0, 0, 0}; };
  const auto face_along_normal = [&](DofRef d) { return d[0] == 1 ? n : Point3{0, 0, 0}; };
  const auto face_along_tangent = [&](DofRef d) { return d[0] == 1 ? pair[0] : Point3{0, 0, 0}; };
  for (size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(slip(rows[k], rigid, component), 0, 1e-14) << "a rigid translation does not slip";
    EXPECT_NEAR(slip(rows[k], slave_only, component), dot(pair[k], v), 1e-14);
    EXPECT_NEAR(slip(rows[k], face_along_normal, component), 0, 1e-14) << "closing is not slipping";
    EXPECT_NEAR(slip(rows[k], face_along_tangent, component), k == 0 ? -1 : 0, 1e-14);
  }
}

TEST(FrictionRows3D, DiscResidualsMeasureTheNormAndTheDirection) {
  Constraints c;  // one contact row (row 0) and its friction pair (rows 1, 2)
  c.rhs = {0, 0, 0};
  c.friction_rows = 2;
  c.tangent_directions = 2;
  c.normal_row = {0, 0};
  const Vec at_bound = (Vec(3) << 1, 3, 4).finished();  // ||lambda_t|| = 5
  EXPECT_TRUE(at_slip_bound(c, at_bound, 1, 5));
  EXPECT_FALSE(at_slip_bound(c, at_bound, 1, 5.001));
  EXPECT_FALSE(holds_with_equality(c, at_bound, Vec::Constant(2, 5), 2));
  EXPECT_TRUE(holds_with_equality(c, at_bound, Vec::Constant(2, 6), 2));
  const Vec along = (Vec(3) << 0, 0.3, 0.4).finished(), across = (Vec(3) << 0, 0.4, -0.3).finished();
  EXPECT_NEAR(friction_residual(c, at_bound, along, 1, 5, 10).complementarity, 0, 1e-14);
  EXPECT_NEAR(friction_residual(c, at_bound, along, 1, 5, 10).excess, 0, 1e-14);
  EXPECT_NEAR(friction_residual(c, at_bound, across, 1, 5, 10).complementarity, 2.5, 1e-14);  // ||l|| ||s||
  EXPECT_NEAR(friction_residual(c, at_bound, along, 1, 6, 10).complementarity, 0.5, 1e-14);   // inside, slipping
  EXPECT_NEAR(friction_residual(c, at_bound, along, 1, 4, 10).excess, 1, 1e-14);
  const ContactRowForces forces = contact_row_forces(c, at_bound, Vec::Constant(2, 5));
  EXPECT_EQ(forces.state[0], ContactState::slip);
  EXPECT_EQ(forces.tangential[0], 3);
  EXPECT_EQ(forces.second_tangential[0], 4);
  EXPECT_EQ(contact_row_forces(c, at_bound, Vec::Constant(2, 6)).state[0], ContactState::stick);
}


// ---- A block on a rigid plane, pressed and sheared ----------------------------------------

constexpr double kGap = 0.001;
const std::array<double, 3> kTop{0.004, 0.0, -0.01};  // the top face's motion: shear along x, push down

/// The block [0, 1] x [0, 0.5] x [0, 0.25] (4 x 2 x 1 cubes) in two halves along x, turned by
/// `turn` about z, over the plane z = -kGap.
std::vector<SubdomainInput> halves(double turn) {
  return {solid_block(0, {0.5, 0.5, 0.25}, {2, 2, 1}, kTop, turn), solid_block(0.5, {0.5, 0.5, 0.25}, {2, 2, 1}, kTop, turn)};
}

/// Every dof of the bottom nodes slave, against the plane z = -kGap with normal e_z (whose
/// tangent pair is e_x, e_y).
ContactInput on_plane(const std::vector<SubdomainInput>& subdomains) {
  ContactInput contact;
  contact.slave_dofs = bottom_dofs(subdomains);
  contact.input_of<ObstacleInput>().given = true;
  contact.input_of<ObstacleInput>().point = {0, 0, -kGap};
  contact.input_of<ObstacleInput>().normal = {0, 0, 1};
  return contact;
}

/// Per bottom node: its position (x, y) and its forces (lambda_n, lambda_t1, lambda_t2).
struct NodeForces {
  std::array<double, 2> at;
  std::array<double, 3> force;
};

/// The undivided block's dual (friction_reference.h): lambda_n >= 0 and ||(lambda_t1,
/// lambda_t2)|| <= g per bottom node, rows -u_z <= kGap and the slips u_x, u_y.
/// `bound` gives g at a node's position (x, y).
using NodeBound = std::function<double(const std::array<double, 2>&)>;
std::vector<NodeForces> undivided_dual(const NodeBound& bound, double turn) {
  const SubdomainInput block = solid_block(0, {1, 0.5, 0.25}, {4, 2, 1}, kTop, turn);
  const Eigen::Index n = block.K.rows();
  std::vector<ReferenceRow> rows;
  std::vector<std::array<double, 2>> at;
  for (Eigen::Index node = 0; 3 * node < n; ++node) {
    const auto dof = static_cast<size_t>(3 * node);
    if (block.z[dof] != 0) continue;
    const auto unit_row = [&](size_t component, double sign) {
      Vec row = Vec::Zero(n);
      row[static_cast<Eigen::Index>(dof + component)] = sign;
      return row;
    };
    at.push_back({block.x[dof], block.y[dof]});
    rows.push_back({unit_row(2, -1), kGap, {unit_row(0, 1), unit_row(1, 1)}, bound(at.back())});
  }
  const std::vector<ReferenceForces> forces =
      friction_dual(Eigen::MatrixXd(block.K.get()), block.f, block.dirichlet_dofs, block.dirichlet_values, rows);
  std::vector<NodeForces> out;
  for (size_t k = 0; k < rows.size(); ++k)
    out.push_back({at[k], {forces[k].normal, forces[k].tangential[0], forces[k].tangential[1]}});
  return out;
}

/// FETI's forces per contact row (fetiContact's normal, tangential, tangential2).
std::vector<NodeForces> feti_forces(const FetiProblem& p, const FetiResult& r) {
  const Constraints& c = p.constraints();
  const ContactRowForces forces = contact_row_forces(c, r.lambda, r.slip_bound);
  std::vector<NodeForces> out;
  for (int i = 0; i < c.contact_rows(); ++i) {
    const auto k = static_cast<size_t>(i);
    out.push_back({p.contact_positions()[k], {r.lambda[c.equality_rows + i], forces.tangential[k], forces.second_tangential[k]}});
  }
  return out;
}

/// The forces of `of` at the node of `reference` at the same position.
const NodeForces& at_node(const std::vector<NodeForces>& of, const std::array<double, 2>& at) {
  for (const NodeForces& node : of)
    if (std::hypot(node.at[0] - at[0], node.at[1] - at[1]) < 1e-9) return node;
  throw std::runtime_error("no contact row at that node");
}

double largest_normal(const std::vector<NodeForces>& forces) {
  double scale = 0;
  for (const NodeForces& node : forces) scale = std::max(scale, std::abs(node.force[0]));
  return scale;
}

void expect_same_forces(const std::vector<NodeForces>& feti, const std::vector<NodeForces>& reference) {
  ASSERT_EQ(feti.size(), reference.size());
  const double scale = largest_normal(reference);
  for (const NodeForces& node : reference)
    for (size_t k = 0; k < 3; ++k)
      EXPECT_NEAR(at_node(feti, node.at).force[k], node.force[k], 1e-8 * scale)
          << "force " << k << " at (" << node.at[0] << ", " << node.at[1] << ")";
}

NodeBound everywhere(double g) {
  return [g](const std::array<double, 2>&) { return g; };
}

DualSolveSettings tight() {
  DualSolveSettings s;
  s.tolerance = 1e-12;
  s.max_hessian = 200000;
  return s;
}

/// The block of halves(turn) on the plane in `variant`, its law set by `law`.
std::unique_ptr<FetiProblem> pressed_block(FetiVariant variant, double turn, const std::function<void(ContactInput&)>& law) {
  ContactInput contact = on_plane(halves(turn));
  law(contact);
  FetiSetupSettings setup;
  setup.variant = variant;
  return std::make_unique<FetiProblem>(halves(turn), contact, setup);
}

std::function<void(ContactInput&)> tresca(double g) {
  return [g](ContactInput& c) { c.slip_bound = g; };
}

class Tresca3D : public ::testing::TestWithParam<FetiVariant> {};

TEST_P(Tresca3D, FrictionRowsComeInPairsAlongThePlanesTangents) {
  const auto problem = pressed_block(GetParam(), 0, tresca(0.1));
  const Constraints& c = problem->constraints();
  ASSERT_EQ(c.contact_rows(), 15);
  ASSERT_EQ(c.friction_rows, 30);
  EXPECT_EQ(c.tangent_directions, 2);
  for (int t = 0; t < c.friction_rows; ++t) {
    const auto row = static_cast<size_t>(c.first_friction_row() + t);
    EXPECT_EQ(c.normal_row[static_cast<size_t>(t)], c.normal_row[static_cast<size_t>(t - t % 2)]);
    ASSERT_EQ(c.row_start[row + 1] - c.row_start[row], 1);  // one dof, e_x then e_y
    const ConstraintEntry& e = c.entries[static_cast<size_t>(c.row_start[row])];
    EXPECT_EQ(e.dof % 3, t % 2);
    EXPECT_EQ(e.coefficient, 1.0);
  }
}

TEST_P(Tresca3D, MatchesTheUndividedDualSolvedByProjectedGradient) {
  for (double bound : {0.05, 0.15, 100.0}) {
    SCOPED_TRACE("slip bound " + std::to_string(bound));
    const auto problem = pressed_block(GetParam(), 0, tresca(bound));
    const FetiProblem& p = *problem;
    const FetiResult r = p.solve(tight());
    ASSERT_EQ(r.status, SolveStatus::converged);
    EXPECT_LT(r.kkt.max(), 1e-8);
    expect_same_forces(feti_forces(p, r), undivided_dual(everywhere(bound), 0));
    if (bound == 0.15) {  // the mixed case: some rows stick, some slip
      EXPECT_GT(r.slipping_contact, 0);
      EXPECT_LT(r.slipping_contact, r.active_contact);
    }
    if (bound == 100.0) EXPECT_EQ(r.slipping_contact, 0);
  }
}

TEST_P(Tresca3D, TurningTheSceneAboutTheNormalTurnsTheForces) {
  // The block and its shear turned by 30 degrees about the plane's normal: the same normal
  // forces and friction magnitudes, the friction forces turned (a box, anisotropic, fails this).
  const double turn = M_PI / 6, bound = 0.15;
  const auto straight_problem = pressed_block(GetParam(), 0, tresca(bound));
  const auto turned_problem = pressed_block(GetParam(), turn, tresca(bound));
  const FetiProblem &straight = *straight_problem, &turned = *turned_problem;
  const FetiResult a = straight.solve(tight()), b = turned.solve(tight());
  ASSERT_EQ(a.status, SolveStatus::converged);
  ASSERT_EQ(b.status, SolveStatus::converged);
  EXPECT_EQ(a.slipping_contact, b.slipping_contact);
  EXPECT_GT(a.slipping_contact, 0);
  const std::vector<NodeForces> fa = feti_forces(straight, a), fb = feti_forces(turned, b);
  const double scale = largest_normal(fa), c = std::cos(turn), s = std::sin(turn);
  for (const NodeForces& node : fa) {
    const NodeForces& other = at_node(fb, {c * node.at[0] - s * node.at[1], s * node.at[0] + c * node.at[1]});
    EXPECT_NEAR(other.force[0], node.force[0], 1e-8 * scale);
    EXPECT_NEAR(other.force[1], c * node.force[1] - s * node.force[2], 1e-8 * scale);
    EXPECT_NEAR(other.force[2], s * node.force[1] + c * node.force[2], 1e-8 * scale);
  }
  expect_same_forces(fb, undivided_dual(everywhere(bound), turn));
}

TEST_P(Tresca3D, CoulombFixedPointMeetsTheLawAndTheReference) {
  // Coulomb's answer is the Tresca solution for g = mu lambda_n of itself: the reference with
  // those bounds, node by node.
  constexpr double mu = 0.1;
  const auto problem = pressed_block(GetParam(), 0, [](ContactInput& c) { c.friction = mu; });
  const FetiProblem& p = *problem;
  const FetiResult r = p.solve(tight());
  ASSERT_EQ(r.status, SolveStatus::converged);
  EXPECT_GT(r.friction_iterations, 1);
  EXPECT_LT(r.kkt.max(), 1e-8);
  EXPECT_GT(r.slipping_contact, 0);
  const std::vector<NodeForces> forces = feti_forces(p, r);
  expect_same_forces(forces, undivided_dual([&](const std::array<double, 2>& at) { return mu * at_node(forces, at).force[0]; }, 0));
}

TEST_P(Tresca3D, NewtonGivesTheFixedPointsCoulombAnswer) {
  // coulomb = "newton" in 3D (its slipping pairs linearized across their direction): the
  // fixed point's multipliers to the tolerance; automatic keeps the fixed point in 3D.
  constexpr double mu = 0.1;
  const auto problem = pressed_block(GetParam(), 0, [](ContactInput& c) { c.friction = mu; });
  const FetiProblem& p = *problem;
  DualSolveSettings newton = tight();
  newton.coulomb = CoulombMethod::newton;
  const FetiResult a = p.solve(tight()), b = p.solve(newton);
  ASSERT_EQ(a.status, SolveStatus::converged);
  ASSERT_EQ(b.status, SolveStatus::converged);
  EXPECT_EQ(a.newton_steps, 0);
  EXPECT_GT(b.newton_steps, 0);
  EXPECT_LE((a.lambda - b.lambda).norm(), 1e-9 * a.lambda.norm());
  EXPECT_LT(b.kkt.max(), 1e-8);
}

TEST_P(Tresca3D, AFloatingBlockTheDiscsCannotHoldIsInfeasibleWithoutIterating) {
  // The block free (nothing fixes its top), weighed down and pushed along x by a load on every
  // node: it stands only if the bottom rows' friction discs carry the push. Their least-norm
  // forces meet the normal bounds but not the discs, so the feasibility test must read the
  // discs: without them it let SMALBE iterate to maxit.
  constexpr double push = 0.2, weight = 1.0;
  std::vector<SubdomainInput> blocks = halves(0);
  double total_push = 0;
  for (SubdomainInput& block : blocks) {
    block.dirichlet_dofs.clear();
    block.dirichlet_values.clear();
    for (Eigen::Index dof = 0; dof < block.K.rows(); dof += 3) {
      block.f[dof] = push, block.f[dof + 2] = -weight;
      total_push += push;
    }
  }
  const ContactInput held = on_plane(blocks);
  const int rows = static_cast<int>(held.slave_dofs[0].size() + held.slave_dofs[1].size()) / 3;
  for (double capacity : {0.5, 2.0}) {  // the discs' sum against the push
    SCOPED_TRACE("capacity " + std::to_string(capacity) + " x the push");
    ContactInput contact = held;
    contact.slip_bound = capacity * total_push / rows;  // 18 slave nodes for 15 rows: the discs' sum is 5/6 of that
    FetiSetupSettings setup;
    setup.variant = GetParam();
    const FetiProblem problem(blocks, contact, setup);
    const FetiResult r = problem.solve();
    if (capacity < 1) {
      EXPECT_EQ(r.status, SolveStatus::infeasible) << to_string(r.status);
      EXPECT_EQ(r.counts.hessian, 0);
    } else {
      EXPECT_EQ(r.status, SolveStatus::converged) << to_string(r.status);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Variants, Tresca3D, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

}  // namespace
}  // namespace ffeti
