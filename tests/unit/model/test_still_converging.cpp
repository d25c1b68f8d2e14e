// Which Newton residual histories that ran out of iterations count as still converging
// (model::still_converging): the failure message says "raise solver.max_iterations" for these
// and, for the others, keeps naming a load beyond capacity, a cycling active set, divergence.
#include "hpcontact/model/contact_solve_failure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using hpcontact::model::still_converging;

namespace {

std::vector<double> history(int n, double (*r)(int)) {
  std::vector<double> h;
  for (int i = 0; i <= n; ++i) h.push_back(r(i));
  return h;
}

}  // namespace

TEST(StillConverging, QuadraticConvergenceOneIterationShort) {
  // The rubber ring of tests/cli/test_messages.py at max_iterations = 5.
  EXPECT_TRUE(still_converging({37.68, 0.5208, 0.1944, 0.01527, 1.197e-4, 2.488e-8}));
}

TEST(StillConverging, SteadyLinearConvergence) {
  // A factor 0.8 per iteration: 30 iterations take 20.6 to 0.025.
  EXPECT_TRUE(still_converging(history(30, [](int i) { return 20.6 * std::pow(0.8, i); })));
}

TEST(StillConverging, StagnationIsNot) {
  // Falling by 1 % per iteration: a factor 0.86 over the last 15, no convergence in sight.
  EXPECT_FALSE(still_converging(history(30, [](int i) { return 0.03 * std::pow(0.99, i); })));
  // Level with round-off noise, half of the iterations a hair lower than the one before.
  EXPECT_FALSE(still_converging(history(30, [](int i) { return 0.0295 * (1 + 1e-6 * (i % 2)); })));
}

TEST(StillConverging, CyclingAndDivergenceAreNot) {
  // An active set that cycles between two states.
  EXPECT_FALSE(still_converging(history(30, [](int i) { return i % 2 ? 0.5 : 5.0; })));
  // Three states in turn, ending on the smallest: no fall from one cycle to the next.
  EXPECT_FALSE(still_converging(history(29, [](int i) {
    const int k = i % 3;
    return k == 0 ? 9.0 : (k == 1 ? 3.0 : 1.0);
  })));
  EXPECT_FALSE(still_converging(history(30, [](int i) { return 1e-3 * std::pow(1.5, i); })));
}

TEST(StillConverging, ZigzagConvergenceIs) {
  // Down tenfold, up threefold, in turn (a semi-smooth Newton whose active set still moves):
  // a factor 3.3 in two iterations, ending on a fall.
  EXPECT_TRUE(still_converging(history(29, [](int i) {
    return std::pow(10.0 / 3.0, -(i / 2)) * (i % 2 ? 0.1 : 1.0);
  })));
}

TEST(StillConverging, TooShortAHistoryIsNot) {
  EXPECT_FALSE(still_converging({1.0, 0.1, 0.01}));
  EXPECT_FALSE(still_converging({}));
}
