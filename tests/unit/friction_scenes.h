// Shared by the friction tests of node to node, balls and mortar: FETI's forces per contact
// row and the dense reference's (friction_reference.h) compared as vectors, so that a
// reference with another tangent basis compares; two bodies in one dense problem; the
// stacked blocks of 3D node to node and mortar.
#pragma once

#include "constraints/contact/point3.h"
#include "feti/feti_problem.h"
#include "friction_reference.h"

#include <gtest/gtest.h>

#include <functional>

namespace ffeti {

constexpr double kGap = 0.001;

DualSolveSettings tight();

/// A contact row's node (x, y) and its forces: lambda_n, then the friction force as a vector
/// (the multipliers times their tangents).
struct NodeForces {
  std::array<double, 2> at;
  double normal;
  Point3 friction;
};

const NodeForces& at_node(const std::vector<NodeForces>& of, const std::array<double, 2>& at);
/// Node by node, to 1e-8 of the largest normal force.
void expect_same_forces(const std::vector<NodeForces>& feti, const std::vector<NodeForces>& reference);
/// FETI's forces per contact row; `tangents(row)` the directions of its friction rows.
std::vector<NodeForces> feti_forces(const FetiProblem& p, const FetiResult& r,
                                    const std::function<std::vector<Point3>(int)>& tangents);
/// The reference's forces per row, its rows' tangents given as vectors.
std::vector<NodeForces> reference_forces(const std::vector<ReferenceForces>& forces,
                                         const std::vector<std::array<double, 2>>& at,
                                         const std::vector<std::vector<Point3>>& tangents);

/// Two bodies side by side in one dense problem: K and f block-diagonal, the Dirichlet dofs of both.
struct Undivided {
  Eigen::MatrixXd K;
  Vec f;
  std::vector<int> fixed;
  std::vector<double> values;
  Eigen::Index offset;  ///< the second body's first dof
};
Undivided side_by_side(const SubdomainInput& a, const SubdomainInput& b);

/// Per subdomain the dofs of component `component` on the plane where coordinate `axis` is 0.
std::vector<std::vector<int>> dofs_on_zero(const std::vector<SubdomainInput>& subdomains, int axis, int component);

using Law = std::function<void(ContactInput&)>;
Law tresca(double g);
Law coulomb(double mu);
/// g per row: Tresca's bound, or Coulomb's mu lambda_n of FETI's own answer (its fixed point is
/// the Tresca problem of those bounds).
using RowBound = std::function<double(const std::array<double, 2>&)>;

/// Solves, checks convergence and KKT, and compares with `reference(bound)` where bound is
/// Tresca's g (`is_coulomb` false) or Coulomb's mu lambda_n of FETI's answer; `mixed`: some
/// closed rows stick and some slip.
void expect_reference(const FetiProblem& p, bool is_coulomb, double parameter,
                      const std::function<std::vector<Point3>(int)>& tangents,
                      const std::function<std::vector<NodeForces>(const RowBound&)>& reference, bool mixed);

/// Tests run in FETI-1 and in Total FETI.
class FrictionVariants : public ::testing::TestWithParam<FetiVariant> {
 protected:
  FetiSetupSettings setup() const {
    FetiSetupSettings s;
    s.variant = GetParam();
    return s;
  }
};

/// The upper block's top: shear along x and y, push down.
inline const std::array<double, 3> kTop3{0.004, 0.002, -0.01};
/// Body 0: [0, 1] x [0, 0.5] x [0, 0.25] (4 x 2 x 1 cubes), top moved by kTop3; body 1: its
/// mirror image below z = 0, bottom fixed; each in `parts` slices along x.
std::vector<SubdomainInput> stacked_blocks(int parts);

/// The plane version: body 0 [0, 1] x [0, 0.5] (4 x 2 cells), top edge moved by (kDrag,
/// kPush); body 1 its mirror image below y = 0, bottom fixed; each in `parts` slices along x.
constexpr double kDrag = 0.004, kPush = -0.01;
std::vector<SubdomainInput> stacked_plates(int parts);

}  // namespace ffeti
