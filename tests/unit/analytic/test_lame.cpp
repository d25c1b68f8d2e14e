// Property tests of the Lamé thick-cylinder solution: kinematics, constitutive law, equilibrium,
// boundary tractions, plane strain and plane stress.
#include "hpcontact/analytic/lame.hpp"
#include "hpcontact/basis/quadrature.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

using hpcontact::analytic::Lame;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

constexpr double pi = std::numbers::pi;

std::vector<Lame> cylinders() {
  std::vector<Lame> out;
  for (bool strain : {true, false}) {
    Lame a{1.0, 2.0, 100.0, 0.0, 210000.0, 0.3, strain};
    Lame b{5.0, 6.0, 3.0, 7.0, 1000.0, 0.45, strain};
    b.center = Vector2d(-2, 3);
    Lame c{0.5, 4.0, 0.0, 12.0, 70.0, -0.2, strain};
    c.center = Vector2d(10, 0);
    out.insert(out.end(), {a, b, c});
  }
  return out;
}

std::string name(const Lame& L) {
  return std::string(L.plane_strain ? "plane strain" : "plane stress") + " a=" +
         std::to_string(L.inner_radius) + " b=" + std::to_string(L.outer_radius);
}

/// Points in the wall a <= r <= b at several angles, including the boundaries.
std::vector<Vector2d> wall_points(const Lame& L) {
  std::vector<Vector2d> x;
  for (double s : {0.0, 0.3, 0.5, 0.9, 1.0})
    for (double t : {0.0, 0.4, 1.3, 2.9, -2.2}) {
      const double r = L.inner_radius + s * (L.outer_radius - L.inner_radius);
      x.push_back(L.center + r * Vector2d(std::cos(t), std::sin(t)));
    }
  return x;
}

/// Displacement gradient H(i, j) = du_i / dx_j by central differences with step h.
Eigen::Matrix2d displacement_gradient(const Lame& L, const Vector2d& x, double h) {
  Eigen::Matrix2d H;
  for (int j = 0; j < 2; ++j) {
    Vector2d e = Vector2d::Zero();
    e(j) = h;
    H.col(j) = (L.displacement(x + e) - L.displacement(x - e)) / (2 * h);
  }
  return H;
}

/// Plane elasticity matrix by hand (this test links only the analytic module).
Eigen::Matrix3d elasticity(const Lame& L) {
  const double E = L.youngs_modulus, nu = L.poisson_ratio;
  Eigen::Matrix3d D;
  if (L.plane_strain) {
    const double c = E / ((1 + nu) * (1 - 2 * nu));
    D << c * (1 - nu), c * nu, 0, c * nu, c * (1 - nu), 0, 0, 0, c * (1 - 2 * nu) / 2;
  } else {
    const double c = E / (1 - nu * nu);
    D << c, c * nu, 0, c * nu, c, 0, 0, 0, c * (1 - nu) / 2;
  }
  return D;
}

}  // namespace

// The strain shall be the symmetric gradient of the displacement: central differences with
// h = 1e-5·r agree to 1e-7 of the strain scale (truncation ~h²|u'''| ~ 1e-10, round-off
// ~1e-16·|u|/h ~ 1e-11 relative).
TEST(Lame, StrainIsTheSymmetricDisplacementGradient) {
  for (const Lame& L : cylinders()) {
    for (const Vector2d& x : wall_points(L)) {
      const double h = 1e-5 * L.inner_radius;
      const Eigen::Matrix2d H = displacement_gradient(L, x, h);
      const Vector3d fd(H(0, 0), H(1, 1), H(0, 1) + H(1, 0));
      const Vector3d eps = L.strain(x);
      const double scale = std::abs(L.radial_displacement(L.inner_radius)) / L.inner_radius +
                           std::abs(L.radial_displacement(L.outer_radius)) / L.outer_radius;
      EXPECT_LE((fd - eps).norm(), 1e-7 * scale) << name(L) << " at " << x.transpose();
      // The displacement is radial: no rotation.
      EXPECT_NEAR(H(0, 1) - H(1, 0), 0.0, 1e-7 * scale) << name(L);
    }
  }
}

// The stress shall be D times the strain with the plane strain or plane stress D (1e-12).
TEST(Lame, StressIsHookeOfStrain) {
  for (const Lame& L : cylinders()) {
    const Eigen::Matrix3d D = elasticity(L);
    const double scale = std::abs(L.inner_pressure) + std::abs(L.outer_pressure);
    for (const Vector2d& x : wall_points(L))
      EXPECT_LE((D * L.strain(x) - L.stress(x)).norm(), 1e-12 * scale) << name(L);
  }
}

// The stress shall be in equilibrium without body force: div sigma = 0 by central differences
// (h = 1e-5·a, relative to pressure / a: 1e-6).
TEST(Lame, StressIsInEquilibrium) {
  for (const Lame& L : cylinders()) {
    const double h = 1e-5 * L.inner_radius;
    const double scale = (std::abs(L.inner_pressure) + std::abs(L.outer_pressure)) / L.inner_radius;
    for (const Vector2d& x : wall_points(L)) {
      const Vector3d dsx = (L.stress(x + Vector2d(h, 0)) - L.stress(x - Vector2d(h, 0))) / (2 * h);
      const Vector3d dsy = (L.stress(x + Vector2d(0, h)) - L.stress(x - Vector2d(0, h))) / (2 * h);
      EXPECT_NEAR(dsx(0) + dsy(2), 0.0, 1e-6 * scale) << name(L);
      EXPECT_NEAR(dsx(2) + dsy(1), 0.0, 1e-6 * scale) << name(L);
    }
  }
}

// The boundary tractions shall equal the pressures: sigma n = −p_i n on r = a and −p_o n on r = b
// (n the outward normal of the wall), to 1e-12 of the pressures, at any angle.
TEST(Lame, BoundaryTractionsEqualThePressures) {
  for (const Lame& L : cylinders()) {
    const double scale = std::abs(L.inner_pressure) + std::abs(L.outer_pressure);
    for (double t = -pi; t < pi; t += 0.37) {
      const Vector2d er(std::cos(t), std::sin(t));
      for (int side = 0; side < 2; ++side) {
        const double r = side == 0 ? L.inner_radius : L.outer_radius;
        const double p = side == 0 ? L.inner_pressure : L.outer_pressure;
        const Vector2d n = side == 0 ? Vector2d(-er) : er;
        const Vector3d s = L.stress(L.center + r * er);
        const Vector2d traction(s(0) * n.x() + s(2) * n.y(), s(2) * n.x() + s(1) * n.y());
        EXPECT_LE((traction + p * n).norm(), 1e-12 * scale) << name(L) << " side " << side;
      }
    }
  }
}

// The plane stress and plane strain variants shall have the same stresses, and the plane stress
// radial displacement shall be 1/E[(1−nu) A r + (1+nu) B/r] — equivalently the plane strain one
// with E* = E(1+2nu)/(1+nu)², nu* = nu/(1+nu) (the standard conversion), to 1e-13.
TEST(Lame, PlaneStressVariant) {
  for (const Lame& L : cylinders()) {
    if (L.plane_strain) continue;
    Lame strain = L;
    strain.plane_strain = true;
    for (const Vector2d& x : wall_points(L))
      EXPECT_LE((L.stress(x) - strain.stress(x)).norm(),
                1e-14 * (std::abs(L.inner_pressure) + std::abs(L.outer_pressure)));
    const double nu = L.poisson_ratio, E = L.youngs_modulus;
    Lame equivalent = strain;
    equivalent.poisson_ratio = nu / (1 + nu);
    equivalent.youngs_modulus = E * (1 + 2 * nu) / ((1 + nu) * (1 + nu));
    for (double s : {0.0, 0.25, 1.0}) {
      const double r = L.inner_radius + s * (L.outer_radius - L.inner_radius);
      const double u = L.radial_displacement(r);
      EXPECT_NEAR(u, equivalent.radial_displacement(r), 1e-13 * std::abs(u)) << name(L);
    }
    // The out-of-plane strain of plane stress, -nu/E (s_xx + s_yy), is not in the 3-vector; the
    // in-plane strain follows the plane stress compliance.
    const Vector2d x = wall_points(L)[7];
    const Vector3d s = L.stress(x), e = L.strain(x);
    EXPECT_NEAR(e(0), (s(0) - nu * s(1)) / E, 1e-14 * s.norm() / E);
  }
}

// The strain energy shall equal ½ ∫ sigma : eps dA over the sector of opening angle alpha
// (the density depends on r only; 40-point Gauss in r), to 1e-12 relative.
TEST(Lame, StrainEnergyIsTheIntegralOfTheEnergyDensity) {
  // 40-point Gauss–Legendre (basis module). r·density = c1 r + c2 / r³ is analytic inside the
  // Bernstein ellipse through r = 0, so the rule converges like rho^-80 (< 1e-20 here).
  const auto& rule = hpcontact::basis::gauss_legendre(40);
  const int n = rule.size();
  const auto& xg = rule.points;
  const auto& wg = rule.weights;
  for (const Lame& L : cylinders()) {
    const double a = L.inner_radius, b = L.outer_radius, alpha = 0.7;
    double U = 0;
    for (int i = 0; i < n; ++i) {
      const double r = 0.5 * (a + b) + 0.5 * (b - a) * xg[i];
      const Vector2d x = L.center + r * Vector2d(std::cos(0.3), std::sin(0.3));
      const double density = 0.5 * L.stress(x).dot(L.strain(x));
      U += 0.5 * (b - a) * wg[i] * density * r * alpha;
    }
    EXPECT_NEAR(U, L.strain_energy(alpha), 1e-12 * std::abs(L.strain_energy(alpha))) << name(L);
  }
}
