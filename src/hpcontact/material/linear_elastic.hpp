// Linear isotropic elasticity: the 3D law and its plane strain, plane stress (seed §2.1.3) and
// axisymmetric reductions.
#pragma once

#include <Eigen/Dense>

namespace hpcontact::material {

/// axisymmetric: the plane is the meridian section (x = r, y = z) of a solid of revolution.
enum class Plane { strain, stress, axisymmetric };

/// Voigt order (xx, yy, xy) with engineering shear strain gamma_xy = 2 eps_xy.
using Voigt = Eigen::Vector3d;
using Elasticity = Eigen::Matrix3d;
/// 3D Voigt order (xx, yy, zz, yz, xz, xy) with engineering shear strains gamma_ij = 2 eps_ij.
using Voigt3 = Eigen::Matrix<double, 6, 1>;
using Elasticity3 = Eigen::Matrix<double, 6, 6>;

struct LinearElastic {
  double youngs_modulus = 0;
  double poisson_ratio = 0;
  Plane plane = Plane::strain;

  /// Throws InputError unless E > 0 and -1 < nu < 0.5; `where` names the input key.
  void validate(const std::string& where) const;

  /// The plane elasticity matrix D: sigma = D eps (Voigt). Axisymmetric: the (rr, zz, rz)
  /// block of the 4 × 4 matrix, the same as plane strain's.
  Elasticity D() const;

  /// The 3D elasticity matrix D: sigma = D eps in the 3D Voigt order (xx, yy, zz, yz, xz, xy),
  ///   D = λ m mᵀ + μ diag(2, 2, 2, 1, 1, 1),  m = (1, 1, 1, 0, 0, 0);
  /// the plane laws are its reductions (plane strain: the (xx, yy, xy) block; plane stress: that
  /// block after condensing σ_zz = 0). Independent of `plane`.
  Elasticity3 D3() const;

  /// Out-of-plane stress: nu (sxx + syy) in plane strain, 0 in plane stress (not for
  /// axisymmetry, whose hoop stress needs the hoop strain: axisymmetric_stress).
  double sigma_zz(const Voigt& sigma) const;

  /// Lamé's first parameter λ = E ν / ((1 + ν)(1 − 2ν)) (3-D).
  double lambda() const;
  /// The shear modulus, Lamé's second parameter μ = E / (2 (1 + ν)).
  double mu() const;
  /// The modulus of the plane problem: E' = E / (1 − ν²) (plane strain, axisymmetric), E (plane
  /// stress); the stiffness scale of a contact boundary.
  double plane_modulus() const;
  /// Axisymmetric stresses from the in-plane strains (ε_rr, ε_zz, γ_rz) and the hoop strain
  /// ε_θθ = u_r / r: (σ_rr, σ_zz, τ_rz) = D ε + λ ε_θθ (1, 1, 0), and σ_θθ into *hoop.
  Voigt axisymmetric_stress(const Voigt& eps, double eps_hoop, double* hoop) const;
};

}  // namespace hpcontact::material
