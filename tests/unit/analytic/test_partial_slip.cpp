// Cattaneo–Mindlin partial slip of two similar cylinders: equilibrium, Coulomb's law in the
// slip zones and below it in the stick zone, and (independently of the formula) no relative
// tangential strain of the surfaces where they stick.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vector>

#include "hpcontact/analytic/partial_slip.hpp"
#include "hpcontact/basis/quadrature.hpp"

using namespace hpcontact::analytic;

namespace {
constexpr double pi = std::numbers::pi;

// Two steel cylinders R = 10 (R* = 5, E* = E / (2 (1 - nu²))), the seed's load, mu = 0.3.
const double kRadius = pair_radius(10, 10);
const double kModulus = pair_modulus(contact_modulus(210000, 0.3, true), contact_modulus(210000, 0.3, true));
constexpr double kForce = 70000, kMu = 0.3;

PartialSlip slip_at(double Q_over_muP) {
  return PartialSlip(kRadius, kForce, kModulus, kMu, Q_over_muP * kMu * kForce);
}

/// ∫ f over [l, r] by 200-point Gauss–Legendre in u, s = l + (r - l)(1 - cos(pi u))/2, u in
/// [0, 1]: the points cluster at both ends, where the tractions have square-root behaviour.
double integrate(const std::function<double(double)>& f, double l, double r) {
  const auto& g = hpcontact::basis::gauss_legendre(200);
  double sum = 0;
  for (size_t i = 0; i < g.points.size(); ++i) {
    const double u = 0.5 * (g.points[i] + 1);
    const double s = l + 0.5 * (r - l) * (1 - std::cos(pi * u));
    sum += 0.5 * g.weights[i] * 0.5 * (r - l) * pi * std::sin(pi * u) * f(s);
  }
  return sum;
}

/// ∫ f over [-a, a], in pieces between the sorted break points (the kinks of the integrand).
double integrate_pieces(const std::function<double(double)>& f, std::vector<double> breaks) {
  std::sort(breaks.begin(), breaks.end());
  double sum = 0;
  for (size_t k = 0; k + 1 < breaks.size(); ++k)
    if (breaks[k + 1] > breaks[k]) sum += integrate(f, breaks[k], breaks[k + 1]);
  return sum;
}

/// D(x) = PV ∫_{-a}^{a} q(s) / (x - s) ds, |x| < a: the relative tangential surface strain of
/// the two half-spaces is -2 / (pi E*) D(x) (Johnson eq. 2.25b; the normal tractions' terms
/// cancel between similar bodies). Regularised: ∫ (q(s) - q(x)) / (x - s) ds + q(x) ln((a + x)/(a - x)),
/// in pieces between the kinks -a, -c, c, a of q and x.
double shear_strain_integral(const std::function<double(double)>& q, double a, double c, double x) {
  const double qx = q(x);
  const auto f = [&](double s) { return (q(s) - qx) / (x - s); };
  return integrate_pieces(f, {-a, -c, c, a, x}) + qx * std::log((a + x) / (a - x));
}

double shear_strain_integral(const PartialSlip& ps, double x) {
  return shear_strain_integral([&](double s) { return ps.shear(s); }, ps.half_width(),
                               ps.stick_half_width(), x);
}
}  // namespace

// The stick zone's half width is a sqrt(1 - Q / (mu P)): c -> a as Q -> 0 (no shear at all),
// c = 0 at Q = mu P (gross slip: q = mu p everywhere).
TEST(PartialSlip, StickZoneBetweenNoShearAndGrossSlip) {
  const auto none = slip_at(0.0), gross = slip_at(1.0), half = slip_at(0.5);
  const double a = half.half_width();
  EXPECT_NEAR(a, Hertz::pair(kRadius, kForce, kModulus).half_width(), 1e-14 * a);
  EXPECT_NEAR(none.stick_half_width(), a, 1e-14 * a);
  EXPECT_EQ(gross.stick_half_width(), 0.0);
  EXPECT_NEAR(half.stick_half_width(), a / std::sqrt(2.0), 1e-14 * a);
  EXPECT_NEAR(slip_at(1e-8).stick_half_width(), a, 1e-7 * a);
  EXPECT_NEAR(slip_at(1 - 1e-8).stick_half_width(), 0.0, 1e-3 * a);
  for (double x : {-0.9 * a, 0.0, 0.3 * a}) {
    EXPECT_EQ(none.shear(x), 0.0) << x;
    EXPECT_NEAR(gross.shear(x), kMu * gross.pressure(x), 1e-12 * gross.peak_pressure()) << x;
  }
}

// Equilibrium: ∫ p dx = P and ∫ q dx = Q, to quadrature accuracy, for several Q / (mu P).
TEST(PartialSlip, TractionsIntegrateToTheForces) {
  for (double r : {0.1, 0.5, 0.9}) {
    const auto ps = slip_at(r);
    const double a = ps.half_width(), c = ps.stick_half_width();
    const double P = integrate_pieces([&](double x) { return ps.pressure(x); }, {-a, a});
    const double Q = integrate_pieces([&](double x) { return ps.shear(x); }, {-a, -c, c, a});
    EXPECT_NEAR(P, kForce, 1e-12 * kForce) << r;
    EXPECT_NEAR(Q, r * kMu * kForce, 1e-12 * kForce) << r;
  }
}

// Coulomb's law: q = mu p in the slip zones c <= |x| < a, 0 <= q < mu p in the stick zone,
// q continuous at |x| = c, and zero outside the contact.
TEST(PartialSlip, CoulombInSlipBelowItInStick) {
  const auto ps = slip_at(0.6);
  const double a = ps.half_width(), c = ps.stick_half_width(), p0 = ps.peak_pressure();
  for (int i = -200; i <= 200; ++i) {
    const double x = a * i / 201.0;
    const double q = ps.shear(x), mup = kMu * ps.pressure(x);
    if (std::abs(x) >= c) {
      EXPECT_NEAR(q, mup, 1e-14 * p0) << x;
      EXPECT_FALSE(ps.sticks(x));
    } else {
      EXPECT_TRUE(ps.sticks(x));
      EXPECT_GE(q, 0.0) << x;
      EXPECT_LT(q, mup) << x;
    }
  }
  for (double side : {-1.0, 1.0}) {
    const double eps = 1e-12 * c;
    EXPECT_NEAR(ps.shear(side * (c - eps)), ps.shear(side * (c + eps)), 1e-5 * p0);
    EXPECT_EQ(ps.shear(side * 1.0001 * a), 0.0);
    EXPECT_EQ(ps.pressure(side * 1.0001 * a), 0.0);
  }
}

// The real check of the formula, by the half-space's influence function and not the formula's
// own algebra: where the surfaces stick, their relative tangential displacement is a rigid
// shift (D(x) = 0 for |x| < c, to 1e-9 of mu pi p0); where they slip, it is not, and the slip
// grows from 0 at |x| = c in the same direction in both slip zones (D odd, nonzero).
TEST(PartialSlip, SticksRigidlyInsideSlipsOutside) {
  for (double r : {0.3, 0.75}) {
    const auto ps = slip_at(r);
    const double a = ps.half_width(), c = ps.stick_half_width();
    const double scale = kMu * pi * ps.peak_pressure();
    for (double t : {-0.97, -0.6, -0.2, 0.0, 0.35, 0.8, 0.99})
      EXPECT_NEAR(shear_strain_integral(ps, t * c), 0.0, 1e-9 * scale) << r << ' ' << t;
    for (double t : {0.1, 0.5, 0.9}) {
      const double x = c + t * (a - c);
      const double right = shear_strain_integral(ps, x), left = shear_strain_integral(ps, -x);
      EXPECT_GT(std::abs(right), 1e-3 * scale) << r << ' ' << t;
      EXPECT_NEAR(left, -right, 1e-9 * scale) << r << ' ' << t;
    }
  }
}

// The check can fail: the same shapes with the stick term's factor c/a left out (a shear of the
// same zones, continuous at |x| = c) strain the stick zone.
TEST(PartialSlip, WrongStickCorrectionWouldStrain) {
  const auto ps = slip_at(0.5);
  const double a = ps.half_width(), c = ps.stick_half_width(), p0 = ps.peak_pressure();
  const auto wrong = [&](double x) {
    const auto e = [](double x, double w) { return std::abs(x) < w ? std::sqrt(1 - x * x / (w * w)) : 0.0; };
    return kMu * p0 * (e(x, a) - e(x, c));
  };
  EXPECT_GT(std::abs(shear_strain_integral(wrong, a, c, 0.5 * c)), 1e-3 * kMu * pi * p0);
}
