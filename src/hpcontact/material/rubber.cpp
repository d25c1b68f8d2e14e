// Rubber laws by the chain rule on the isochoric invariants. With J = √det C,
//   ∂J/∂C = J/2 C⁻¹,  ∂C⁻¹/∂C = −𝕀_C⁻¹, (𝕀_A)_ijkl = ½ (A_ik A_jl + A_il A_jk),
//   A₁ = ∂Ī₁/∂C = J^(−2/3) (I − I₁/3 C⁻¹),
//   A₂ = ∂Ī₂/∂C = J^(−4/3) (I₁ I − C − 2/3 I₂ C⁻¹)          (I₂ = ½ (I₁² − C : C)),
// S_iso = 2 (W₁ A₁ + W₂ A₂), W_a = ∂W_iso/∂Ī_a, and
//   ℂ_iso = 4 [W₁₁ A₁⊗A₁ + W₁₂ (A₁⊗A₂ + A₂⊗A₁) + W₂₂ A₂⊗A₂ + W₁ ∂A₁/∂C + W₂ ∂A₂/∂C],
//   ∂A₁/∂C = J^(−2/3) [−1/3 (I⊗C⁻¹ + C⁻¹⊗I) + I₁/9 C⁻¹⊗C⁻¹ + I₁/3 𝕀_C⁻¹],
//   ∂A₂/∂C = J^(−4/3) [I⊗I − 𝕀 − 2/3 I₁ (I⊗C⁻¹ + C⁻¹⊗I) + 2/3 (C⊗C⁻¹ + C⁻¹⊗C)
//                     + 4/9 I₂ C⁻¹⊗C⁻¹ + 2/3 I₂ 𝕀_C⁻¹]
// (product rule with ∂J^(−2/3)/∂C = −1/3 J^(−2/3) C⁻¹). At C = I, A₁ = A₂ = 0 and
// ∂A₁/∂C = ∂A₂/∂C = 𝕀 − 1/3 I⊗I: ℂ_iso = 4 (C10 + C01) 𝕀_dev = 2μ 𝕀_dev.
// Volumetric: S_vol = 2 U' ∂J/∂C = J p C⁻¹ (p = U'), ℂ = 2 ∂S_vol/∂C =
// J p (C⁻¹⊗C⁻¹ − 2 𝕀_C⁻¹) + J² U'' C⁻¹⊗C⁻¹; at C = I, K I⊗I.
#include "hpcontact/material/rubber.hpp"

#include <cmath>

namespace hpcontact::material {

namespace {

/// Voigt index pairs (11, 22, 33, 23, 13, 12).
constexpr int kI[6] = {0, 1, 2, 1, 0, 0}, kJ[6] = {0, 1, 2, 2, 2, 1};

Voigt3 voigt(const Eigen::Matrix3d& A) {
  Voigt3 v;
  for (int a = 0; a < 6; ++a) v(a) = A(kI[a], kJ[a]);
  return v;
}

/// A ⊗ B + B ⊗ A of symmetric A, B.
Elasticity3 sym_outer(const Eigen::Matrix3d& A, const Eigen::Matrix3d& B) {
  const Voigt3 a = voigt(A), b = voigt(B);
  return a * b.transpose() + b * a.transpose();
}

/// 𝕀_A of a symmetric A: ½ (A_ik A_jl + A_il A_jk); 𝕀_I is the symmetric identity 𝕀.
Elasticity3 sym_product(const Eigen::Matrix3d& A) {
  Elasticity3 P;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      const int i = kI[a], j = kJ[a], k = kI[b], l = kJ[b];
      P(a, b) = 0.5 * (A(i, k) * A(j, l) + A(i, l) * A(j, k));
    }
  return P;
}

/// W_iso and its derivatives in (Ī₁, Ī₂).
struct InvariantDerivatives {
  double W = 0, W1 = 0, W2 = 0, W11 = 0, W12 = 0, W22 = 0;
};

InvariantDerivatives invariant_derivatives(const RubberConstants& k, double I1_bar, double I2_bar) {
  const double x = I1_bar - 3, y = I2_bar - 3;
  InvariantDerivatives d;
  d.W = k.C10 * x + k.C01 * y + k.C20 * x * x + k.C30 * x * x * x;
  d.W1 = k.C10 + 2 * k.C20 * x + 3 * k.C30 * x * x;
  d.W2 = k.C01;
  d.W11 = 2 * k.C20 + 6 * k.C30 * x;
  return d;
}

}  // namespace

LinearElastic RubberConstants::small_strain(Plane plane) const {
  const double mu = shear_modulus();
  // An incompressible law (K = ∞) has ν = 1/2, where the linear law's D is singular: the scales
  // and estimators see it as K = 1000 μ (ν = 0.4995), the ratio of a typical rubber.
  const double bulk = std::isfinite(K) ? K : 1000 * mu;
  LinearElastic m;
  m.youngs_modulus = 9 * bulk * mu / (3 * bulk + mu);
  m.poisson_ratio = (3 * bulk - 2 * mu) / (2 * (3 * bulk + mu));
  m.plane = plane;
  return m;
}

StressTangent3 isochoric_stress(const RubberConstants& constants, const Eigen::Matrix3d& C) {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity(), Ci = C.inverse();
  const double J = std::sqrt(C.determinant());
  const double j23 = std::pow(J, -2.0 / 3.0), j43 = j23 * j23;
  const double I1 = C.trace(), I2 = 0.5 * (I1 * I1 - (C * C).trace());
  const auto d = invariant_derivatives(constants, j23 * I1, j43 * I2);
  const Eigen::Matrix3d A1 = j23 * (I - I1 / 3 * Ci);
  const Eigen::Matrix3d A2 = j43 * (I1 * I - C - 2.0 / 3.0 * I2 * Ci);
  const Elasticity3 CiCi = voigt(Ci) * voigt(Ci).transpose(), ICi = sym_outer(I, Ci);
  const Elasticity3 II_Ci = sym_product(Ci);
  const Elasticity3 dA1 = j23 * (-1.0 / 3.0 * ICi + I1 / 9 * CiCi + I1 / 3 * II_Ci);
  const Elasticity3 dA2 =
      j43 * (voigt(I) * voigt(I).transpose() - sym_product(I) - 2.0 / 3.0 * I1 * ICi +
             2.0 / 3.0 * sym_outer(C, Ci) + 4.0 / 9.0 * I2 * CiCi + 2.0 / 3.0 * I2 * II_Ci);
  StressTangent3 s;
  s.W = d.W;
  s.S = 2 * (d.W1 * A1 + d.W2 * A2);
  s.C = 4 * (d.W11 * voigt(A1) * voigt(A1).transpose() + d.W12 * sym_outer(A1, A2) +
             d.W22 * voigt(A2) * voigt(A2).transpose() + d.W1 * dA1 + d.W2 * dA2);
  return s;
}

Volumetric volumetric_energy(double K, double J) {
  return {0.5 * K * (J - 1) * (J - 1), K * (J - 1), K};
}

StressTangent3 pressure_stress(const Eigen::Matrix3d& C, double p) {
  const Eigen::Matrix3d Ci = C.inverse();
  const double J = std::sqrt(C.determinant());
  StressTangent3 s;
  s.S = J * p * Ci;
  s.C = J * p * (voigt(Ci) * voigt(Ci).transpose() - 2 * sym_product(Ci));
  return s;
}

StressTangent3 rubber_stress(const RubberConstants& constants, const Eigen::Matrix3d& C) {
  const double J = std::sqrt(C.determinant());
  const Volumetric U = volumetric_energy(constants.K, J);
  StressTangent3 s = isochoric_stress(constants, C);
  const StressTangent3 vol = pressure_stress(C, U.dU);
  const Voigt3 ci = voigt(C.inverse());
  s.W += U.U;
  s.S += vol.S;
  s.C += vol.C + J * J * U.d2U * ci * ci.transpose();
  return s;
}

}  // namespace hpcontact::material
