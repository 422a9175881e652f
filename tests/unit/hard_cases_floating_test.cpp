// Hard cases of floating bodies held only by contact (rows of docs/results/hard-cases.md,
// recorded as hard_cases_test.cpp's): a body on a rigid obstacle and a chain of three.
#include "feti/feti_problem.h"
#include "constraints/contact/node_to_node.h"
#include "constraints/contact/obstacle.h"
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

TEST(HardCases, BodyHeldOnlyByARigidObstacle) {
  // A 2-component block (two decoupled copies of the membrane operator, kernel: the two
  // translations) in 2 subdomains, pressed down (load -1 in y) onto the rigid floor y = 0;
  // only u_x is fixed (at x = 0): the vertical motion is held by the obstacle alone. Every
  // bottom node touches, so u_y is the solution with u_y = 0 on the floor, computed here by
  // a direct solve of the undivided block (Eigen's LDL').
  const auto load = [](double, double) { return -1.0; };
  std::vector<SubdomainInput> subs;
  ContactInput contact;
  for (int I = 0; I < 2; ++I) {
    const SubdomainInput scalar = test::p1_rectangle(0.5 * I, 0, 0.5, 1, 8, 16, 1.0, load, 0);
    SubdomainInput s = test::two_components(scalar);
    std::vector<int> slaves;
    for (int k = 0; k < static_cast<int>(scalar.x.size()); ++k) {
      s.f[2 * k + 1] = scalar.f[k];
      if (scalar.x[k] == 0.0) s.dirichlet_dofs.push_back(2 * k);
      if (scalar.y[k] == 0.0) slaves.insert(slaves.end(), {2 * k, 2 * k + 1});
    }
    contact.slave_dofs.push_back(slaves);
    subs.push_back(std::move(s));
  }
  contact.input_of<ObstacleInput>().given = true;
  contact.input_of<ObstacleInput>().point = {0.0, 0.0};
  contact.input_of<ObstacleInput>().normal = {0.0, 1.0};
  const FetiProblem problem(subs, contact);
  DualSolveSettings settings;
  settings.tolerance = 1e-8;
  const FetiResult r = problem.solve(settings);
  ASSERT_EQ(r.status, SolveStatus::converged);
  EXPECT_EQ(r.active_contact, problem.constraints().count(RowKind::contact));

  const SubdomainInput block = test::p1_rectangle(0, 0, 1, 1, 16, 16, 1.0, load, 0);
  std::vector<int> free_index(block.x.size(), -1);
  int free = 0;
  for (size_t k = 0; k < block.x.size(); ++k)
    if (block.y[k] != 0.0) free_index[k] = free++;
  std::vector<Eigen::Triplet<double, int>> entries;
  Vec rhs = Vec::Zero(free);
  for (int j = 0; j < block.K.get().outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(block.K, j); it; ++it)
      if (free_index[it.row()] >= 0 && free_index[j] >= 0) entries.emplace_back(free_index[it.row()], free_index[j], it.value());
  for (size_t k = 0; k < block.x.size(); ++k)
    if (free_index[k] >= 0) rhs[free_index[k]] = block.f[k];
  SparseMatrix reduced(free, free);
  reduced.setFromTriplets(entries.begin(), entries.end());
  const Vec uy = Eigen::SimplicialLDLT<SparseMatrix>(reduced).solve(rhs);
  double difference = 0, largest = 0;
  for (size_t s = 0; s < subs.size(); ++s)
    for (size_t k = 0; k < subs[s].x.size(); k += 2) {
      size_t b = 0;  // the block node at this position
      while (std::abs(block.x[b] - subs[s].x[k]) + std::abs(block.y[b] - subs[s].y[k]) > 1e-12) ++b;
      const double expected = free_index[b] >= 0 ? uy[free_index[b]] : 0.0;
      difference = std::max({difference, std::abs(r.u[s][static_cast<Eigen::Index>(k) + 1] - expected),
                             std::abs(r.u[s][static_cast<Eigen::Index>(k)])});
      largest = std::max(largest, std::abs(expected));
    }
  record("body held only by a rigid obstacle", r, difference / largest, "u against a direct solve on the floor", 1e-7);
  EXPECT_LT(difference, 1e-7 * largest);
  EXPECT_LT(r.kkt.max(), 1e-7);
}

TEST(HardCases, ChainOfThreeFloatingBodiesHeldOnlyByContact) {
  // Bodies (b, b+1) x (0,1), b = 0..3, each in 2 x 2 subdomains; body 0 fixed at x = 0, the
  // others held only by the contact lines x = 1, 2, 3 (u_left <= u_right), all loaded by
  // -1. Equilibrium: the multipliers on line x = b carry the load of bodies b .. 3.
  const int n = 16, bodies = 4;
  const auto load = [](double, double) { return -1.0; };
  std::vector<SubdomainInput> subs;
  ContactInput contact;
  for (int b = 0; b < bodies; ++b)
    for (int J = 0; J < 2; ++J)
      for (int I = 0; I < 2; ++I) {
        SubdomainInput s = test::p1_rectangle(b + 0.5 * I, 0.5 * J, 0.5, 0.5, n / 2, n / 2, 1.0, load, b);
        std::vector<int> slave, master;
        for (int k = 0; k < static_cast<int>(s.x.size()); ++k) {
          if (b == 0 && s.x[k] == 0.0) s.dirichlet_dofs.push_back(k);
          if (b + 1 < bodies && std::abs(s.x[k] - (b + 1)) < 1e-12) slave.push_back(k);
          if (b > 0 && std::abs(s.x[k] - b) < 1e-12) master.push_back(k);
        }
        contact.slave_dofs.push_back(slave);
        contact.input_of<NodeToNodeInput>().masters.push_back(master);
        subs.push_back(std::move(s));
      }
  std::vector<double> load_of_body(bodies, 0.0);
  for (const auto& s : subs) load_of_body[static_cast<size_t>(s.body)] += s.f.sum();
  double energies[2];
  for (FetiVariant variant : {FetiVariant::feti1, FetiVariant::tfeti}) {
    FetiSetupSettings setup;
    setup.variant = variant;
    const FetiProblem problem(subs, contact, setup);
    DualSolveSettings settings;
    settings.tolerance = 1e-8;
    const FetiResult r = problem.solve(settings);
    ASSERT_EQ(r.status, SolveStatus::converged);
    energies[variant == FetiVariant::feti1 ? 0 : 1] = r.energy;
    std::map<int, double> carried;  // contact line -> sum of its multipliers
    const Constraints& c = problem.constraints();
    for (int i = c.equality_rows; i < c.rows(); ++i)
      carried[static_cast<int>(std::lround(problem.contact_positions()[static_cast<size_t>(i - c.equality_rows)][0]))] +=
          r.lambda[i];
    double worst = 0;
    for (int line = 1; line < bodies; ++line) {
      double load_beyond = 0;
      for (int b = line; b < bodies; ++b) load_beyond += load_of_body[static_cast<size_t>(b)];
      worst = std::max(worst, std::abs(carried[line] + load_beyond) / std::abs(load_beyond));
    }
    record(std::string("chain of 3 floating bodies, ") + (variant == FetiVariant::feti1 ? "FETI-1" : "Total FETI"), r,
           worst, "contact force per line against the load it carries", 1e-7);
    EXPECT_LT(worst, 1e-6);
    EXPECT_LT(r.kkt.max(), 1e-6);
  }
  EXPECT_NEAR(energies[0], energies[1], 1e-8 * std::abs(energies[1]));
}

}  // namespace
}  // namespace ffeti
