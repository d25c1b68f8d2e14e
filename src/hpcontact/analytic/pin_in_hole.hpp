// Frictionless conforming contact of an elastic pin pressed into a slightly larger hole of an
// elastic plate (Persson's problem), solved "exactly" in the linear theory of small clearance.
#pragma once

#include <limits>
#include <vector>

namespace hpcontact::analytic {

/// A pin of radius R1 in a hole of radius R2 = R1 + ΔR, ΔR > 0 and ΔR << R1, pressed towards
/// θ = 0 by a force P per unit thickness; frictionless; plane strain unless said otherwise.
///
/// The plate is infinite, or an annulus R2 <= r <= R_out held (u = 0) at R_out. The pin is a solid
/// disc loaded by a concentrated force at its centre or by a uniform body force (the two give the
/// same contact: a uniform body force balanced by the pressure P cos θ / (π R1) moves the rim
/// radially only by a multiple of cos θ, see pin_in_hole.cpp), or, with pin_core_radius > 0, an
/// annulus r_c <= r <= R1 whose inner circle is moved rigidly (a prescribed displacement).
///
/// The linear theory poses the contact on the circle of radius R1 (the pin's radius): the
/// radii of the two surfaces differ by ΔR, so its answer is exact as ΔR/R1 -> 0 and otherwise
/// carries errors of order ΔR/R1 (5e-4 in the angle at ΔR/R1 = 1e-3).
struct PinInHole {
  double pin_radius;                ///< R1
  double hole_radius;               ///< R2 > R1
  double pin_youngs_modulus;        ///< E1
  double pin_poisson_ratio;         ///< ν1
  double plate_youngs_modulus;      ///< E2
  double plate_poisson_ratio;       ///< ν2
  /// R_out > R2, where the plate is held; ∞ an infinite plate.
  double plate_outer_radius = std::numeric_limits<double>::infinity();
  /// r_c, 0 <= r_c < R1: the pin's displacement is prescribed rigid on r = r_c; 0 a solid pin.
  double pin_core_radius = 0;
  bool plane_strain = true;
};

/// The pair's contact modulus E*: 1/E* = 1/E'1 + 1/E'2, E' = 8G/(κ+1) (E/(1 − ν²) in plane
/// strain, E in plane stress).
double pin_in_hole_modulus(const PinInHole& problem);

/// Dundurs' β = [G1(κ2 − 1) − G2(κ1 − 1)] / [G1(κ2 + 1) + G2(κ1 + 1)] of pin (1) and plate (2).
double pin_in_hole_dundurs_beta(const PinInHole& problem);

/// Λ_n, n = 0 or n >= 2: how far the surfaces move apart radially (plate outwards plus pin
/// inwards, length) under a unit pressure cos nθ (force per length²) acting on both, the sum of
/// the pin's and the plate's compliances (Michell's solution). Λ_1 is not defined: the cos θ part of
/// the radial displacements is a rigid approach, eliminated by the force.
double pin_in_hole_gap_compliance(const PinInHole& problem, int n);

/// The contact for one half-angle ε of the contact arc (|θ| < ε, θ from the load line, radians),
/// 0 < ε < limit_half_angle: the force P that makes it, and the pressure p(θ) (force per unit
/// arc length and thickness, that is, per area). Everything is proportional to ΔR.
class PinInHoleContact {
public:
  PinInHoleContact(const PinInHole& problem, double half_angle);
  /// The contact under the force P > 0 per unit thickness (the inverse of force()).
  static PinInHoleContact at_force(const PinInHole& problem, double force);

  double half_angle() const { return half_angle_; }
  double force() const { return force_; }  ///< P = ∫ p(θ) cos θ R1 dθ
  /// p(θ) for θ in [-π, π]; 0 outside the arc.
  double pressure(double theta) const;

private:
  PinInHole problem_;
  double half_angle_, force_;
  /// a_k of the pressure density q(y) = p dθ/dy = sqrt(1 − y²) Σ_k a_k U_2k(y), y = tan(θ/2) /
  /// tan(ε/2).
  std::vector<double> coefficients_;
};

/// The force P for a half-angle ε (PinInHoleContact(problem, ε).force()).
double pin_in_hole_force(const PinInHole& problem, double half_angle);

/// The half-angle under the force P (PinInHoleContact::at_force(problem, P).half_angle()).
double pin_in_hole_half_angle(const PinInHole& problem, double force);

/// The half-angle the contact tends to as P -> ∞ (that of zero clearance), where P(ε) has its
/// pole: 84.83° for elastically similar bodies (β = 0) in an infinite plate, whatever ν.
double pin_in_hole_limit_half_angle(const PinInHole& problem);

}  // namespace hpcontact::analytic
