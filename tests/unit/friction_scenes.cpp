#include "friction_scenes.h"

#include "feti/friction.h"
#include "plane_block.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace ffeti {

DualSolveSettings tight() {
  DualSolveSettings s;
  s.tolerance = 1e-12;
  s.max_hessian = 200000;
  return s;
}

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

Undivided side_by_side(const SubdomainInput& a, const SubdomainInput& b) {
  Undivided u;
  u.offset = a.K.rows();
  const Eigen::Index n = a.K.rows() + b.K.rows();
  u.K = Eigen::MatrixXd::Zero(n, n);
  u.K.topLeftCorner(a.K.rows(), a.K.rows()) = Eigen::MatrixXd(a.K.get());
  u.K.bottomRightCorner(b.K.rows(), b.K.rows()) = Eigen::MatrixXd(b.K.get());
  u.f = Vec(n);
  u.f << a.f, b.f;
  u.fixed = a.dirichlet_dofs, u.values = a.dirichlet_values;
  for (size_t k = 0; k < b.dirichlet_dofs.size(); ++k)
    u.fixed.push_back(b.dirichlet_dofs[k] + static_cast<int>(u.offset)), u.values.push_back(b.dirichlet_values[k]);
  return u;
}

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

Law tresca(double g) {
  return [g](ContactInput& c) { c.slip_bound = g; };
}
Law coulomb(double mu) {
  return [mu](ContactInput& c) { c.friction = mu; };
}

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

}  // namespace ffeti
