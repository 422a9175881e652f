// SharedFactors: one build per bitwise-equal (K, fixing dofs, interface), none for anything
// else, the waiting threads get the builder's outcome (or its exception).
#include "factor/shared_factors.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace ffeti {
namespace {

SparseMatrix path_laplacian(int n, double scale) {
  std::vector<Eigen::Triplet<double, int>> entries;
  for (int i = 0; i < n; ++i) {
    entries.emplace_back(i, i, 2.0 * scale);
    if (i + 1 < n) entries.emplace_back(i + 1, i, -scale), entries.emplace_back(i, i + 1, -scale);
  }
  SparseMatrix K(n, n);
  K.setFromTriplets(entries.begin(), entries.end());
  K.makeCompressed();
  return K;
}

/// A build that counts its calls and returns a fresh (unfactorized) factor to compare by address.
struct CountingBuild {
  std::atomic<int> calls{0};
  FactorOutcome operator()() {
    ++calls;
    FactorOutcome outcome;
    outcome.factor = std::make_shared<CholmodFactor>();
    outcome.residual = 1e-16;
    return outcome;
  }
};

TEST(SharedFactors, EqualTriplesBuildOnceAndAnyDifferenceBuildsAgain) {
  // The matrices outlive `shared` (it keeps them by reference): declared before it.
  const SparseMatrix K = path_laplacian(20, 1.0), copy = K, bigger = path_laplacian(21, 1.0);
  SparseMatrix one_ulp = K;
  one_ulp.valuePtr()[5] = std::nextafter(one_ulp.valuePtr()[5], 10.0);
  SharedFactors shared;
  CountingBuild build;
  const auto run = [&build] { return build(); };
  const FactorOutcome first = shared.obtain(K, {0}, {3, 7}, run);
  const FactorOutcome again = shared.obtain(copy, {0}, {3, 7}, run);
  EXPECT_EQ(build.calls, 1);
  EXPECT_EQ(first.factor.get(), again.factor.get());
  EXPECT_EQ(again.residual, first.residual);

  const FactorOutcome other_value = shared.obtain(one_ulp, {0}, {3, 7}, run);
  const FactorOutcome other_fixing = shared.obtain(K, {1}, {3, 7}, run);
  const FactorOutcome other_interface = shared.obtain(K, {0}, {3, 8}, run);
  const FactorOutcome other_size = shared.obtain(bigger, {0}, {3, 7}, run);
  EXPECT_EQ(build.calls, 5);
  for (const FactorOutcome* o : {&other_value, &other_fixing, &other_interface, &other_size})
    EXPECT_NE(o->factor.get(), first.factor.get());
  EXPECT_EQ(shared.built(), 5);
  EXPECT_EQ(shared.reused(), 1);
}

TEST(SharedFactors, ThreadsAskingForOneTripleWaitForASingleBuild) {
  const SparseMatrix K = path_laplacian(50, 3.0);
  SharedFactors shared;
  std::atomic<int> calls{0};
  const auto slow_build = [&calls] {
    ++calls;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the others arrive meanwhile
    FactorOutcome outcome;
    outcome.factor = std::make_shared<CholmodFactor>();
    return outcome;
  };
  std::vector<const CholmodFactor*> got(4);
  std::vector<std::thread> threads;
  for (size_t t = 0; t < got.size(); ++t)
    threads.emplace_back([&, t] { got[t] = shared.obtain(K, {}, {1, 2}, slow_build).factor.get(); });
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(calls, 1);
  for (const CholmodFactor* f : got) EXPECT_EQ(f, got[0]);
}

TEST(SharedFactors, AFailedBuildFailsEverySubdomainThatWouldShareIt) {
  const SparseMatrix K = path_laplacian(10, 1.0);
  SharedFactors shared;
  int calls = 0;
  const auto failing = [&calls]() -> FactorOutcome {
    ++calls;
    throw std::runtime_error("CHOLMOD allocation failed");
  };
  EXPECT_THROW(shared.obtain(K, {}, {}, failing), std::runtime_error);
  EXPECT_THROW(shared.obtain(K, {}, {}, failing), std::runtime_error);  // the registered outcome: its exception
  EXPECT_EQ(calls, 1);
}

}  // namespace
}  // namespace ffeti
