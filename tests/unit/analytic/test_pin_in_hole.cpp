// Persson's pin in a hole against limits and properties that do not use its solution method.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hpcontact/analytic/hertz.hpp"
#include "hpcontact/analytic/lame.hpp"
#include "hpcontact/analytic/pin_in_hole.hpp"
#include "hpcontact/basis/quadrature.hpp"

using namespace hpcontact::analytic;
using std::numbers::pi;

namespace {
/// Steel pin (R1 = 10 mm) in a steel plate, ΔR/R1 = 1e-3, plane strain.
PinInHole steel() { return {10.0, 10.01, 210000, 0.3, 210000, 0.3}; }
/// An aluminium plate (β = −0.17 against the steel pin: the curvature's sign term acts).
PinInHole steel_in_aluminium() { return {10.0, 10.01, 210000, 0.3, 70000, 0.33}; }

/// Nodes θ and weights of ∫_{−ε}^{ε} f(θ) dθ for a density with square-root ends: θ = ε sin(πu/2)
/// makes it smooth in u; `panels` Gauss–Legendre panels of 20 points on [−1, 1].
struct ArcRule {
  std::vector<double> theta, weight;
  ArcRule(double eps, int panels) {
    const auto& rule = hpcontact::basis::gauss_legendre(20);
    for (int k = 0; k < panels; ++k) {
      const double u0 = -1 + 2.0 * k / panels, h = 2.0 / panels;
      for (int i = 0; i < rule.size(); ++i) {
        const double u = u0 + 0.5 * h * (rule.points[i] + 1);
        theta.push_back(eps * std::sin(0.5 * pi * u));
        weight.push_back(rule.weights[i] * eps * 0.5 * pi * std::cos(0.5 * pi * u) * 0.5 * h);
      }
    }
  }
};

template <class F>
double integrate_over_arc(double eps, F f, int panels = 1) {
  const ArcRule rule(eps, panels);
  double sum = 0;
  for (size_t i = 0; i < rule.theta.size(); ++i) sum += rule.weight[i] * f(rule.theta[i]);
  return sum;
}
}  // namespace

// For small loads the contact is Hertz's of a cylinder in a concave cylinder: R* = R1 R2/(R2 − R1),
// b = sqrt(4 P R*/(π E*)), half-angle b/R1, peak 2P/(π b); the relative difference falls as ε²
// (with ΔR/R1 = 1e-9, so that the linear theory's O(ΔR/R) is out of the comparison).
TEST(PinInHole, SmallLoadsGiveHertzsContact) {
  PinInHole q = steel();
  q.hole_radius = q.pin_radius * (1 + 1e-9);
  const double E_star = pair_modulus(contact_modulus(210000, 0.3, true),
                                     contact_modulus(210000, 0.3, true));
  const double R_star = pair_radius(q.pin_radius, -q.hole_radius);
  for (double eps_hertz : {0.003, 0.01, 0.03}) {
    const double b = eps_hertz * q.pin_radius;
    const double P = pi * E_star * b * b / (4 * R_star);
    const Hertz hertz = Hertz::pair(R_star, P, E_star);
    ASSERT_NEAR(hertz.half_width(), b, 1e-12 * b);
    const auto contact = PinInHoleContact::at_force(q, P);
    EXPECT_NEAR(contact.half_angle() / eps_hertz, 1, 0.5 * eps_hertz * eps_hertz + 1e-8) << P;
    EXPECT_NEAR(contact.pressure(0) / hertz.peak_pressure(), 1, 0.5 * eps_hertz * eps_hertz + 1e-8);
    // and the contact is narrower than Hertz's (the hole's wall wraps round the pin)
    EXPECT_LT(contact.half_angle(), eps_hertz);
  }
}

// The pressure carries the force: ∫ p(θ) cos θ R1 dθ = P to 1e-10, for similar and dissimilar
// bodies, an infinite plate and a held ring with a pin on a rigid core.
TEST(PinInHole, PressureIntegratesToTheForce) {
  PinInHole ring = steel_in_aluminium();
  ring.plate_outer_radius = 50;
  ring.pin_core_radius = 2;
  for (const PinInHole& q : {steel(), steel_in_aluminium(), ring})
    for (double eps : {0.2, 0.8, 1.3}) {
      const PinInHoleContact c(q, eps);
      const double P = integrate_over_arc(
          eps, [&](double th) { return c.pressure(th) * std::cos(th) * q.pin_radius; }, 4);
      EXPECT_NEAR(P, c.force(), 1e-10 * c.force()) << eps;
      EXPECT_GT(c.pressure(0.99 * eps), 0);
      EXPECT_EQ(c.pressure(1.01 * eps), 0);
    }
}

// The gap equation, summed as the Fourier series of Michell's modes (no kernel in closed form, no
// change of variable): g(θ) = ΔR − δ cos θ + Σ_{n != 1} Λ_n p_n cos nθ vanishes on the arc (to the
// series' truncation, 2e-6 ΔR at 1500 modes) once δ is taken from g(0) = 0, and is positive
// outside it.
TEST(PinInHole, GapClosesOnTheArcAndOpensOutside) {
  PinInHole ring = steel_in_aluminium();
  ring.plate_outer_radius = 40;
  for (const PinInHole& q : {steel(), steel_in_aluminium(), ring})
    for (double eps : {0.35, 1.2}) {
      const PinInHoleContact c(q, eps);
      const double dR = q.hole_radius - q.pin_radius;
      const int n_modes = 1500;
      const ArcRule rule(eps, 200);
      std::vector<double> weighted_pressure;  // w_j p(θ_j)
      for (size_t j = 0; j < rule.theta.size(); ++j)
        weighted_pressure.push_back(rule.weight[j] * c.pressure(rule.theta[j]));
      std::vector<double> modes(n_modes + 1, 0.0);  // Λ_n p_n
      for (int n = 0; n <= n_modes; ++n) {
        if (n == 1) continue;
        double p_n = 0;
        for (size_t j = 0; j < rule.theta.size(); ++j)
          p_n += weighted_pressure[j] * std::cos(n * rule.theta[j]);
        modes[n] = pin_in_hole_gap_compliance(q, n) * p_n / (n == 0 ? 2 * pi : pi);
      }
      auto opening = [&](double th) {
        double s = 0;
        for (int n = 0; n <= n_modes; ++n) s += modes[n] * std::cos(n * th);
        return s;
      };
      const double delta = dR + opening(0);
      auto gap = [&](double th) { return dR - delta * std::cos(th) + opening(th); };
      for (double f : {0.2, 0.5, 0.8, 0.95}) EXPECT_NEAR(gap(f * eps) / dR, 0, 2e-6) << eps << " " << f;
      for (double th : {1.1 * eps, 0.5 * (eps + pi), pi}) EXPECT_GT(gap(th) / dR, 1e-3) << eps;
    }
}

// Elastically similar bodies in an infinite plate: P/(E* ΔR) is a function of ε alone, the same
// for any ν, E and plane stress or strain (Λ_n = (2R/E*) n/(n² − 1), Λ_0 = R/E*).
TEST(PinInHole, SimilarBodiesDependOnTheContactModulusAlone) {
  PinInHole a = steel(), b = steel();
  b.pin_youngs_modulus = b.plate_youngs_modulus = 1000;
  b.pin_poisson_ratio = b.plate_poisson_ratio = 0.45;
  PinInHole c = b;
  c.plane_strain = false;
  c.pin_poisson_ratio = c.plate_poisson_ratio = 0.1;
  for (double eps : {0.3, 1.0, 1.4}) {
    auto scaled = [&](const PinInHole& q) {
      return pin_in_hole_force(q, eps) / (pin_in_hole_modulus(q) * (q.hole_radius - q.pin_radius));
    };
    EXPECT_NEAR(scaled(b) / scaled(a), 1, 1e-10) << eps;
    EXPECT_NEAR(scaled(c) / scaled(a), 1, 1e-10) << eps;
  }
  EXPECT_NEAR(pin_in_hole_limit_half_angle(b), pin_in_hole_limit_half_angle(a), 1e-10);
}

// A held ring of outer radius R_out: its uniform mode is Lamé's cylinder with the outer pressure
// that holds r = R_out; every mode tends to the infinite plate's, and the contact angle's change
// falls as (R1/R_out)² (a quarter from R_out/R1 = 10 to 20). So does that of a rigid core.
TEST(PinInHole, HeldRingTendsToTheInfinitePlate) {
  PinInHole q = steel();
  q.pin_youngs_modulus = 1e30;  // the plate's compliance alone
  q.plate_outer_radius = 100;
  const double R = q.pin_radius, E = q.plate_youngs_modulus, nu = q.plate_poisson_ratio;
  // Lamé: u_r(R_out) is linear in p_o; choose p_o so that it vanishes.
  const Lame open{R, q.plate_outer_radius, 1.0, 0.0, E, nu};
  const Lame pressed{R, q.plate_outer_radius, 1.0, 1.0, E, nu};
  const double u0 = open.radial_displacement(q.plate_outer_radius);
  const double u1 = pressed.radial_displacement(q.plate_outer_radius);
  const Lame held{R, q.plate_outer_radius, 1.0, u0 / (u0 - u1), E, nu};
  EXPECT_NEAR(held.radial_displacement(q.plate_outer_radius), 0, 1e-15);
  EXPECT_NEAR(pin_in_hole_gap_compliance(q, 0), held.radial_displacement(R),
              1e-12 * held.radial_displacement(R));

  PinInHole far = q, infinite = q;
  far.plate_outer_radius = 1e5 * R;
  infinite.plate_outer_radius = std::numeric_limits<double>::infinity();
  for (int n : {0, 2, 3, 7, 30}) {
    EXPECT_NEAR(pin_in_hole_gap_compliance(far, n) / pin_in_hole_gap_compliance(infinite, n), 1,
                1e-8) << n;
    EXPECT_LT(pin_in_hole_gap_compliance(q, n), pin_in_hole_gap_compliance(infinite, n)) << n;
  }

  const double P = pin_in_hole_force(steel(), 0.8);
  auto change = [&](double outer, double core) {
    PinInHole r = steel();
    r.plate_outer_radius = outer;
    r.pin_core_radius = core;
    return pin_in_hole_half_angle(r, P) - 0.8;
  };
  EXPECT_NEAR(pin_in_hole_half_angle(steel(), P), 0.8, 1e-12);
  const double ring_ratio = change(20 * R, 0) / change(10 * R, 0);
  EXPECT_GT(ring_ratio, 0.22);
  EXPECT_LT(ring_ratio, 0.28);
  EXPECT_LT(change(10 * R, 0), 0);  // a stiffer plate: a narrower contact
  const double core_ratio = change(std::numeric_limits<double>::infinity(), 0.05 * R) /
                            change(std::numeric_limits<double>::infinity(), 0.1 * R);
  EXPECT_GT(core_ratio, 0.22);
  EXPECT_LT(core_ratio, 0.28);
}

// The load grows without bound as ε tends to the zero-clearance angle: P rises monotonically
// below it and the force for a half-angle and the half-angle for that force invert each other.
TEST(PinInHole, ForceAndHalfAngleInvertEachOther) {
  for (const PinInHole& q : {steel(), steel_in_aluminium()}) {
    const double limit = pin_in_hole_limit_half_angle(q);
    double previous = 0;
    for (double eps : {0.1, 0.4, 0.8, 1.2, limit - 0.01}) {
      const double P = pin_in_hole_force(q, eps);
      EXPECT_GT(P, previous) << eps;
      previous = P;
      EXPECT_NEAR(pin_in_hole_half_angle(q, P), eps, 1e-11) << eps;
    }
    EXPECT_GT(pin_in_hole_force(q, limit - 1e-6), 100 * pin_in_hole_force(q, limit - 0.01));
  }
}
