// Property tests of Lamé's thick sphere on the meridian plane (x = r, y = z): the strains are the
// displacement's (with the hoop strain u_r / r), the stress of Hooke's law is in axisymmetric
// equilibrium, the surface tractions are the pressures, and the energy is the pressures' work.
#include "hpcontact/analytic/lame_sphere.hpp"
#include "hpcontact/basis/quadrature.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

using hpcontact::analytic::LameSphere;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

constexpr double pi = std::numbers::pi;

std::vector<LameSphere> spheres() {
  return {LameSphere{10, 20, 100, 0, 200000, 0.3},
          LameSphere{1, 1.5, 3, 7, 1000, 0.45, Vector2d(0, -2)},
          LameSphere{0.5, 4, 0, 12, 70, -0.2, Vector2d(0, 5)}};
}

/// Points of the wall a <= ρ <= b off the axis (polar angle 0.1…3.0 from +z), boundaries included.
std::vector<Vector2d> wall_points(const LameSphere& S) {
  std::vector<Vector2d> x;
  for (double s : {0.0, 0.3, 0.5, 0.9, 1.0})
    for (double phi : {0.1, 0.8, 1.5707963, 2.2, 3.0}) {
      const double rho = S.inner_radius + s * (S.outer_radius - S.inner_radius);
      x.push_back(S.center + rho * Vector2d(std::sin(phi), std::cos(phi)));
    }
  return x;
}

double strain_scale(const LameSphere& S) {
  return std::abs(S.radial_displacement(S.inner_radius)) / S.inner_radius +
         std::abs(S.radial_displacement(S.outer_radius)) / S.outer_radius;
}

/// (σ_rr, σ_zz, τ_rz, σ_θθ) of the isotropic law σ = λ tr ε I + 2μ ε, written out here (this
/// test links only the analytic module).
std::array<double, 4> stress(const LameSphere& S, const Vector2d& x) {
  const double E = S.youngs_modulus, nu = S.poisson_ratio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const Vector3d e = S.strain(x);
  const double hoop = S.hoop_strain(x), trace = e(0) + e(1) + hoop;
  return {lambda * trace + 2 * mu * e(0), lambda * trace + 2 * mu * e(1), mu * e(2),
          lambda * trace + 2 * mu * hoop};
}

}  // namespace

// ε_rr = ∂u_r/∂r, ε_zz = ∂u_z/∂z, γ_rz = ∂u_r/∂z + ∂u_z/∂r by central differences (h = 1e-5 a,
// to 1e-7 of the strain scale), and ε_θθ = u_r / r to round-off.
TEST(LameSphere, StrainsAreTheDisplacements) {
  for (const LameSphere& S : spheres())
    for (const Vector2d& x : wall_points(S)) {
      const double h = 1e-5 * S.inner_radius, scale = strain_scale(S);
      const Vector2d dr = (S.displacement(x + Vector2d(h, 0)) - S.displacement(x - Vector2d(h, 0))) / (2 * h);
      const Vector2d dz = (S.displacement(x + Vector2d(0, h)) - S.displacement(x - Vector2d(0, h))) / (2 * h);
      const Vector3d fd(dr.x(), dz.y(), dz.x() + dr.y());
      EXPECT_LE((fd - S.strain(x)).norm(), 1e-7 * scale) << x.transpose();
      EXPECT_NEAR(S.hoop_strain(x), S.displacement(x).x() / x.x(), 1e-13 * scale);
    }
}

// Without body force, ∂σ_rr/∂r + ∂τ_rz/∂z + (σ_rr − σ_θθ)/r = 0 and ∂τ_rz/∂r + ∂σ_zz/∂z + τ_rz/r
// = 0 (central differences, 1e-6 of pressure / a).
TEST(LameSphere, StressIsInAxisymmetricEquilibrium) {
  for (const LameSphere& S : spheres()) {
    const double h = 1e-5 * S.inner_radius;
    const double scale = (std::abs(S.inner_pressure) + std::abs(S.outer_pressure)) / S.inner_radius;
    for (const Vector2d& x : wall_points(S)) {
      const auto s = stress(S, x);
      const auto rp = stress(S, x + Vector2d(h, 0)), rm = stress(S, x - Vector2d(h, 0));
      const auto zp = stress(S, x + Vector2d(0, h)), zm = stress(S, x - Vector2d(0, h));
      const double r = x.x();
      EXPECT_NEAR((rp[0] - rm[0]) / (2 * h) + (zp[2] - zm[2]) / (2 * h) + (s[0] - s[3]) / r, 0,
                  1e-6 * scale) << x.transpose();
      EXPECT_NEAR((rp[2] - rm[2]) / (2 * h) + (zp[1] - zm[1]) / (2 * h) + s[2] / r, 0, 1e-6 * scale)
          << x.transpose();
    }
  }
}

// σ n = −p_i n on ρ = a and −p_o n on ρ = b (n outward from the wall), to 1e-12 of the pressures.
TEST(LameSphere, SurfaceTractionsAreThePressures) {
  for (const LameSphere& S : spheres()) {
    const double scale = std::abs(S.inner_pressure) + std::abs(S.outer_pressure);
    for (double phi = 0.05; phi < pi; phi += 0.37) {
      const Vector2d e(std::sin(phi), std::cos(phi));
      for (int side = 0; side < 2; ++side) {
        const double rho = side == 0 ? S.inner_radius : S.outer_radius;
        const double p = side == 0 ? S.inner_pressure : S.outer_pressure;
        const Vector2d n = side == 0 ? Vector2d(-e) : e;
        const auto s = stress(S, S.center + rho * e);
        const Vector2d t(s[0] * n.x() + s[2] * n.y(), s[2] * n.x() + s[1] * n.y());
        EXPECT_LE((t + p * n).norm(), 1e-12 * scale) << "side " << side << " phi " << phi;
      }
    }
  }
}

// U(Ω) = ½ ∫ σ : ε ρ² dρ Ω over a solid angle Ω (the density depends on ρ only; 40-point Gauss),
// the work of the pressures, to 1e-12.
TEST(LameSphere, StrainEnergyIsTheIntegralOfTheEnergyDensity) {
  const auto& rule = hpcontact::basis::gauss_legendre(40);
  for (const LameSphere& S : spheres()) {
    const double a = S.inner_radius, b = S.outer_radius, omega = 2 * pi;  // a hemisphere
    double U = 0;
    for (int i = 0; i < rule.size(); ++i) {
      const double rho = 0.5 * (a + b) + 0.5 * (b - a) * rule.points[i];
      const Vector2d x = S.center + rho * Vector2d(std::sin(0.7), std::cos(0.7));
      const auto s = stress(S, x);
      const Vector3d e = S.strain(x);
      const double density = 0.5 * (s[0] * e(0) + s[1] * e(1) + s[2] * e(2) + s[3] * S.hoop_strain(x));
      U += 0.5 * (b - a) * rule.weights[i] * density * rho * rho * omega;
    }
    EXPECT_NEAR(U, S.strain_energy(omega), 1e-12 * std::abs(S.strain_energy(omega)));
  }
}
