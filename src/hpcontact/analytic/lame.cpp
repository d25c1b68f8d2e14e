// Lamé solution in Cartesian components.
#include "hpcontact/analytic/lame.hpp"

#include <cmath>

namespace hpcontact::analytic {

namespace {
struct Coefficients {
  double A, B;
};
Coefficients coefficients(const Lame& L) {
  const double a2 = L.inner_radius * L.inner_radius, b2 = L.outer_radius * L.outer_radius;
  return {(L.inner_pressure * a2 - L.outer_pressure * b2) / (b2 - a2),
          (L.inner_pressure - L.outer_pressure) * a2 * b2 / (b2 - a2)};
}
}  // namespace

double Lame::radial_displacement(double r) const {
  const auto [A, B] = coefficients(*this);
  const double E = youngs_modulus, nu = poisson_ratio;
  if (plane_strain) return (1 + nu) / E * ((1 - 2 * nu) * A * r + B / r);
  return 1 / E * ((1 - nu) * A * r + (1 + nu) * B / r);
}

Eigen::Vector2d Lame::displacement(const Eigen::Vector2d& x) const {
  const Eigen::Vector2d d = x - center;
  const double r = d.norm();
  return radial_displacement(r) * d / r;
}

Eigen::Vector3d Lame::stress(const Eigen::Vector2d& x) const {
  const auto [A, B] = coefficients(*this);
  const Eigen::Vector2d d = x - center;
  const double r2 = d.squaredNorm(), c = d.x() * d.x() / r2, s = d.y() * d.y() / r2,
               cs = d.x() * d.y() / r2;
  const double sr = A - B / r2, st = A + B / r2;
  return {sr * c + st * s, sr * s + st * c, (sr - st) * cs};
}

Eigen::Vector3d Lame::strain(const Eigen::Vector2d& x) const {
  const double E = youngs_modulus, nu = poisson_ratio;
  const Eigen::Vector3d s = stress(x);
  if (plane_strain) {
    const double k = (1 + nu) / E;
    return {k * ((1 - nu) * s(0) - nu * s(1)), k * ((1 - nu) * s(1) - nu * s(0)), 2 * k * s(2)};
  }
  return {(s(0) - nu * s(1)) / E, (s(1) - nu * s(0)) / E, 2 * (1 + nu) / E * s(2)};
}

double Lame::strain_energy(double angle) const {
  return 0.5 * angle *
         (inner_pressure * inner_radius * radial_displacement(inner_radius) -
          outer_pressure * outer_radius * radial_displacement(outer_radius));
}

}  // namespace hpcontact::analytic
