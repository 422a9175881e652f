// parallel_stable_sort against std::stable_sort: the same order, equal keys included, on
// every thread count (parts merged pairwise, an odd count leaving a run unmerged a round).
#include "base/parallel_sort.h"
#include "parallel/process.h"

#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

namespace ffeti {
namespace {

TEST(ParallelStableSort, GivesStdStableSortsOrderOnAnyThreadCount) {
  std::mt19937 random(7);
  std::uniform_int_distribution<int> key(0, 999);  // 300,000 items: many equal keys
  std::vector<std::pair<int, int>> items;          // (key, position): stability is visible
  for (int k = 0; k < 300000; ++k) items.emplace_back(key(random), k);
  const auto by_key = [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.first < b.first; };
  std::vector<std::pair<int, int>> expected = items;
  std::stable_sort(expected.begin(), expected.end(), by_key);
  for (int threads : {1, 2, 3, 4}) {
    const ThreadLimit limit(threads);
    std::vector<std::pair<int, int>> sorted = items;
    parallel_stable_sort(sorted, by_key);
    EXPECT_EQ(sorted, expected) << threads << " threads";
  }
}

TEST(ParallelStableSort, SortsSmallAndEmptyVectors) {
  std::vector<int> empty, one{5}, few{3, 1, 2};
  parallel_stable_sort(empty, std::less<int>());
  parallel_stable_sort(one, std::less<int>());
  parallel_stable_sort(few, std::less<int>());
  EXPECT_TRUE(empty.empty());
  EXPECT_EQ(one, std::vector<int>{5});
  EXPECT_EQ(few, (std::vector<int>{1, 2, 3}));
}

}  // namespace
}  // namespace ffeti
