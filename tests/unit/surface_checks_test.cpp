// Contact surfaces listed against their bodies (issue 37, items 1 and 2): a face with two
// corners swapped, every face reversed, a plane whose normal points into the body, P2
// sub-triangles given to mortar contact. Each is refused naming the argument; the correctly
// listed scenes pass.
#include "base/errors.h"
#include "constraints/contact/node_to_face.h"
#include "constraints/contact/mortar.h"
#include "constraints/contact/obstacle.h"
#include "constraints/input_checks.h"
#include "feti/feti_problem.h"
#include "solid_block.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <utility>

namespace ffeti {
namespace {

constexpr int kCells = 2;  // per side of the blocks' top and bottom faces

/// Body 0: the block [0, 1]^2 x [0, 0.5] (top fixed); body 1: the same block 0.001 below it,
/// its top face z = -0.001 the master surface.
std::vector<SubdomainInput> stacked_blocks() {
  SubdomainInput upper = solid_block(0, {1, 1, 0.5}, {kCells, kCells, 1}, {0, 0, -0.01});
  SubdomainInput lower = solid_block(0, {1, 1, 0.5}, {kCells, kCells, 1}, {0, 0, 0});
  for (double& z : lower.z) z -= 0.501;
  lower.body = 1;
  return {std::move(upper), std::move(lower)};
}

/// The lower block's top face as triangles whose normal (b - a) x (c - a) is +z, out of it.
std::vector<std::array<int, 9>> lower_top_faces() {
  const auto node = [](int i, int j) { return i + (kCells + 1) * (j + (kCells + 1)); };  // layer z = top
  const auto corner_dofs = [](std::array<int, 9>& face, int corner, int n) {
    for (int c = 0; c < 3; ++c) face[static_cast<size_t>(3 * corner + c)] = 3 * n + c;
  };
  std::vector<std::array<int, 9>> faces;
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i)
      for (const std::array<int, 3>& t : {std::array<int, 3>{node(i, j), node(i + 1, j), node(i + 1, j + 1)},
                                          std::array<int, 3>{node(i, j), node(i + 1, j + 1), node(i, j + 1)}}) {
        std::array<int, 9> face{};
        for (int corner = 0; corner < 3; ++corner) corner_dofs(face, corner, t[static_cast<size_t>(corner)]);
        faces.push_back(face);
      }
  return faces;
}

ContactInput node_to_face(const std::vector<SubdomainInput>& subs, std::vector<std::array<int, 9>> faces) {
  ContactInput contact;
  contact.slave_dofs = {{}, {}};
  for (int k = 0; k < static_cast<int>(subs[0].z.size()); ++k)
    if (subs[0].z[static_cast<size_t>(k)] == 0) contact.slave_dofs[0].push_back(k);
  contact.input_of<NodeToFaceInput>().faces = {{}, std::move(faces)};
  return contact;
}

std::string refusal(const std::function<void()>& run) {
  try {
    run();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void swap_corners(std::array<int, 9>& face) {
  for (size_t i = 0; i < 3; ++i) std::swap(face[3 + i], face[6 + i]);
}

TEST(SurfaceChecks, OneFaceWithSwappedCornersIsRefusedByName) {
  const auto subs = stacked_blocks();
  EXPECT_EQ(refusal([&] { validate_input(subs, node_to_face(subs, lower_top_faces())); }), "");
  auto faces = lower_top_faces();
  swap_corners(faces[5]);
  const std::string message = refusal([&] { validate_input(subs, node_to_face(subs, faces)); });
  EXPECT_NE(message.find("contactFaces[1]: face 5 "), std::string::npos) << message;
  EXPECT_NE(message.find("pointing into its body"), std::string::npos) << message;
}

TEST(SurfaceChecks, EveryFaceReversedIsRefusedAtTheFirst) {
  const auto subs = stacked_blocks();
  auto faces = lower_top_faces();
  for (auto& face : faces) swap_corners(face);
  const std::string message = refusal([&] { validate_input(subs, node_to_face(subs, faces)); });
  EXPECT_NE(message.find("contactFaces[1]: face 0 "), std::string::npos) << message;
}

TEST(SurfaceChecks, MortarSlaveFacesAreJudgedToo) {
  // The upper block's bottom face as mortar slave faces: out of body 0 is -z, so the
  // lower block's top triangles (+z) listed on body 0's bottom nodes point into it.
  auto subs = stacked_blocks();
  auto bottom = lower_top_faces();
  for (auto& face : bottom)
    for (int& dof : face) dof -= 3 * (kCells + 1) * (kCells + 1);  // the same triangles on layer z = 0
  ContactInput contact;
  contact.input_of<NodeToFaceInput>().faces = {{}, lower_top_faces()};
  contact.input_of<MortarInput>().slave_faces = {bottom, {}};
  std::string message = refusal([&] { validate_input(subs, contact); });
  EXPECT_NE(message.find("contactSlaveFaces[0]: face 0 "), std::string::npos) << message;
  for (auto& face : contact.input_of<MortarInput>().slave_faces[0]) swap_corners(face);
  EXPECT_EQ(refusal([&] { validate_input(subs, contact); }), "");
}

/// The plane z = -0.001 under the upper block alone, its normal +z (toward the block); the
/// block's bottom nodes the slaves.
ContactInput plane_below(const std::vector<SubdomainInput>& block) {
  ContactInput contact = node_to_face(block, {});
  contact.input_of<NodeToFaceInput>().faces.clear();
  contact.slave_dofs.resize(1);
  contact.input_of<ObstacleInput>().given = true;
  contact.input_of<ObstacleInput>().point = {0, 0, -0.001};
  contact.input_of<ObstacleInput>().normal = {0, 0, 1};
  return contact;
}

TEST(SurfaceChecks, PlaneWhoseNormalPointsIntoTheBodyIsRefused) {
  // The upper block alone over the plane z = -0.001: its bottom nodes are the slaves.
  std::vector<SubdomainInput> block = {stacked_blocks()[0]};
  ContactInput contact = plane_below(block);
  EXPECT_EQ(refusal([&] { FetiProblem(block, contact, FetiSetupSettings{}); }), "");
  contact.input_of<ObstacleInput>().normal = {0, 0, -1};
  const std::string message = refusal([&] { FetiProblem(block, contact, FetiSetupSettings{}); });
  EXPECT_NE(message.find("obstacle: its normal points into the bodies"), std::string::npos) << message;
  // Every node of the block slave (a closed surface): the outward pushes cancel, no verdict.
  contact.input_of<ObstacleInput>().normal = {0, 0, 1};
  contact.slave_dofs[0].clear();
  for (int k = 0; k < static_cast<int>(block[0].K.rows()); ++k) contact.slave_dofs[0].push_back(k);
  EXPECT_EQ(refusal([&] { FetiProblem(block, contact, FetiSetupSettings{}); }).find("normal points into"),
            std::string::npos);
}

TEST(SurfaceChecks, AMassMatrixGivesNoVerdictAndALumpedMassKeepsTheStiffnessOne) {
  // A transient scene sets up K + c M (a step) and M alone (the predictor's projection in the
  // mass norm, edp/dynamics.idp). A consistent mass couples a node positively to its
  // neighbours: its dilation force points into the body, and read as a stiffness's it refused
  // a correct plane. Here a mass-like matrix (the block's couplings made positive, its
  // diagonal their sum): no verdict either way. A diagonal (lumped) mass added to K leaves
  // the dilation force K's: a reversed normal is still refused.
  std::vector<SubdomainInput> block = {stacked_blocks()[0]};
  ContactInput contact = plane_below(block);
  const SparseMatrix K = block[0].K.get();
  std::vector<Eigen::Triplet<double>> mass_like, lumped;
  for (Eigen::Index j = 0; j < K.outerSize(); ++j) {
    double row = 0;
    for (SparseMatrix::InnerIterator it(K, j); it; ++it)
      if (it.row() != j) mass_like.emplace_back(it.row(), j, std::abs(it.value())), row += std::abs(it.value());
    mass_like.emplace_back(j, j, row);
    lumped.emplace_back(j, j, 10 * K.coeff(j, j));
  }
  std::vector<SubdomainInput> mass = block, stepped = block;
  mass[0].K = SparseMatrix(K.rows(), K.cols());
  mass[0].K.edit().setFromTriplets(mass_like.begin(), mass_like.end());
  SparseMatrix diagonal(K.rows(), K.cols());
  diagonal.setFromTriplets(lumped.begin(), lumped.end());
  stepped[0].K = SparseMatrix(K + diagonal);
  EXPECT_EQ(refusal([&] { FetiProblem(mass, contact, FetiSetupSettings{}); }), "");
  EXPECT_EQ(refusal([&] { FetiProblem(stepped, contact, FetiSetupSettings{}); }), "");
  contact.input_of<ObstacleInput>().normal = {0, 0, -1};
  EXPECT_EQ(refusal([&] { FetiProblem(mass, contact, FetiSetupSettings{}); }).find("normal points into"), std::string::npos);
  const std::string message = refusal([&] { FetiProblem(stepped, contact, FetiSetupSettings{}); });
  EXPECT_NE(message.find("obstacle: its normal points into the bodies"), std::string::npos) << message;
}

/// A P2 triangle's six nodes (vertices 0-2, edge midpoints 3: 01, 4: 12, 5: 20) at height
/// z, dofs 3k + c, with the vertices' x dofs coupled as in one element; `midpoints` false:
/// the vertices alone (a P1 triangle).
SubdomainInput triangle_nodes(double z, int body, bool midpoints) {
  std::vector<std::array<double, 3>> nodes = {{0, 0, z}, {1, 0, z}, {0, 1, z}};
  if (midpoints) nodes.insert(nodes.end(), {{0.5, 0, z}, {0.5, 0.5, z}, {0, 0.5, z}});
  SubdomainInput s;
  for (const auto& node : nodes)
    for (int c = 0; c < 3; ++c)
      s.x.push_back(node[0]), s.y.push_back(node[1]), s.z.push_back(node[2]), s.component.push_back(c);
  const auto n = static_cast<Eigen::Index>(s.x.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index i = 0; i < n; ++i) entries.emplace_back(i, i, 1.0);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      if (a != b) entries.emplace_back(3 * a, 3 * b, -0.1);
  s.K = SparseMatrix(n, n);
  s.K.edit().setFromTriplets(entries.begin(), entries.end());
  s.f = Vec::Zero(n);
  s.body = body;
  return s;
}

std::array<int, 9> face_of(int a, int b, int c) {
  return {3 * a, 3 * a + 1, 3 * a + 2, 3 * b, 3 * b + 1, 3 * b + 2, 3 * c, 3 * c + 1, 3 * c + 2};
}

TEST(SurfaceChecks, MortarRefusesP2SubTriangles) {
  // Slave faces on top of body 0 (normal +z), the master a P1 triangle of body 1 above (-z).
  ContactInput contact;
  contact.input_of<NodeToFaceInput>().faces = {{}, {face_of(0, 2, 1)}};
  contact.input_of<MortarInput>().slave_faces = {{face_of(0, 3, 5), face_of(3, 1, 4), face_of(5, 4, 2), face_of(3, 4, 5)}, {}};
  const std::vector<SubdomainInput> p2 = {triangle_nodes(0, 0, true), triangle_nodes(0.001, 1, false)};
  const std::string message = refusal([&] { validate_input(p2, contact); });
  EXPECT_NE(message.find("contactSlaveFaces[0]"), std::string::npos) << message;
  EXPECT_NE(message.find("P1 faces only"), std::string::npos) << message;
  // The same nodes as P1 faces (the midpoints' nodes not coupled to the vertices as one
  // element's): accepted.
  contact.input_of<MortarInput>().slave_faces = {{face_of(0, 1, 2)}, {}};
  const std::vector<SubdomainInput> p1 = {triangle_nodes(0, 0, false), triangle_nodes(0.001, 1, false)};
  EXPECT_EQ(refusal([&] { validate_input(p1, contact); }), "");
  // Node to face takes P2 faces as sub-triangles (the reference says so): no refusal there.
  ContactInput faces;
  faces.slave_dofs = {{}, {0, 1, 2}};
  faces.input_of<NodeToFaceInput>().faces = {{face_of(0, 3, 5), face_of(3, 1, 4), face_of(5, 4, 2), face_of(3, 4, 5)}, {}};
  EXPECT_EQ(refusal([&] { validate_input(p2, faces); }), "");
}

}  // namespace
}  // namespace ffeti
