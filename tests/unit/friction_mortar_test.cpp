// Mortar friction in three dimensions: the stacked blocks of friction_kinds_test.cpp with
// mortar contact on their matching faces z = 0, against the undivided problem's dual whose
// rows are written here from the face mass matrix D of the triangles of z = 0 (on matching
// flat faces both mortar matrices are D): per node j, with w_j = sum_k D_jk,
//   normal  (1/w_j) sum_k D_jk (u_s - u_m)_k . e_z <= 0      (n = -e_z, the master's normal)
//   slips   (1/w_j) sum_k D_jk t.(u_s - u_m)_k,  t = e_x, -e_y (tangent_pair(-e_z)).
#include "constraints/constraints.h"
#include "constraints/contact/mortar.h"
#include "constraints/contact/node_to_face.h"
#include "friction_scenes.h"

#include <gtest/gtest.h>

#include <string>

namespace ffeti {
namespace {

/// The triangles of the face z = 0 of a solid_block of nx x ny cells (Kuhn's tetrahedra cut
/// each square along the diagonal from (i, j) to (i + 1, j + 1)), as node numbers ordered
/// with (b - a) x (c - a) along +z.
std::vector<std::array<int, 3>> face_triangles(int nx, int ny) {
  const auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  std::vector<std::array<int, 3>> out;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      out.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      out.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return out;
}

std::array<int, 9> corner_dofs(const std::array<int, 3>& nodes) {
  std::array<int, 9> dofs;
  for (size_t k = 0; k < 9; ++k) dofs[k] = 3 * nodes[k / 3] + static_cast<int>(k % 3);
  return dofs;
}

/// The lower block's top triangles slave (outward +z), the upper's bottom ones master
/// (reversed: outward -z), per subdomain of stacked_blocks(parts).
ContactInput mortar_contact(int parts, const Law& law) {
  ContactInput contact;
  for (int body = 0; body < 2; ++body)
    for (int k = 0; k < parts; ++k) {
      std::vector<std::array<int, 9>> faces;
      for (std::array<int, 3> t : face_triangles(4 / parts, 2)) {
        if (body == 0) std::swap(t[1], t[2]);
        faces.push_back(corner_dofs(t));
      }
      contact.input_of<MortarInput>().slave_faces.push_back(body == 1 ? faces : std::vector<std::array<int, 9>>{});
      contact.input_of<NodeToFaceInput>().faces.push_back(body == 0 ? faces : std::vector<std::array<int, 9>>{});
    }
  law(contact);
  return contact;
}

std::vector<NodeForces> mortar_reference(const RowBound& bound) {
  const auto blocks = stacked_blocks(1);
  const SubdomainInput &upper = blocks[0], &lower = blocks[1];
  const Undivided u = side_by_side(upper, lower);
  // The P1 mass matrix of the face: area/12 (1 + delta_jk) per triangle.
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(15, 15);
  for (const auto& t : face_triangles(4, 2)) {
    const double area = 0.25 * 0.25 / 2;
    for (int a : t)
      for (int b : t) D(a, b) += area / 12 * (a == b ? 2 : 1);
  }
  std::vector<ReferenceRow> rows;
  std::vector<std::array<double, 2>> at;
  for (int j = 0; j < 15; ++j) {
    const double w = D.row(j).sum();
    // (1/w) sum_k D_jk v.(u_lower - u_upper)_k
    const auto jump = [&](const Point3& v) {
      Vec row = Vec::Zero(u.K.rows());
      for (int k = 0; k < 15; ++k)
        for (int i = 0; i < 3; ++i) {
          row[u.offset + 3 * k + i] += D(j, k) / w * v[static_cast<size_t>(i)];
          row[3 * k + i] -= D(j, k) / w * v[static_cast<size_t>(i)];
        }
      return row;
    };
    at.push_back({upper.x[static_cast<size_t>(3 * j)], upper.y[static_cast<size_t>(3 * j)]});
    rows.push_back({jump({0, 0, 1}), 0.0, {jump({1, 0, 0}), jump({0, -1, 0})}, bound(at.back())});
  }
  return reference_forces(friction_dual(u.K, u.f, u.fixed, u.values, rows), at,
                          std::vector<std::vector<Point3>>(15, {{1, 0, 0}, {0, -1, 0}}));
}

std::vector<Point3> mortar_tangents(int) { return {{1, 0, 0}, {0, -1, 0}}; }

class MortarFriction : public FrictionVariants {};

TEST_P(MortarFriction, EachRowSlipsAlongItsTangentPairByTheMortarWeights) {
  const FetiProblem p(stacked_blocks(2), mortar_contact(2, tresca(0.1)), setup());
  const Constraints& c = p.constraints();
  ASSERT_EQ(c.contact_rows(), 15);
  ASSERT_EQ(c.friction_rows, 30);
  // A rigid translation of both blocks does not slip; one of the lower block alone along
  // e_x slips by 1 along t1 and 0 along t2 (the weights of a row sum to 1 on either side).
  const auto slip_of = [&](int row, const Point3& lower, const Point3& upper) {
    double value = 0;
    for (int e = c.row_start[static_cast<size_t>(row)]; e < c.row_start[static_cast<size_t>(row) + 1]; ++e) {
      const ConstraintEntry& entry = c.entries[static_cast<size_t>(e)];
      const int component = entry.dof % 3;
      value += entry.coefficient * (entry.subdomain >= 2 ? lower : upper)[static_cast<size_t>(component)];
    }
    return value;
  };
  for (int t = 0; t < c.friction_rows; ++t) {
    const int row = c.first_friction_row() + t;
    EXPECT_NEAR(slip_of(row, {0.3, -0.2, 0.7}, {0.3, -0.2, 0.7}), 0, 1e-14);
    EXPECT_NEAR(slip_of(row, {1, 0, 0}, {0, 0, 0}), t % 2 == 0 ? 1 : 0, 1e-14);
    EXPECT_NEAR(slip_of(row, {0, 1, 0}, {0, 0, 0}), t % 2 == 0 ? 0 : -1, 1e-14);
    EXPECT_NEAR(slip_of(row, {0, 0, 1}, {0, 0, 0}), 0, 1e-14) << "closing is not slipping";
  }
}

TEST_P(MortarFriction, MatchesTheUndividedDual) {
  for (const double bound : {0.05, 0.15, 100.0}) {
    SCOPED_TRACE("slip bound " + std::to_string(bound));
    const FetiProblem p(stacked_blocks(2), mortar_contact(2, tresca(bound)), setup());
    expect_reference(p, false, bound, mortar_tangents, mortar_reference, bound == 0.15);
  }
  const FetiProblem p(stacked_blocks(2), mortar_contact(2, coulomb(0.1)), setup());
  expect_reference(p, true, 0.1, mortar_tangents, mortar_reference, false);
}

INSTANTIATE_TEST_SUITE_P(Variants, MortarFriction, ::testing::Values(FetiVariant::feti1, FetiVariant::tfeti),
                         [](const auto& info) { return info.param == FetiVariant::feti1 ? "feti1" : "tfeti"; });

}  // namespace
}  // namespace ffeti
