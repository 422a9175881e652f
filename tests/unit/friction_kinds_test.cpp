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
#include "friction_reference.h"
#include "membrane_model.h"
#include "plane_block.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace ffeti {
namespace {

constexpr double kGap = 0.001;

DualSolveSettings tight() {
  DualSolveSettings s;
  s.tolerance = 1e-12;
  s.max_hessian = 200000;
  return s;
}

/// A contact row's node (x, y) and its forces: lambda_n, then the friction force as a vector
/// (the multipliers times their tangents), so that references with another tangent basis compare.
struct NodeForces {
  std::array<double, 2> at;
  double normal;
  Point3 friction;
};

const NodeForces& at_node(const std::vector<NodeForces>& of, const std::array<double, 2>& at) {
  for (const NodeForces& node : of)
    if (std::hypot(node.at[0] - at[0], node.at[1] - at[1]) < 1e-9) return node;
  throw std::runtime_error("no contact row at (" + std::to_string(at[0]) + ", " + std::to_string(at[1]) + ")");
}

void expect_same_forces(const std::vector<NodeForces>& feti, const std::vector<NodeForces>& reference) {
  ASSERT_EQ(feti.size(), reference.size());
  double scale = 0;
  for (const NodeForces& node : reference) scale = std::max(scale, node.normal);
  ASSERT_GT(scale, 0);
  for (const NodeForces& node : reference) {
    const NodeForces& other = at_node(feti, node.at);
    EXPECT_NEAR(other.normal, node.normal, 1e-8 * scale) << "normal force at (" << node.at[0] << ", " << node.at[1] << ")";
    for (size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(other.friction[i], node.friction[i], 1e-8 * scale)
          << "friction force " << i << " at (" << node.at[0] << ", " << node.at[1] << ")";
  }
}

/// FETI's forces per contact row; `tangents(row)` the directions of its friction rows.
std::vector<NodeForces> feti_forces(const FetiProblem& p, const FetiResult& r,
                                    const std::function<std::vector<Point3>(int)>& tangents) {
  const Constraints& c = p.constraints();
  const ContactRowForces forces = contact_row_forces(c, r.lambda, r.slip_bound);
  std::vector<NodeForces> out;
  for (int i = 0; i < c.contact_rows(); ++i) {
    const auto k = static_cast<size_t>(i);
    const std::vector<Point3> t = tangents(i);
    Point3 friction{0, 0, 0};
    for (size_t d = 0; d < 3; ++d)
      friction[d] = forces.tangential[k] * t[0][d] + (t.size() > 1 ? forces.second_tangential[k] * t[1][d] : 0.0);
    out.push_back({p.contact_positions()[k], r.lambda[c.equality_rows + i], friction});
  }
  return out;
}

/// The reference's forces per row, its rows' tangents given as vectors.
std::vector<NodeForces> reference_forces(const std::vector<ReferenceForces>& forces,
                                         const std::vector<std::array<double, 2>>& at,
                                         const std::vector<std::vector<Point3>>& tangents) {
  std::vector<NodeForces> out;
  for (size_t k = 0; k < forces.size(); ++k) {
    Point3 friction{0, 0, 0};
    for (size_t j = 0; j < tangents[k].size(); ++j)
      for (size_t d = 0; d < 3; ++d) friction[d] += forces[k].tangential[j] * tangents[k][j][d];
    out.push_back({at[k], forces[k].normal, friction});
  }
  return out;
}

/// Two bodies side by side in one dense problem: K and f block-diagonal, the Dirichlet dofs of both.
struct Undivided {
  Eigen::MatrixXd K;
  Vec f;
  std::vector<int> fixed;
  std::vector<double> values;
  Eigen::Index offset;  ///< the second body's first dof
};
Undivided side_by_side(const SubdomainInput& a, const SubdomainInput& b) {
  Undivided u;
  u.offset = a.K.rows();
  const Eigen::Index n = a.K.rows() + b.K.rows();
  u.K = Eigen::MatrixXd::Zero(n, n);
  u.K.topLeftCorner(a.K.rows(), a.K.rows()) = Eigen::MatrixXd(a.K);
  u.K.bottomRightCorner(b.K.rows(), b.K.rows()) = Eigen::MatrixXd(b.K);
  u.f = Vec(n);
  u.f << a.f, b.f;
  u.fixed = a.dirichlet_dofs, u.values = a.dirichlet_values;
  for (size_t k = 0; k < b.dirichlet_dofs.size(); ++k)
    u.fixed.push_back(b.dirichlet_dofs[k] + static_cast<int>(u.offset)), u.values.push_back(b.dirichlet_values[k]);
  return u;
}

/// Per subdomain the dofs of component `component` on the plane where coordinate `axis` is 0.
std::vector<std::vector<int>> dofs_on_zero(const std::vector<SubdomainInput>& subdomains, int axis, int component) {
  std::vector<std::vector<int>> out;
  for (const SubdomainInput& s : subdomains) {
    const std::vector<double>& coordinate = axis == 2 ? s.z : s.y;
    out.emplace_back();
    for (int k = 0; k < static_cast<int>(coordinate.size()); ++k)
      if (coordinate[static_cast<size_t>(k)] == 0 && s.component[static_cast<size_t>(k)] == component) out.back().push_back(k);
  }
  return out;
}

using Law = std::function<void(ContactInput&)>;
Law tresca(double g) {
  return [g](ContactInput& c) { c.slip_bound = g; };
}
Law coulomb(double mu) {
  return [mu](ContactInput& c) { c.friction = mu; };
}
/// g per row: Tresca's bound, or Coulomb's mu lambda_n of FETI's own answer (its fixed point is
/// the Tresca problem of those bounds).
using RowBound = std::function<double(const std::array<double, 2>&)>;

class FrictionKinds : public ::testing::TestWithParam<FetiVariant> {
 protected:
  FetiSetupSettings setup() const {
    FetiSetupSettings s;
    s.variant = GetParam();
    return s;
  }
  /// Solves, checks convergence and KKT, and compares with `reference(bound)` where bound is
  /// Tresca's g or Coulomb's mu lambda_n of FETI's answer.
  void expect_reference(const FetiProblem& p, bool is_coulomb, double parameter,
                        const std::function<std::vector<Point3>(int)>& tangents,
                        const std::function<std::vector<NodeForces>(const RowBound&)>& reference, bool mixed) {
    const FetiResult r = p.solve(tight());
    ASSERT_EQ(r.status, SolveStatus::converged);
    EXPECT_LT(r.kkt.max(), 1e-8);
    const std::vector<NodeForces> forces = feti_forces(p, r, tangents);
    const RowBound bound = [&](const std::array<double, 2>& at) {
      return is_coulomb ? parameter * at_node(forces, at).normal : parameter;
    };
    expect_same_forces(forces, reference(bound));
    if (mixed) {  // some closed rows stick, some slip
      EXPECT_GT(r.slipping_contact, 0);
      EXPECT_LT(r.slipping_contact, r.active_contact);
    }
  }
};

// ---- Node to node in three dimensions: a block pressed and sheared onto another ----------

const std::array<double, 3> kTop3{0.004, 0.002, -0.01};  // the upper block's top: shear along x and y, push down

/// Body 0: [0, 1] x [0, 0.5] x [0, 0.25] (4 x 2 x 1 cubes), top moved by kTop3; body 1: its
/// mirror image below z = 0, bottom fixed; each in `parts` slices along x.
std::vector<SubdomainInput> stacked_blocks(int parts) {
  std::vector<SubdomainInput> out;
  for (int body = 0; body < 2; ++body)
    for (int k = 0; k < parts; ++k) {
      const double w = 1.0 / parts;
      SubdomainInput s = solid_block(k * w, {w, 0.5, 0.25}, {4 / parts, 2, 1}, body == 0 ? kTop3 : std::array<double, 3>{0, 0, 0});
      if (body == 1) s = mirrored(s);
      s.body = body;
      out.push_back(std::move(s));
    }
  return out;
}

/// The lower block's top z dofs slave (u_lower - u_upper <= kGap), the upper's bottom ones master.
ContactInput stacked_contact(const std::vector<SubdomainInput>& subdomains, const Law& law) {
  ContactInput contact;
  const auto on_face = dofs_on_zero(subdomains, 2, 2);
  for (size_t s = 0; s < subdomains.size(); ++s) {
    contact.slave_dofs.push_back(subdomains[s].body == 1 ? on_face[s] : std::vector<int>{});
    contact.master_dofs.push_back(subdomains[s].body == 0 ? on_face[s] : std::vector<int>{});
  }
  contact.gap = kGap;
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
  const FetiProblem p(subdomains, stacked_contact(subdomains, tresca(0.1)), setup());
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
    const FetiProblem p(subdomains, stacked_contact(subdomains, tresca(bound)), setup());
    expect_reference(p, false, bound, node_to_node_3d_tangents, stacked_reference, bound == 0.15);
  }
  const FetiProblem p(subdomains, stacked_contact(subdomains, coulomb(0.1)), setup());
  expect_reference(p, true, 0.1, node_to_node_3d_tangents, stacked_reference, false);
}

// ---- Node to node in the plane: a block pressed and dragged over another -----------------

constexpr double kDrag = 0.004, kPush = -0.01;

/// Body 0: [0, 1] x [0, 0.5] (4 x 2 cells), top edge moved by (kDrag, kPush); body 1 its mirror
/// image below y = 0, bottom fixed; each in `parts` slices along x.
std::vector<SubdomainInput> stacked_plates(int parts) {
  std::vector<SubdomainInput> out;
  for (int body = 0; body < 2; ++body)
    for (int k = 0; k < parts; ++k) {
      const double w = 1.0 / parts;
      SubdomainInput s = elastic_block(k * w, w, 0.5, 4 / parts, 2, body == 0 ? kDrag : 0.0, body == 0 ? kPush : 0.0);
      if (body == 1) s = mirrored(s);
      s.body = body;
      out.push_back(std::move(s));
    }
  return out;
}

ContactInput plate_contact(const std::vector<SubdomainInput>& subdomains, const Law& law) {
  ContactInput contact;
  const auto on_edge = dofs_on_zero(subdomains, 1, 1);
  for (size_t s = 0; s < subdomains.size(); ++s) {
    contact.slave_dofs.push_back(subdomains[s].body == 1 ? on_edge[s] : std::vector<int>{});
    contact.master_dofs.push_back(subdomains[s].body == 0 ? on_edge[s] : std::vector<int>{});
  }
  contact.gap = kGap;
  law(contact);
  return contact;
}

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
    const FetiProblem p(subdomains, plate_contact(subdomains, tresca(bound)), setup());
    expect_reference(p, false, bound, node_to_node_2d_tangent, plate_reference, bound == 0.3);
  }
  const FetiProblem p(subdomains, plate_contact(subdomains, coulomb(0.2)), setup());
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
  for (const SubdomainInput& s : subdomains) {
    contact.slave_dofs.emplace_back();
    for (int k = 0; k < static_cast<int>(s.z.size()); ++k)
      if (s.z[static_cast<size_t>(k)] == 0) contact.slave_dofs.back().push_back(k);
  }
  contact.obstacle = true;
  contact.obstacle_point = kCentre;
  contact.obstacle_radius = kRadius;
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
  return reference_forces(friction_dual(Eigen::MatrixXd(block.K), block.f, block.dirichlet_dofs, block.dirichlet_values, rows),
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

// ---- Refusals ----------------------------------------------------------------------------

std::string refusal(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

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
  ContactInput contact = plate_contact(subdomains, coulomb(0.3));
  const auto tangential = dofs_on_zero(subdomains, 1, 0);
  contact.slave_dofs[1].insert(contact.slave_dofs[1].end(), tangential[1].begin(), tangential[1].end());
  contact.master_dofs[0].insert(contact.master_dofs[0].end(), tangential[0].begin(), tangential[0].end());
  EXPECT_NE(refusal([&] { build_constraints(subdomains, contact, FetiVariant::tfeti); })
                .find("node-to-node friction takes one slave dof per node"),
            std::string::npos);
  contact.friction = -1;  // frictionless: both components unilateral, as before
  EXPECT_EQ(build_constraints(subdomains, contact, FetiVariant::tfeti).contact_rows(), 10);
}

}  // namespace
}  // namespace ffeti
