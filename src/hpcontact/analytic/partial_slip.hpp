// Partial slip of two elastically similar cylinders under a normal and then a monotonically
// increasing tangential force (Cattaneo 1938, Mindlin 1949, in 2-D: Johnson, Contact Mechanics
// §7.1; derivation in docs/theory.md §10a).
#pragma once

#include <cmath>

#include "hpcontact/analytic/hertz.hpp"

namespace hpcontact::analytic {

/// Two elastically similar cylinders in plane strain (the normal and tangential half-space
/// problems uncouple), pressed by P per unit length, then sheared by Q, 0 <= Q <= mu P, applied
/// monotonically from 0 at constant P. With a the Hertz half width, p0 its peak pressure and
/// c = a sqrt(1 - Q / (mu P)) the half width of the central stick zone:
///   p(x) = p0 sqrt(1 - x²/a²)                                        |x| < a
///   q(x) = mu p(x)                                                    c <= |x| < a (slip)
///   q(x) = mu p0 [sqrt(1 - x²/a²) - (c/a) sqrt(1 - x²/c²)]            |x| < c (stick)
/// x along the common tangent from the centre of contact; q in the direction of Q, force per
/// unit length along the tangent like p. Q = mu P is gross slip (c = 0).
class PartialSlip {
public:
  /// R* and E* of the pair (pair_radius, pair_modulus), P and Q per unit length, mu > 0.
  /// Precondition: P > 0, 0 <= Q <= mu P.
  PartialSlip(double effective_radius, double normal_force, double effective_modulus,
              double friction_coefficient, double tangential_force);

  double half_width() const { return a_; }        ///< a, Hertz's
  double stick_half_width() const { return c_; }  ///< c = a sqrt(1 - Q / (mu P))
  double peak_pressure() const { return p0_; }    ///< p0 = 2 P / (pi a)
  double pressure(double x) const;                ///< p(x); 0 outside [-a, a]
  double shear(double x) const;                   ///< q(x); 0 outside [-a, a]
  bool sticks(double x) const { return std::abs(x) < c_; }

private:
  double mu_, a_, c_, p0_;
};

}  // namespace hpcontact::analytic
