// Isotropic rubber laws on the 3-D right Cauchy–Green tensor C with the isochoric–volumetric
// split W = W_iso(Ī₁, Ī₂) + U(J): neo-Hooke, Mooney–Rivlin and Yeoh, each part with its second
// Piola–Kirchhoff stress and consistent tangent, so that a mixed u–p element can take W_iso and
// put its own pressure in place of U'(J). The derivation is in docs/theory.md §12 and rubber.cpp.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/material/linear_elastic.hpp"

namespace hpcontact::material {

/// The constants of
///   W = C10 (Ī₁ − 3) + C01 (Ī₂ − 3) + C20 (Ī₁ − 3)² + C30 (Ī₁ − 3)³ + K/2 (J − 1)²,
/// Ī₁ = J^(−2/3) I₁, Ī₂ = J^(−4/3) I₂ the invariants of C̄ = J^(−2/3) C. Neo-Hooke is C10 alone,
/// Mooney–Rivlin C10 and C01, Yeoh C10, C20 and C30 (the law decides which the input takes).
/// All in force/length² (e.g. MPa = N/mm²). The small-strain shear modulus is μ = 2 (C10 + C01),
/// the bulk modulus K.
struct RubberConstants {
  double C10 = 0, C01 = 0, C20 = 0, C30 = 0;
  double K = 0;  ///< ∞: incompressible (only the mixed element takes it)

  /// μ = 2 (C10 + C01), the shear modulus at C = I.
  double shear_modulus() const { return 2 * (C10 + C01); }
  /// The linear law of the same μ and K: E = 9Kμ / (3K + μ), ν = (3K − 2μ) / (2 (3K + μ)); what
  /// the small-strain parts of a model (contact stiffness scales, estimators) see of the rubber.
  /// An incompressible law (K = ∞) is seen as K = 1000 μ (ν = 0.4995).
  LinearElastic small_strain(Plane plane) const;
};

/// A part of W at C: its energy, S = 2 ∂W/∂C and ℂ = 2 ∂S/∂C (= ∂S/∂E), in the 3-D Voigt order
/// (11, 22, 33, 23, 13, 12) with ℂ acting on (E11, E22, E33, 2 E23, 2 E13, 2 E12).
struct StressTangent3 {
  double W = 0;
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  Elasticity3 C = Elasticity3::Zero();
};

/// The isochoric part W_iso(Ī₁, Ī₂) at a symmetric positive definite C. Its S is deviatoric
/// in the sense S : C = 0 (W_iso does not change under C → a C).
StressTangent3 isochoric_stress(const RubberConstants& constants, const Eigen::Matrix3d& C);

/// The volumetric energy U(J) = K/2 (J − 1)² and its derivatives: U' the pressure p (positive
/// in tension; the Cauchy stress's mean is p at a pure volume change), U''.
struct Volumetric {
  double U = 0, dU = 0, d2U = 0;
};
Volumetric volumetric_energy(double K, double J);

/// The stress of a pressure p held fixed: S = J p C⁻¹, ℂ = J p (C⁻¹⊗C⁻¹ − 2 𝕀_C⁻¹) (W = 0): a
/// mixed element's pressure term, and with p = U'(J) the volumetric stress of the law.
StressTangent3 pressure_stress(const Eigen::Matrix3d& C, double p);

/// The whole law: isochoric part plus pressure_stress at p = U'(J), with ℂ's term of dp/dC,
/// J² U''(J) C⁻¹⊗C⁻¹.
StressTangent3 rubber_stress(const RubberConstants& constants, const Eigen::Matrix3d& C);

}  // namespace hpcontact::material
