// Failures inside threaded loops: every item runs, the lowest failing item's exception comes
// out of the loop (not std::terminate from inside a thread), and a loop that a collective
// step follows rethrows it on every rank.
#include "base/parallel_for.h"
#include "parallel/communicator.h"

#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <stdexcept>
#include <string>

namespace ffeti {
namespace {

TEST(ThreadFailures, ALoopRunsEveryItemAndRethrowsTheLowestFailure) {
  std::atomic<int> ran{0};
  try {
    parallel_for_each(64, 2, [&](int k) {
      ++ran;
      if (k == 40 || k == 7) throw std::runtime_error("item " + std::to_string(k));
    });
    FAIL() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "item 7");
  }
  EXPECT_EQ(ran.load(), 64);
}

TEST(ThreadFailures, OnOneRankTheFailureKeepsItsType) {
  const SerialCommunicator comm;
  // Memory running out in a subdomain solve reaches the caller as itself.
  EXPECT_THROW(parallel_for_each_on_every_rank(comm, 8, 2, [](int k) {
                 if (k == 3) throw std::bad_alloc();
               }),
               std::bad_alloc);
  int sum = 0;
  parallel_for_each_on_every_rank(comm, 4, 1, [&](int k) { sum += k; });
  EXPECT_EQ(sum, 6);
  EXPECT_NO_THROW(rethrow_on_every_rank(comm, nullptr));
}

}  // namespace
}  // namespace ffeti
