// Hertz and Shtayerman solutions for a plane-strain cylinder pressed onto a rigid flat (seed §5.2.1).
#pragma once

#include <functional>

namespace hpcontact::analytic {

/// Hertz, cylinder of radius R on a rigid plane, plane strain, force F per unit length on the
/// whole cylinder (seed eq. 5.1–5.3 with r2, E2 -> infinity):
///   b = sqrt(4 F R (1 - nu²) / (pi E)),  p0 = 2 F / (pi b),  p(x) = p0 sqrt(1 - x²/b²).
struct Hertz {
  double radius, force, youngs_modulus, poisson_ratio;
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
  /// The parabola f(t) = t² / (2R), for which the solution is Hertz's.
  static Shtayerman parabola(double radius, double force, double youngs_modulus,
                             double poisson_ratio);

  double half_width() const { return b_; }
  double pressure(double y) const;  ///< 0 outside [-b, b]

private:
  std::function<double(double)> df_, d2f_;
  double K_, F_, b_;
};

}  // namespace hpcontact::analytic
