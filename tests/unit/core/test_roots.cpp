// The Pegasus root finder shared by the contact-zone ends, the pressure probe and the projection.
#include <gtest/gtest.h>

#include <cmath>

#include "hpcontact/core/roots.hpp"

using hpcontact::pegasus_root;

// A root inside the bracket is found to the function tolerance, from either orientation of
// the bracket, with few evaluations where plain regula falsi would stall (a convex function).
TEST(PegasusRoot, FindsTheRootOfAConvexFunction) {
  int calls = 0;
  auto f = [&](double x) {
    ++calls;
    return std::exp(x) - 2.0;  // root ln 2, convex: regula falsi keeps one end for ever
  };
  const double r = pegasus_root(f, 0.0, 3.0, f(0.0), f(3.0), 1e-14);
  EXPECT_NEAR(r, std::log(2.0), 1e-13);
  EXPECT_LT(calls, 20);
  const double s = pegasus_root(f, 3.0, 0.0, f(3.0), f(0.0), 1e-14);
  EXPECT_NEAR(s, std::log(2.0), 1e-13);
}

// A bracket end that is a root is returned as it is.
TEST(PegasusRoot, ReturnsABracketEndThatIsARoot) {
  auto f = [](double x) { return x * x - 1.0; };
  EXPECT_EQ(pegasus_root(f, 1.0, 3.0, 0.0, 8.0, 1e-14), 1.0);
  EXPECT_EQ(pegasus_root(f, -3.0, -1.0, 8.0, 0.0, 1e-14), -1.0);
}
