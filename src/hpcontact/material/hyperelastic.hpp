// Hyperelastic laws of the total Lagrangian formulation in plane strain (seed §2.1.1, §5.3-5.4):
// St. Venant–Kirchhoff, compressible Neo-Hooke and the rubber laws (rubber.hpp), with their
// consistent material tangents.
#pragma once

#include <string>

#include <Eigen/Dense>

#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/material/rubber.hpp"

namespace hpcontact::material {

/// How stress follows from deformation: linear elasticity (small strain), or a hyperelastic law
/// of finite strain, evaluated with the Green–Lagrange strain of the whole deformation gradient.
/// The first two finite-strain laws take E and ν; the rubber laws (neo_hooke_split,
/// mooney_rivlin, yeoh) the RubberConstants of rubber.hpp.
enum class Law { linear, saint_venant_kirchhoff, neo_hooke, neo_hooke_split, mooney_rivlin, yeoh };

/// The input name of a law ("linear-elastic", "saint-venant-kirchhoff", "neo-hooke",
/// "neo-hooke-split", "mooney-rivlin", "yeoh").
std::string law_name(Law law);

/// Whether the law is one of W_iso(Ī₁, Ī₂) + U(J) with RubberConstants.
bool is_rubber(Law law);

/// A finite-strain law with its constants.
struct FiniteStrainLaw {
  Law law = Law::saint_venant_kirchhoff;
  LinearElastic elastic;   ///< E, ν of St. Venant–Kirchhoff and Neo-Hooke
  RubberConstants rubber;  ///< the rubber laws' (is_rubber)
};

/// The second Piola–Kirchhoff stress of a deformation gradient, its tangent and energy.
struct HyperelasticState {
  Voigt S = Voigt::Zero();           ///< (S11, S22, S12)
  Elasticity C = Elasticity::Zero();  ///< dS/dE in Voigt (E11, E22, 2 E12)
  double S33 = 0;                     ///< out of plane (plane strain: F33 = 1)
  double W = 0;                       ///< strain energy per reference volume
  double J = 1;                       ///< det F
};

/// The state at the in-plane deformation gradient F (F33 = 1 in plane strain, free in plane
/// stress, where only St. Venant–Kirchhoff is offered). Needs det F > 0 (the caller checks).
///  - St. Venant–Kirchhoff: W = λ/2 (tr E)² + μ E:E, S = λ tr E I + 2μ E (the linear D acting on
///    the Green–Lagrange strain; in plane stress the plane-stress D).
///  - Neo-Hooke (compressible): W = μ/2 (I₁ − 3) − μ ln J + λ/2 (ln J)²,
///    S = μ (I − C⁻¹) + λ ln J C⁻¹, ℂ = λ C⁻¹⊗C⁻¹ + 2(μ − λ ln J) 𝕀(C⁻¹).
/// Both reduce to linear elasticity for small strains; λ, μ are Lamé's constants of E, ν.
HyperelasticState hyperelastic_state(const LinearElastic& elastic, Law law, const Eigen::Matrix2d& F);

/// The state of any finite-strain law; a rubber law is rubber_stress with C33 = 1 (plane
/// strain), restricted to (11, 22, 12) and S33.
HyperelasticState hyperelastic_state(const FiniteStrainLaw& law, const Eigen::Matrix2d& F);

/// Cauchy stress σ = F S Fᵀ / J in Voigt (xx, yy, xy) and σ_zz = S33 / J (plane strain).
Voigt cauchy_stress(const HyperelasticState& state, const Eigen::Matrix2d& F, double* sigma_zz);

}  // namespace hpcontact::material
