// Hertz in closed form; Shtayerman by Gauss quadrature in theta and a safeguarded secant for b.
#include "hpcontact/analytic/hertz.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::analytic {

namespace {
constexpr double pi = std::numbers::pi;

/// The 200-point Gauss–Legendre rule used for both Shtayerman integrals (smooth in theta).
const basis::QuadratureRule1D& rule() { return basis::gauss_legendre(200); }
}  // namespace

double Hertz::half_width() const {
  return std::sqrt(4 * force * radius * (1 - poisson_ratio * poisson_ratio) /
                   (pi * youngs_modulus));
}

double Hertz::peak_pressure() const { return 2 * force / (pi * half_width()); }

double Hertz::pressure(double x) const {
  const double b = half_width();
  return std::abs(x) >= b ? 0.0 : peak_pressure() * std::sqrt(1 - x * x / (b * b));
}

Shtayerman::Shtayerman(std::function<double(double)> df, std::function<double(double)> d2f,
                       double force, double youngs_modulus, double poisson_ratio, double b_guess)
    : df_(std::move(df)),
      d2f_(std::move(d2f)),
      K_(2 * (1 - poisson_ratio * poisson_ratio) / youngs_modulus),
      F_(force) {
  const auto& x = rule().points;
  const auto& w = rule().weights;
  // g(b) = ∫ t f'(t) / sqrt(b² - t²) dt - K F, with t = b sin(theta), theta in (-pi/2, pi/2).
  auto g = [&](double b) {
    double s = 0;
    for (size_t i = 0; i < x.size(); ++i) {
      const double t = b * std::sin(0.5 * pi * x[i]);
      s += 0.5 * pi * w[i] * t * df_(t);
    }
    return s - K_ * F_;
  };
  // g increases with b: bracket, then bisection (robust, 1e-15 relative).
  double lo = 0.0, hi = b_guess;
  while (g(hi) < 0) hi *= 2;
  for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < 0 ? lo : hi) = mid;
  }
  b_ = 0.5 * (lo + hi);
}

Shtayerman Shtayerman::circle(double R, double force, double E, double nu) {
  return Shtayerman([R](double t) { return t / std::sqrt(R * R - t * t); },
                    [R](double t) { return R * R / std::pow(R * R - t * t, 1.5); }, force, E, nu,
                    0.1 * R);
}

Shtayerman Shtayerman::parabola(double R, double force, double E, double nu) {
  return Shtayerman([R](double t) { return t / R; }, [R](double) { return 1 / R; }, force, E, nu,
                    0.1 * R);
}

double Shtayerman::pressure(double y) const {
  if (std::abs(y) >= b_) return 0.0;
  const auto& x = rule().points;
  const auto& w = rule().weights;
  const double fy = df_(y);
  double s = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    const double t = b_ * std::sin(0.5 * pi * x[i]);
    const double dd = std::abs(t - y) > 1e-9 * b_ ? (df_(t) - fy) / (t - y) : d2f_(y);
    s += 0.5 * pi * w[i] * dd;
  }
  return std::sqrt(b_ * b_ - y * y) / (pi * K_) * s;
}

}  // namespace hpcontact::analytic
