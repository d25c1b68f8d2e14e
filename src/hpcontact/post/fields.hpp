// Displacement, strain and stress of a solution anywhere in an element, and derived measures.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::post {

struct PointResult {
  Vec2 x;                    ///< physical point
  Vec2 u;                    ///< displacement
  Eigen::Vector3d strain;    ///< (xx, yy, gamma_xy); Green–Lagrange under finite strain
  Eigen::Vector3d stress;    ///< (xx, yy, xy); Cauchy under finite strain
  double stress_zz = 0;      ///< out of plane: nu (sxx + syy) in plane strain
  double von_mises = 0;      ///< from all four stress components
  double principal_1 = 0;    ///< larger in-plane principal stress
  double principal_2 = 0;    ///< smaller in-plane principal stress
  double pressure = 0;       ///< a mixed body's element pressure (positive in tension), else 0
  /// An axisymmetric body's hoop strain u_r / r (Green–Lagrange ((1 + u_r/r)² − 1)/2 under
  /// finite strain; on the axis the radial strain, its limit); 0 for other bodies.
  double strain_hoop = 0;
};

/// Fields at reference point (xi, eta) of element q of a body. Where the map is singular (a
/// corner of 180°) the strain is that of a point just inside.
PointResult evaluate(const model::Body& body, int q, double xi, double eta, const Eigen::VectorXd& u);

/// von Mises stress from sxx, syy, szz, sxy:
///   √(½ ((sxx − syy)² + (syy − szz)² + (szz − sxx)²) + 3 sxy²).
double von_mises(double sxx, double syy, double szz, double sxy);

/// von Mises stress of a 3D stress in Voigt order (xx, yy, zz, yz, xz, xy):
///   √(½ ((σxx − σyy)² + (σyy − σzz)² + (σzz − σxx)²) + 3 (σyz² + σxz² + σxy²)).
double von_mises(const std::array<double, 6>& s);

/// The in-plane principal stresses {σ1, σ2}, σ1 ≥ σ2, of (sxx, syy, sxy): c ± R with
/// c = (sxx + syy)/2, R = √(((sxx − syy)/2)² + sxy²) (the centre and radius of Mohr's circle).
std::array<double, 2> principal_stresses(double sxx, double syy, double sxy);

/// U = ½ B(u, u) = ½ ∫ eps^T D eps t dA over all bodies (seed eq. 2.31); for a finite-strain
/// body ∫ W(F) t dA over the reference body.
double strain_energy(const model::Discretization& d, const Eigen::VectorXd& u);

/// An exact strain field as functions of the physical point: the in-plane strain (xx, yy,
/// gamma_xy) and, for an axisymmetric body (x = r), the hoop strain ε_θθ.
struct ExactStrain {
  std::function<Eigen::Vector3d(const Vec2&)> in_plane;
  std::function<double(const Vec2&)> hoop;  ///< required where a body is axisymmetric
};

/// ||u_exact - u||_E² = ½ ∫ (eps_ex - eps)^T D (eps_ex - eps) t dA (axisymmetric: the four
/// strains with D₄, over 2π r dA), integrated with `extra_points` more Gauss points per
/// direction than the solve used.
double energy_error_squared(const model::Discretization& d, const Eigen::VectorXd& u,
                            const ExactStrain& exact, int extra_points = 4);

/// ½ ∫ εᵀ D ε dV of the local coefficients ue (component-blocked) of element q of a linear
/// elastic body, at the points of ev (the element's values, of any rule).
double element_strain_energy(const model::Body& body, int q, const fem::ElementValues& ev,
                             const Eigen::VectorXd& ue);

/// Per body, per element: ½ ∫ εᵀ D ε dV of the field u (all dofs) of linear elastic bodies.
std::vector<std::vector<double>> element_strain_energies(const model::Discretization& d,
                                                         const Eigen::VectorXd& u);

}  // namespace hpcontact::post
