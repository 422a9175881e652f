// What the FreeFEM binding hands to the core besides conversions: connected partitions,
// which rank owns a subdomain, and the constraint rows as triplets.
#include "base/errors.h"
#include "constraints/constraint_triplets.h"
#include "feti/feti_problem.h"
#include "membrane_model.h"
#include "mesh/connect_parts.h"
#include "parallel/communicator.h"
#include "parallel/ownership.h"

#include <gtest/gtest.h>

#include <map>

namespace ffeti {
namespace {

/// A strip of `n` triangles, each the neighbour of the next across one edge.
std::vector<std::vector<int>> strip(int n) {
  std::vector<std::vector<int>> neighbours;
  for (int k = 0; k < n; ++k) neighbours.push_back({k > 0 ? k - 1 : -1, k + 1 < n ? k + 1 : -1, -1});
  return neighbours;
}

TEST(ConnectParts, StrayPieceJoinsTheNeighbourItSharesMostEdgesWith) {
  // Part 0 has two pieces, triangles 0-3 and 7; triangle 7 lies between parts 1 and 2.
  std::vector<long> part = {0, 0, 0, 0, 1, 1, 1, 0, 2, 2};
  EXPECT_EQ(connect_parts(strip(10), part), 1);
  // Ties go to the part met first among the neighbours' parts in ascending order: 1.
  EXPECT_EQ(part, (std::vector<long>{0, 0, 0, 0, 1, 1, 1, 1, 2, 2}));
}

TEST(ConnectParts, ConnectedPartitionStaysAsItIs) {
  std::vector<long> part = {3, 3, 5, 5, 5, 1};
  const std::vector<long> before = part;
  EXPECT_EQ(connect_parts(strip(6), part), 0);
  EXPECT_EQ(part, before);
}

TEST(ConnectParts, SmallerPieceMovesWhereTheBorderIsLongest) {
  // Triangle 4 (part 0, apart from triangles 0-3) touches part 1 (triangles 5 and 6, one
  // piece) across two edges and part 2 across one.
  std::vector<std::vector<int>> neighbours = {{1, -1, -1}, {0, 2, -1}, {1, 3, -1}, {2, -1, -1},
                                                {5, 6, 7},   {4, 6, -1}, {4, 5, -1}, {4, -1, -1}};
  std::vector<long> part = {0, 0, 0, 0, 0, 1, 1, 2};
  EXPECT_EQ(connect_parts(neighbours, part), 1);
  EXPECT_EQ(part[4], 1);
}

TEST(ConnectParts, WrongSizeIsAnError) {
  std::vector<long> part = {0, 1};
  EXPECT_THROW(connect_parts(strip(3), part), InputError);
}

TEST(SubdomainOwners, OneProcessOwnsWhatItAssembled) {
  const SerialCommunicator comm;
  EXPECT_EQ(subdomain_owners({1, 1, 1}, comm), (std::vector<int>{0, 0, 0}));
  try {
    subdomain_owners({1, 0, 1}, comm);
    FAIL() << "an empty subdomain was accepted";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "K[1]: empty on every rank (no rank assembled subdomain 1)");
  }
}

TEST(ConstraintTriplets, RowsMatchTheConstraints) {
  test::MembraneOptions o = test::membrane_options(8, 2);
  auto subs = test::membrane_subdomains(o);
  FetiSetupSettings setup;
  setup.variant = FetiVariant::tfeti;
  const FetiProblem problem(subs, test::membrane_contact(subs), setup);
  const ConstraintTriplets t =
      constraint_triplets(problem.constraints(), problem.inputs(), problem.variant(), problem.communicator().size());
  const Constraints& c = problem.constraints();
  ASSERT_EQ(t.rhs.size(), static_cast<size_t>(c.rows()));
  ASSERT_EQ(t.rows.size(), c.entries.size());
  // Each row's entries sum to what B applied to a field of ones gives: gluing rows
  // (u_s - u_t) vanish, Dirichlet and contact rows have their own coefficients' sum.
  std::map<long, int> kinds;
  for (long k : t.kind) ++kinds[k];
  EXPECT_EQ(kinds[0], c.count(RowKind::gluing));
  EXPECT_EQ(kinds[1], c.count(RowKind::dirichlet));
  EXPECT_EQ(kinds[2], c.count(RowKind::contact));
  std::vector<double> row_sum(t.rhs.size(), 0.0);
  long columns = 0;
  for (const auto& s : subs) columns += s.K.rows();
  for (size_t e = 0; e < t.rows.size(); ++e) {
    ASSERT_GE(t.columns[e], 0);
    ASSERT_LT(t.columns[e], columns);
    row_sum[static_cast<size_t>(t.rows[e])] += t.values[e];
  }
  for (size_t r = 0; r < row_sum.size(); ++r)
    if (t.kind[r] == 0) EXPECT_NEAR(row_sum[r], 0.0, 1e-14) << "gluing row " << r;
}

TEST(ConstraintTriplets, RefusesFeti1) {
  test::MembraneOptions o = test::membrane_options(8, 2);
  auto subs = test::membrane_subdomains(o);
  const FetiProblem problem(subs, test::membrane_contact(subs), FetiSetupSettings{});
  EXPECT_THROW(constraint_triplets(problem.constraints(), problem.inputs(), problem.variant(), 1), InputError);
}

}  // namespace
}  // namespace ffeti
