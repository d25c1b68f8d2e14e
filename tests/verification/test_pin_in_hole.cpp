// Conforming contact: an elastic pin in a hole of radius R + ΔR (ΔR/R = 1e-3, plane strain, both
// steel, the plate held at r = 100), pressed through a rigid core of radius 2, hp to 1e-3 from a
// coarse mesh (examples/pin-in-hole/pin-in-hole.yaml), against Persson's problem solved by
// analytic::PinInHoleContact for the same core and plate.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "hpcontact/analytic/pin_in_hole.hpp"
#include "hpcontact/driver/run.hpp"
#include "hpcontact/io/problem_reader.hpp"

using namespace hpcontact;

namespace {

std::string example() { return std::string(HPC_SOURCE_DIR) + "/examples/pin-in-hole/pin-in-hole.yaml"; }

analytic::PinInHole persson() {
  analytic::PinInHole p{10, 10.01, 210000, 0.3, 210000, 0.3};
  p.plate_outer_radius = 100;
  p.pin_core_radius = 2;
  return p;
}

struct Figures {
  double half_angle_deg, pressure_max, normal_force, strain_energy;
  int dofs;
};

/// The example run at the force P on the whole pin (its half model carries P/2).
Figures run_at(double P) {
  const auto spec = io::read_problem(example(), {"solver.target_resultant.value=" + std::to_string(P / 2)});
  const auto r = driver::run_problem(spec, {});
  const auto& pair = r.summary.extra.at("contact_pairs").at(0);
  // the zone end's angle about the hole's centre, from the load line (the bottom, -90°)
  const auto& angles = pair.at("gamma_star_angles");
  EXPECT_EQ(angles.size(), 1u) << "one zone end, listed once";
  return {90 + angles.at(0).get<double>(), pair.at("pressure_max").get<double>(),
          pair.at("normal_force").get<double>(), r.summary.strain_energy, r.summary.dofs};
}

}  // namespace

// From 20° to 75°: the contact arc's half-angle within 0.2 % of Persson's and the pressure per
// unit arc length at the load line (the largest) within 0.5 % (measured 0.015-0.052 % and
// 0.025-0.2 %, with 836-1282 DOF); the normal force is the applied load to 1e-6 (force control of
// the core's push, normal_direction [0, 1]). The linear theory itself is uncertain to about 5e-4
// in the angle at ΔR/R = 1e-3 (which radius the contact is posed on).
TEST(PinInHole, ContactArcAndPressureArePerssonsFrom20To75Degrees) {
  for (const double P : {118.13, 400.0, 817.43, 3000.0, 8038.6}) {
    const auto exact = analytic::PinInHoleContact::at_force(persson(), P);
    const double eps = exact.half_angle() * 180 / std::numbers::pi;
    const Figures f = run_at(P);
    std::printf("P %g: half-angle %.5f° (Persson %.5f°, %.3g), p(0) %.5f (Persson %.5f, %.3g), %d DOF\n",
                P, f.half_angle_deg, eps, f.half_angle_deg / eps - 1, f.pressure_max, exact.pressure(0),
                f.pressure_max / exact.pressure(0) - 1, f.dofs);
    EXPECT_NEAR(f.half_angle_deg, eps, 2e-3 * eps) << P;
    EXPECT_NEAR(f.pressure_max, exact.pressure(0), 5e-3 * exact.pressure(0)) << P;
    EXPECT_NEAR(f.normal_force, P / 2, 1e-6 * P / 2) << P;
  }
  EXPECT_LT(analytic::PinInHoleContact::at_force(persson(), 118.13).half_angle() * 180 / std::numbers::pi, 20.5);
  EXPECT_GT(analytic::PinInHoleContact::at_force(persson(), 8038.6).half_angle() * 180 / std::numbers::pi, 74);
}

// The same run twice gives the same figures (no state kept between runs, no order dependence).
TEST(PinInHole, TheSameRunTwiceGivesTheSameFigures) {
  const Figures a = run_at(817.43), b = run_at(817.43);
  EXPECT_EQ(a.half_angle_deg, b.half_angle_deg);
  EXPECT_EQ(a.pressure_max, b.pressure_max);
  EXPECT_EQ(a.normal_force, b.normal_force);
  EXPECT_EQ(a.strain_energy, b.strain_energy);
  EXPECT_EQ(a.dofs, b.dofs);
}
