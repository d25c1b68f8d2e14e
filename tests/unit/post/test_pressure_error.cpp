// The pressure error measures, checked on the closed forms themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/post/pressure_error.hpp"

using namespace hpcontact;

// Hertz measured against Shtayerman (R = 10, F = 70000, E = 210000, nu = 0.3): the graded
// composite Gauss rule agrees with a brute-force midpoint rule of 200000 points (1e-3 relative).
// Both give e_L2 = 1.369 % and e_seed = 0.0160 %; docs/cases.md quotes 1.97 % and 0.033 % for the same
// pair, a factor 2.07 in the squared difference that we could not reproduce by any choice of
// interval or normalisation (see the issue note).
TEST(PressureErrors, HertzAgainstShtayermanMatchesBruteForce) {
  const analytic::Hertz h{10, 70000, 210000, 0.3};
  const auto s = analytic::Shtayerman::circle(10, 70000, 210000, 0.3);
  const double b = s.half_width(), p0 = h.peak_pressure();
  const auto e = post::pressure_errors([&](double x) { return h.pressure(x); },
                                       [&](double x) { return s.pressure(x); }, b, p0);
  double d2 = 0, r2 = 0, r1 = 0;
  const int n = 200000;
  const double L = 1.5 * b;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * L / n, pr = s.pressure(x), d = pr - h.pressure(x);
    d2 += d * d * L / n;
    r2 += pr * pr * L / n;
    r1 += pr * L / n;
  }
  EXPECT_NEAR(e.e_L2, 100 * std::sqrt(d2 / r2), 1e-3 * e.e_L2);
  EXPECT_NEAR(e.e_seed, 100 * d2 / (p0 * p0) / (r1 / p0), 1e-3 * e.e_seed);
  EXPECT_NEAR(e.e_L2, 1.369, 0.002);
}

// A pressure equal to the reference has zero error; one 1 % too high everywhere has e_L2 = 1 %.
TEST(PressureErrors, ExactAndScaled) {
  const analytic::Hertz h{10, 70000, 210000, 0.3};
  auto ref = [&](double x) { return h.pressure(x); };
  const auto zero = post::pressure_errors(ref, ref, h.half_width(), h.peak_pressure());
  EXPECT_EQ(zero.e_L2, 0.0);
  EXPECT_EQ(zero.e_seed, 0.0);
  const auto one = post::pressure_errors([&](double x) { return 1.01 * h.pressure(x); }, ref,
                                         h.half_width(), h.peak_pressure());
  EXPECT_NEAR(one.e_L2, 1.0, 1e-9);
}

// A pressure whose own zone ends at b' = 0.9937 b, inside a piece of the graded rule (a sampled
// reference ends so, at the sample where it reaches zero): against Hertz's, with b' given as a
// break the square-root end lies at a piece's end and 8 points a piece agree with a brute-force
// midpoint rule of 10⁶ points to 1e-6 (measured 6e-8); without the break the same points do
// worse (the plain rule's 20 points: 8.6e-6).
TEST(PressureErrors, ABreakAtTheOtherZoneEnd) {
  const analytic::Hertz h{10, 70000, 210000, 0.3};
  const double b = h.half_width(), p0 = h.peak_pressure(), b2 = 0.9937 * b;
  auto ref = [&](double x) { return h.pressure(x); };
  auto p = [&](double x) { return std::abs(x) < b2 ? 1.004 * p0 * std::sqrt(1 - x * x / (b2 * b2)) : 0.0; };
  double d2 = 0, r2 = 0;
  const int n = 1000000;
  const double L = 1.5 * b;
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * L / n, d = ref(x) - p(x);
    d2 += d * d * L / n;
    r2 += ref(x) * ref(x) * L / n;
  }
  const double brute = 100 * std::sqrt(d2 / r2);
  const auto split = post::pressure_errors(p, ref, b, p0, {b2}, 8);
  const auto unsplit = post::pressure_errors(p, ref, b, p0, {}, 8);
  EXPECT_NEAR(split.e_L2, brute, 1e-6 * brute);
  EXPECT_GT(std::abs(unsplit.e_L2 - brute), std::abs(split.e_L2 - brute));
}
