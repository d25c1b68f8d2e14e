// Lamé's closed-form solution of a thick-walled cylinder under internal and external pressure.
#pragma once

#include <Eigen/Dense>

namespace hpcontact::analytic {

/// Cylinder a <= r <= b centred at `center`, pressures p_i (inside) and p_o (outside), positive
/// in compression. Stresses (plane strain and plane stress alike):
///   sigma_r = A - B / r²,  sigma_theta = A + B / r²,
///   A = (p_i a² - p_o b²) / (b² - a²),  B = (p_i - p_o) a² b² / (b² - a²).
/// Radial displacement: plane strain u_r = (1+nu)/E [(1-2nu) A r + B / r];
///                      plane stress u_r = 1/E [(1-nu) A r + (1+nu) B / r].
struct Lame {
  double inner_radius, outer_radius, inner_pressure, outer_pressure;
  double youngs_modulus, poisson_ratio;
  bool plane_strain = true;
  Eigen::Vector2d center = Eigen::Vector2d::Zero();

  double radial_displacement(double r) const;
  /// Cartesian displacement at x.
  Eigen::Vector2d displacement(const Eigen::Vector2d& x) const;
  /// Cartesian stress (xx, yy, xy) at x.
  Eigen::Vector3d stress(const Eigen::Vector2d& x) const;
  /// Cartesian strain (xx, yy, gamma_xy) at x.
  Eigen::Vector3d strain(const Eigen::Vector2d& x) const;
  /// Strain energy per unit thickness of the sector of opening angle `angle` (radians):
  /// U = ½ angle (p_i a u_r(a) - p_o b u_r(b)), the work of the pressures.
  double strain_energy(double angle) const;
};

}  // namespace hpcontact::analytic
