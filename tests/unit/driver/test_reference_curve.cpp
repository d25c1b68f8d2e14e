// A reference pressure read from a CSV, between its samples: the square-root end of a contact
// zone must survive the interpolation, or a comparison at 1e-4 measures the CSV's spacing.
#include <gtest/gtest.h>

#include <cmath>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/driver/contact_compare.hpp"
#include "hpcontact/post/pressure_error.hpp"

using namespace hpcontact;

namespace {

/// Hertz's pressure sampled as pressure.csv samples a run: 1001 points over [0, 1.5 b] and the
/// zone end itself.
driver::ReferenceCurve sampled(const analytic::Hertz& h) {
  driver::ReferenceCurve r;
  const double b = h.half_width();
  for (int i = 0; i <= 1000; ++i) {
    const double x = 1.5 * b * i / 1000;
    if (x > b && r.x.back() < b) {
      r.x.push_back(b);
      r.p.push_back(0.0);
    }
    r.x.push_back(x);
    r.p.push_back(h.pressure(x));
  }
  return r;
}

}  // namespace

// Hertz's p0 √(1 − x²/b²) from its samples: relative L2 error below 1e-6 (measured 5e-7;
// interpolating p linearly leaves 3e-4, almost all of it in the last interval before b).
TEST(ReferenceCurve, KeepsTheSquareRootEndOfTheZone) {
  const auto h = analytic::Hertz::pair(10.0, 70000.0, 210000.0 / (1 - 0.09) / 2);
  const driver::ReferenceCurve r = sampled(h);
  const auto e = post::pressure_errors([&](double x) { return r(x); },
                                       [&](double x) { return h.pressure(x); }, h.half_width(),
                                       h.peak_pressure());
  EXPECT_LT(e.e_L2, 1e-4);  // percent
  // Between samples of a curve of both signs (a pressure from stresses past the zone end) the
  // interpolation is linear, and it is zero outside the samples.
  driver::ReferenceCurve mixed;
  mixed.x = {0.0, 1.0, 2.0};
  mixed.p = {3.0, -1.0, 4.0};
  EXPECT_DOUBLE_EQ(mixed(0.5), 1.0);
  EXPECT_DOUBLE_EQ(mixed(1.5), 1.5);
  EXPECT_DOUBLE_EQ(mixed(2.5), 0.0);
  // Both ends ≥ 0: p² linear, so halfway between 3 and 4 is 5/√2.
  mixed.p = {3.0, 4.0, 0.0};
  EXPECT_NEAR(mixed(0.5), 5 / std::sqrt(2.0), 1e-15);
  EXPECT_NEAR(mixed(1.75), std::sqrt(0.25 * 16), 1e-15);
}
