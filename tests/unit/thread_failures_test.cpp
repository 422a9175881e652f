// Failures inside threaded loops: every item runs, the lowest failing item's exception comes
// out of the loop (not std::terminate from inside a thread), and a loop that a collective
// step follows rethrows it on every rank.
#include "base/errors.h"
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

/// Rank 0 of two, the other rank healthy: first_error passes this rank's error on as an MPI
/// communicator does (prefixed by the failing rank); the rest is not used by collectively.
class TwoRanksFirstOfThem final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 2; }
  std::vector<double> allgather(const std::vector<double>& local, std::vector<int>*) const override { return local; }
  std::vector<long long> allgather(const std::vector<long long>& local, std::vector<int>*) const override {
    return local;
  }
  void allgather_known(const std::vector<double>&, const std::vector<int>&, const std::vector<int>&,
                       std::vector<double>&) const override {}
  double sum(double local) const override { return local; }
  double max(double local) const override { return local; }
  std::string first_error(const std::string& local_error) const override {
    return local_error.empty() ? "" : "rank 0: " + local_error;
  }
};

TEST(ThreadFailures, OnSeveralRanksBadInputAndOtherFailuresKeepTheirKind) {
  const TwoRanksFirstOfThem comm;
  // A failure that is not the input's (memory, a library) must not read as bad input: ffeti-solve
  // exits 2 for bad input, 3 for such failures.
  try {
    collectively(comm, [] { throw std::runtime_error("a factorization ran out of memory (CHOLMOD)"); });
    FAIL() << "no exception";
  } catch (const InputError&) {
    FAIL() << "a memory failure came out as bad input";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "rank 0: a factorization ran out of memory (CHOLMOD)");
  }
  try {
    collectively(comm, [] { throw InputError("K[3]: not symmetric"); });
    FAIL() << "no exception";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "rank 0: K[3]: not symmetric");
  }
  EXPECT_NO_THROW(collectively(comm, [] {}));
}

}  // namespace
}  // namespace ffeti
