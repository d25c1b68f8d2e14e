// Hyperelastic laws of an axisymmetric deformation (x = r, y = z): the in-plane deformation
// gradient and the hoop stretch F_θθ = 1 + u_r / R, a 3-D state with four strain components.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/material/hyperelastic.hpp"

namespace hpcontact::material {

/// The second Piola–Kirchhoff stress of F = [[F_rr, F_rz, 0], [F_zr, F_zz, 0], [0, 0, F_θθ]],
/// its tangent and energy. Voigt order (11, 22, 12, θθ): the meridian plane's (r, z) components
/// as in HyperelasticState, then the hoop component.
struct HoopHyperelasticState {
  Eigen::Vector4d S = Eigen::Vector4d::Zero();  ///< (S_rr, S_zz, S_rz, S_θθ)
  Eigen::Matrix4d C = Eigen::Matrix4d::Zero();  ///< dS/dE in (E_rr, E_zz, 2 E_rz, E_θθ)
  double W = 0;                                 ///< strain energy per reference volume
  double J = 1;                                 ///< det F = det F_plane · F_θθ
};

/// The state at the meridian deformation gradient F and the hoop stretch F_hoop, the 3-D laws of
/// hyperelastic_state with C_θθ = F_hoop² (St. Venant–Kirchhoff: S = λ tr E I + 2μ E with
/// E_θθ = (F_hoop² − 1)/2; Neo-Hooke: S = μ (I − C⁻¹) + λ ln J C⁻¹, C⁻¹_θθ = 1 / F_hoop²).
/// Needs det F > 0 and F_hoop > 0 (the caller checks).
HoopHyperelasticState hoop_hyperelastic_state(const LinearElastic& elastic, Law law,
                                              const Eigen::Matrix2d& F, double F_hoop);

/// The state of any finite-strain law; a rubber law is rubber_stress with C_θθ = F_hoop²,
/// restricted to (11, 22, 12, θθ).
HoopHyperelasticState hoop_hyperelastic_state(const FiniteStrainLaw& law, const Eigen::Matrix2d& F,
                                              double F_hoop);

/// Cauchy stress σ = F S Fᵀ / J in Voigt (rr, zz, rz) and σ_θθ = F_hoop² S_θθ / J into *hoop.
Voigt hoop_cauchy_stress(const HoopHyperelasticState& state, const Eigen::Matrix2d& F,
                         double F_hoop, double* hoop);

}  // namespace hpcontact::material
