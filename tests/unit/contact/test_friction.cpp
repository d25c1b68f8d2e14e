// The Coulomb return mapping at one point against the closed form of a spring–slider.
#include "hpcontact/contact/friction.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

using namespace hpcontact::contact;

namespace {

FrictionLaw coulomb(double mu, double eps_t) {
  FrictionLaw law;
  law.kind = FrictionLaw::Kind::coulomb;
  law.mu = mu;
  law.eps_t = eps_t;
  return law;
}

}  // namespace

// A point driven along g_T = 0 → 3 → −3 → 1 in steps of 0.1 at p_N = 2 (μ = 0.25, ε_T = 4:
// bound μ p_N = 0.5, elastic range g_s ± 0.5/ε_T = g_s ± 0.125) shall follow the spring–slider,
// with the slip carried from step to step: t_T = ε_T (g_T − g_s) inside the range, else the slip
// follows the point at the range's edge and t_T = ±0.5. Worked out by hand: g_T = 0.1 sticks
// (t_T = 0.4), 0.2 slips (g_s = 0.075), … 3 (g_s = 2.875, t_T = 0.5); back: 2.9 and 2.8 stick
// (t_T = 0.1, −0.3), 2.7 slips backwards (g_s = 2.825, t_T = −0.5), … −3 (g_s = −2.875);
// forwards: −2.9, −2.8 stick (t_T = −0.1, 0.3), −2.7 slips, … 1 (g_s = 0.875). Tangent:
// dt/dg_T = ε_T in stick, 0 in slip; dt/dp_N = ±μ in slip, 0 in stick.
TEST(ReturnMap, SpringSliderClosedForm) {
  const FrictionLaw law = coulomb(0.25, 4);
  const double p = 2, bound = 0.5, half = bound / law.eps_t;
  double g_s = 0;
  int sticks = 0, slips = 0;
  std::map<long, Tangential> at;  // by 10 g_T, the last visit
  auto drive = [&](long tenths) {
    const double g = 0.1 * tenths;
    const Tangential r = return_map(law, g, g_s, p);
    const bool slipping = std::abs(g - g_s) > half;
    const double expected_slip = slipping ? g - std::copysign(half, g - g_s) : g_s;
    const double expected_t = slipping ? std::copysign(bound, g - g_s) : law.eps_t * (g - g_s);
    EXPECT_NEAR(r.traction, expected_t, 1e-14) << "g_T " << g;
    EXPECT_NEAR(r.slip, expected_slip, 1e-14) << "g_T " << g;
    EXPECT_EQ(r.state, slipping ? StickSlip::slip : StickSlip::stick) << "g_T " << g;
    EXPECT_EQ(r.dt_dgt, slipping ? 0.0 : law.eps_t) << "g_T " << g;
    EXPECT_EQ(r.dt_dp, slipping ? std::copysign(law.mu, expected_t) : 0.0) << "g_T " << g;
    (slipping ? slips : sticks)++;
    g_s = r.slip;
    at[tenths] = r;
  };
  auto check = [&](long tenths, double t, double slip, StickSlip state) {
    EXPECT_NEAR(at.at(tenths).traction, t, 1e-14) << "g_T " << 0.1 * tenths;
    EXPECT_NEAR(at.at(tenths).slip, slip, 1e-14) << "g_T " << 0.1 * tenths;
    EXPECT_EQ(at.at(tenths).state, state) << "g_T " << 0.1 * tenths;
  };
  for (long k = 1; k <= 30; ++k) drive(k);
  check(1, 0.4, 0, StickSlip::stick);
  check(2, 0.5, 0.075, StickSlip::slip);
  check(30, 0.5, 2.875, StickSlip::slip);
  for (long k = 29; k >= -30; --k) drive(k);
  check(29, 0.1, 2.875, StickSlip::stick);
  check(28, -0.3, 2.875, StickSlip::stick);
  check(27, -0.5, 2.825, StickSlip::slip);
  check(-30, -0.5, -2.875, StickSlip::slip);
  for (long k = -29; k <= 10; ++k) drive(k);
  check(-29, -0.1, -2.875, StickSlip::stick);
  check(-28, 0.3, -2.875, StickSlip::stick);
  check(-27, 0.5, -2.825, StickSlip::slip);
  check(10, 0.5, 0.875, StickSlip::slip);
  EXPECT_EQ(sticks, 1 + 2 + 2);
  EXPECT_EQ(slips, 130 - 5);
}

// A converged slip, evaluated again with its committed slip, shall map to the same traction and
// state (the point lies on the cone); a lower pressure with the same slip shall slip further,
// with the traction following μ p_N.
TEST(ReturnMap, CommittedSlipIsAFixedPointAndFollowsThePressure) {
  const FrictionLaw law = coulomb(0.3, 1000);
  const Tangential first = return_map(law, 0.01, 0.0, 10);  // trial 10 > 3: slip
  ASSERT_EQ(first.state, StickSlip::slip);
  EXPECT_NEAR(first.traction, 3, 1e-14);
  EXPECT_NEAR(first.slip, 0.01 - 3.0 / 1000, 1e-16);
  const Tangential again = return_map(law, 0.01, first.slip, 10);
  EXPECT_EQ(again.state, StickSlip::slip);
  EXPECT_NEAR(again.traction, first.traction, 1e-14);
  EXPECT_NEAR(again.slip, first.slip, 1e-16);
  const Tangential lighter = return_map(law, 0.01, first.slip, 5);
  EXPECT_EQ(lighter.state, StickSlip::slip);
  EXPECT_NEAR(lighter.traction, 1.5, 1e-14);
  EXPECT_NEAR(lighter.slip, 0.01 - 1.5 / 1000, 1e-16);
  const Tangential heavier = return_map(law, 0.01, first.slip, 20);
  EXPECT_EQ(heavier.state, StickSlip::stick);
  EXPECT_NEAR(heavier.traction, 3, 1e-12);
}

// Full stick (Kind::stick) shall never slip, whatever the pressure: t_T = ε_T (g_T − g_s).
TEST(ReturnMap, StickLawNeverSlips) {
  FrictionLaw law;
  law.kind = FrictionLaw::Kind::stick;
  law.eps_t = 50;
  for (double p : {0.0, 1.0, 1e6}) {
    const Tangential r = return_map(law, 0.3, 0.1, p);
    EXPECT_EQ(r.state, StickSlip::stick);
    EXPECT_NEAR(r.traction, 10, 1e-13);
    EXPECT_EQ(r.slip, 0.1);
    EXPECT_EQ(r.dt_dgt, 50);
  }
}

// Coulomb's cone, the one stick–slip test of the return mapping and of the exactly enforced
// pairs: at μ p_N = 0.6, a traction of (1 − 1e-4) μ p_N sticks, one of μ p_N (or beyond, or
// within the test's 1e-9 of it) slips, of either sign; at the apex (p_N = 0) every traction
// slips, zero included; under the stick law nothing slips.
TEST(StickOrSlip, CoulombsConeToARelative1em9) {
  const FrictionLaw law = coulomb(0.3, 1);
  const double p = 2, bound = 0.6;
  for (double sign : {1.0, -1.0}) {
    EXPECT_EQ(stick_or_slip(law, sign * (1 - 1e-4) * bound, p), StickSlip::stick) << sign;
    EXPECT_EQ(stick_or_slip(law, sign * (1 - 1e-8) * bound, p), StickSlip::stick) << sign;
    EXPECT_EQ(stick_or_slip(law, sign * (1 - 1e-10) * bound, p), StickSlip::slip) << sign;
    EXPECT_EQ(stick_or_slip(law, sign * bound, p), StickSlip::slip) << sign;
    EXPECT_EQ(stick_or_slip(law, sign * 2 * bound, p), StickSlip::slip) << sign;
    EXPECT_EQ(stick_or_slip(law, sign * 1e-3, 0.0), StickSlip::slip) << sign;
  }
  EXPECT_EQ(stick_or_slip(law, 0.0, p), StickSlip::stick);
  EXPECT_EQ(stick_or_slip(law, 0.0, 0.0), StickSlip::slip);
  FrictionLaw stick = law;
  stick.kind = FrictionLaw::Kind::stick;
  for (double t : {0.0, bound, -2 * bound}) EXPECT_EQ(stick_or_slip(stick, t, p), StickSlip::stick) << t;
}

// The return mapping classifies its trial by that test: a trial (1 − 1e-4) μ p_N sticks and
// keeps it, one of μ p_N slips at the bound with the sign of the trial; a zero trial sticks
// even at p_N = 0 (held by ε_T), unlike a zero traction on the apex of the cone.
TEST(ReturnMap, ClassifiesItsTrialByTheCone) {
  const FrictionLaw law = coulomb(0.3, 10);
  const double p = 2, bound = 0.6;
  for (double sign : {1.0, -1.0}) {
    const Tangential inside = return_map(law, sign * (1 - 1e-4) * bound / 10, 0, p);
    EXPECT_EQ(inside.state, StickSlip::stick) << sign;
    EXPECT_NEAR(inside.traction, sign * (1 - 1e-4) * bound, 1e-15) << sign;
    const Tangential on = return_map(law, sign * bound / 10, 0, p);
    EXPECT_EQ(on.state, StickSlip::slip) << sign;
    EXPECT_EQ(on.traction, sign * bound) << sign;
  }
  const Tangential apex = return_map(law, 0.1, 0.1, 0.0);
  EXPECT_EQ(apex.state, StickSlip::stick);
  EXPECT_EQ(apex.dt_dgt, 10);
}
