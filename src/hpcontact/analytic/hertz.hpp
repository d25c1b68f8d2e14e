// Hertz and Shtayerman solutions for a cylinder pressed onto a rigid flat (seed §5.2.1), and for
// two elastic bodies through the pair's contact modulus E* and radius R*.
#pragma once

#include <functional>
#include <vector>
#include <limits>

namespace hpcontact::analytic {

/// The contact modulus E' of one body: E / (1 − ν²) in plane strain, E in plane stress.
double contact_modulus(double youngs_modulus, double poisson_ratio, bool plane_strain);

/// The pair's contact modulus E*: 1/E* = 1/E'_1 + 1/E'_2 (a rigid obstacle: E'_2 = ∞).
double pair_modulus(double modulus_1, double modulus_2 = std::numeric_limits<double>::infinity());

/// The pair's radius R*: 1/R* = 1/R_1 + 1/R_2, R_2 = ∞ for a plane, R_2 < 0 for a concave
/// surface (a hole), |R_2| > R_1 then. Precondition: 1/R_1 + 1/R_2 > 0.
double pair_radius(double radius_1, double radius_2 = std::numeric_limits<double>::infinity());

/// Hertz, cylinder of radius R on a rigid plane, plane strain, force F per unit length on the
/// whole cylinder (seed eq. 5.1–5.3 with r2, E2 -> infinity):
///   b = sqrt(4 F R (1 - nu²) / (pi E)),  p0 = 2 F / (pi b),  p(x) = p0 sqrt(1 - x²/b²).
struct Hertz {
  double radius, force, youngs_modulus, poisson_ratio;
  /// Spheres (3-D, axisymmetric models): a = (3 F R* / (4 E*))^(1/3), p0 = 3 F / (2 pi a²),
  /// p(r) = p0 sqrt(1 - r²/a²), F the total force; half_width() is a.
  bool sphere = false;
  /// Two elastic bodies (or one on a rigid obstacle): b = sqrt(4 F R* / (pi E*)), that is the
  /// single body's formula with R = R*, E = E* and nu = 0.
  static Hertz pair(double effective_radius, double force, double effective_modulus) {
    return {effective_radius, force, effective_modulus, 0.0};
  }
  /// Two spheres (or a sphere on a flat) of R* and E* (1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂).
  static Hertz spheres(double effective_radius, double force, double effective_modulus) {
    return {effective_radius, force, effective_modulus, 0.0, true};
  }
  double half_width() const;
  double peak_pressure() const;
  double pressure(double x) const;  ///< 0 outside [-b, b]
};

/// Shtayerman's solution (seed eq. 5.4–5.10) for a symmetric gap profile f(t) between a body
/// and a rigid plane, plane strain: K = (kappa + 1)/(4G) = 2(1 - nu²)/E;
///   b from  ∫_{-b}^{b} t f'(t) / sqrt(b² - t²) dt = K F                         (eq. 5.6)
///   p(y) = sqrt(b² - y²) / (pi K) PV∫_{-b}^{b} f'(t) / (sqrt(b² - t²) (t - y)) dt (eq. 5.10)
/// (eq. 5.5 holds by symmetry). With t = b sin(theta) both integrals are regular: the principal
/// value is that of the divided difference (f'(t) - f'(y)) / (t - y), because
/// PV∫ dt / (sqrt(b² - t²)(t - y)) = 0 for |y| < b.
class Shtayerman {
public:
  /// f'(t) and f''(t) of the profile; F force per unit length on the whole body.
  Shtayerman(std::function<double(double)> df, std::function<double(double)> d2f, double force,
             double youngs_modulus, double poisson_ratio, double b_guess);
  /// The exact circle of radius R: f(t) = R - sqrt(R² - t²).
  static Shtayerman circle(double radius, double force, double youngs_modulus, double poisson_ratio);
  /// Two circles of radii R_1 (the body) and R_2 (the obstacle; ∞ a plane, < 0 concave): the
  /// gap profile f(t) = R_1 − sqrt(R_1² − t²) + R_2 − sign(R_2) sqrt(R_2² − t²), and
  /// K = 2 / E* (E* of pair_modulus).
  static Shtayerman two_circles(double radius_1, double radius_2, double force,
                                double effective_modulus);
  /// The parabola f(t) = t² / (2R), for which the solution is Hertz's.
  static Shtayerman parabola(double radius, double force, double youngs_modulus,
                             double poisson_ratio);

  double half_width() const { return b_; }
  double pressure(double y) const;  ///< 0 outside [-b, b]

private:
  std::function<double(double)> df_, d2f_;
  double K_, F_, b_;
  std::vector<double> t_, df_t_;  ///< b sin(π x_i / 2) of the rule's points, f' there
};

}  // namespace hpcontact::analytic
