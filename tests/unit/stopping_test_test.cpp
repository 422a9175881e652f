// RelativeKktStop on scripted primal checks: a solve whose primal residual stands still at
// round-off, just above tol, stops early as stagnated; one that stands still far above
// round-off is not (maxit ends it); one that reaches tol passes.
#include "qp/stopping_test.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace ffeti {
namespace {

/// Calls the test as a solver would, the gradient falling tenfold per call down to `floor`
/// and a new iterate each call; returns the calls until it said stop (or `limit`).
long calls_until_stop(RelativeKktStop& stop, double floor, long limit = 100000) {
  const RelativeKktStop::Multipliers mu = []() -> const Vec& {
    static const Vec none;
    return none;
  };
  for (long call = 1; call <= limit; ++call) {
    const Vec x = Vec::Constant(1, static_cast<double>(call));
    if (stop(x, mu, std::max(floor, std::pow(10.0, -static_cast<double>(call))))) return call;
  }
  return limit;
}

PrimalCheck check_with(double measure) { return {1.0, measure, 0.0}; }

TEST(RelativeKktStop, StopsEarlyAsStagnatedWhereTheResidualStandsAtRoundOff) {
  // The node-to-face sphere at tol 1e-12: the residual reached 1.29e-12 and stayed.
  RelativeKktStop stop(1e-12, [](const Vec&) { return check_with(1.29e-12); });
  const long calls = calls_until_stop(stop, 1.56e-14);
  EXPECT_TRUE(stop.stagnated());
  EXPECT_LE(calls, 200);
  EXPECT_DOUBLE_EQ(stop.measure(), 1.29e-12);
}

TEST(RelativeKktStop, ResidualFarAboveRoundOffIsNotStagnation) {
  // A residual that stands at 0.3 (a recovery that misreads the active set) is not round-off:
  // the test goes on checking, and the solver's maxit ends the solve.
  RelativeKktStop stop(1e-4, [](const Vec&) { return check_with(0.3); });
  const long calls = calls_until_stop(stop, 1e-16, 5000);
  EXPECT_FALSE(stop.stagnated());
  EXPECT_EQ(calls, 5000);
}

TEST(RelativeKktStop, ResidualThatKeepsFallingIsNotStagnation) {
  // The residual halves at every check until it meets tol: converged, not stagnated.
  int checks = 0;
  RelativeKktStop stop(1e-10, [&](const Vec&) { return check_with(1e-6 * std::pow(0.4, checks++)); });
  calls_until_stop(stop, 1e-20);
  EXPECT_FALSE(stop.stagnated());
  EXPECT_LE(stop.measure(), 1e-10);
}

}  // namespace
}  // namespace ffeti
