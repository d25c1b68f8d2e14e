// Linear isotropic elasticity in plane strain or plane stress (seed §2.1.3).
#pragma once

#include <Eigen/Dense>

namespace hpcontact::material {

enum class Plane { strain, stress };

/// Voigt order (xx, yy, xy) with engineering shear strain gamma_xy = 2 eps_xy.
using Voigt = Eigen::Vector3d;
using Elasticity = Eigen::Matrix3d;

struct LinearElastic {
  double youngs_modulus = 0;
  double poisson_ratio = 0;
  Plane plane = Plane::strain;

  /// Throws InputError unless E > 0 and -1 < nu < 0.5; `where` names the input key.
  void validate(const std::string& where) const;

  /// The plane elasticity matrix D: sigma = D eps (Voigt).
  Elasticity D() const;

  /// Out-of-plane stress: nu (sxx + syy) in plane strain, 0 in plane stress.
  double sigma_zz(const Voigt& sigma) const;
};

}  // namespace hpcontact::material
