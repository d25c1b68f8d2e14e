// Lamé's thick sphere in meridian (r, z) components.
#include "hpcontact/analytic/lame_sphere.hpp"

namespace hpcontact::analytic {

namespace {

struct Coefficients {
  double A, B;
};

Coefficients coefficients(const LameSphere& S) {
  const double a3 = S.inner_radius * S.inner_radius * S.inner_radius,
               b3 = S.outer_radius * S.outer_radius * S.outer_radius;
  return {(S.inner_pressure * a3 - S.outer_pressure * b3) / (b3 - a3),
          (S.inner_pressure - S.outer_pressure) * a3 * b3 / (b3 - a3)};
}

}  // namespace

double LameSphere::radial_displacement(double rho) const {
  const auto [A, B] = coefficients(*this);
  const double nu = poisson_ratio;
  return rho / youngs_modulus * ((1 - 2 * nu) * A + (1 + nu) * B / (2 * rho * rho * rho));
}

Eigen::Vector2d LameSphere::displacement(const Eigen::Vector2d& x) const {
  const Eigen::Vector2d d = x - center;
  const double rho = d.norm();
  return radial_displacement(rho) * d / rho;
}

Eigen::Vector3d LameSphere::strain(const Eigen::Vector2d& x) const {
  const auto [A, B] = coefficients(*this);
  const double nu = poisson_ratio;
  const Eigen::Vector2d d = x - center;
  const double rho = d.norm();
  const double radial = ((1 - 2 * nu) * A - (1 + nu) * B / (rho * rho * rho)) / youngs_modulus;
  const double tangential = radial_displacement(rho) / rho;
  // ε = ε_ρρ n nᵀ + ε_φφ (I − n nᵀ) in the meridian plane, n = d / ρ
  const Eigen::Vector2d n = d / rho;
  const double jump = radial - tangential;
  return {tangential + jump * n.x() * n.x(), tangential + jump * n.y() * n.y(),
          2 * jump * n.x() * n.y()};
}

double LameSphere::hoop_strain(const Eigen::Vector2d& x) const {
  const double rho = (x - center).norm();
  return radial_displacement(rho) / rho;
}

double LameSphere::strain_energy(double solid_angle) const {
  const double a = inner_radius, b = outer_radius;
  return 0.5 * solid_angle *
         (inner_pressure * a * a * radial_displacement(a) -
          outer_pressure * b * b * radial_displacement(b));
}

}  // namespace hpcontact::analytic
