// Lamé's closed-form solution of a thick-walled sphere under internal and external pressure,
// on the meridian plane of an axisymmetric model (x = r, y = z).
#pragma once

#include <Eigen/Dense>

namespace hpcontact::analytic {

/// Sphere a <= ρ <= b centred at `center` (on the axis), pressures p_i (inside) and p_o
/// (outside), positive in compression. With A = (p_i a³ − p_o b³) / (b³ − a³) and
/// B = (p_i − p_o) a³ b³ / (b³ − a³):
///   σ_ρρ = A − B / ρ³,  σ_φφ = σ_θθ = A + B / (2ρ³),
///   u_ρ = ρ / E [(1 − 2ν) A + (1 + ν) B / (2ρ³)],
/// so ε_ρρ = [(1 − 2ν) A − (1 + ν) B / ρ³] / E and the two tangential strains are u_ρ / ρ.
struct LameSphere {
  double inner_radius, outer_radius, inner_pressure, outer_pressure;
  double youngs_modulus, poisson_ratio;
  Eigen::Vector2d center = Eigen::Vector2d::Zero();

  double radial_displacement(double rho) const;
  /// (u_r, u_z) at the meridian point x = (r, z).
  Eigen::Vector2d displacement(const Eigen::Vector2d& x) const;
  /// The meridian strain (ε_rr, ε_zz, γ_rz) at x = (r, z).
  Eigen::Vector3d strain(const Eigen::Vector2d& x) const;
  /// The hoop strain ε_θθ = u_r / r = u_ρ / ρ at x.
  double hoop_strain(const Eigen::Vector2d& x) const;
  /// Strain energy of the part of the sphere that subtends `solid_angle` (4π: the whole
  /// sphere): U = ½ solid_angle (p_i a² u_ρ(a) − p_o b² u_ρ(b)), the work of the pressures.
  double strain_energy(double solid_angle) const;
};

}  // namespace hpcontact::analytic
