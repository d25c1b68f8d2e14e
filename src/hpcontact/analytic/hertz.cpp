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

double contact_modulus(double E, double nu, bool plane_strain) {
  return plane_strain ? E / (1 - nu * nu) : E;
}

double pair_modulus(double m1, double m2) { return 1 / (1 / m1 + 1 / m2); }

double pair_radius(double r1, double r2) {
  const double curvature = 1 / r1 + 1 / r2;
  HPC_ASSERT(curvature > 0, "pair_radius: 1/R1 + 1/R2 = ", curvature, " must be > 0");
  return 1 / curvature;
}

double Hertz::half_width() const {
  const double E_star = youngs_modulus / (1 - poisson_ratio * poisson_ratio);
  if (sphere) return std::cbrt(3 * force * radius / (4 * E_star));
  return std::sqrt(4 * force * radius / (pi * E_star));
}

double Hertz::peak_pressure() const {
  const double a = half_width();
  return sphere ? 3 * force / (2 * pi * a * a) : 2 * force / (pi * a);
}

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
  // The nodes of pressure()'s integral and f' there, the same for every y.
  for (size_t i = 0; i < x.size(); ++i) {
    t_.push_back(b_ * std::sin(0.5 * pi * x[i]));
    df_t_.push_back(df_(t_.back()));
  }
}

Shtayerman Shtayerman::circle(double R, double force, double E, double nu) {
  return Shtayerman([R](double t) { return t / std::sqrt(R * R - t * t); },
                    [R](double t) { return R * R / std::pow(R * R - t * t, 1.5); }, force, E, nu,
                    0.1 * R);
}

Shtayerman Shtayerman::two_circles(double R1, double R2, double force, double E_star) {
  // f'(t) = t / sqrt(R² − t²) of each convex circle, with the sign of R for a concave one; a
  // plane (R = ∞) adds nothing.
  auto df = [](double R, double t) {
    return std::isinf(R) ? 0.0 : std::copysign(1.0, R) * t / std::sqrt(R * R - t * t);
  };
  auto d2f = [](double R, double t) {
    return std::isinf(R) ? 0.0 : std::copysign(1.0, R) * R * R / std::pow(R * R - t * t, 1.5);
  };
  const double r = std::min(R1, std::abs(R2));
  return Shtayerman([=](double t) { return df(R1, t) + df(R2, t); },
                    [=](double t) { return d2f(R1, t) + d2f(R2, t); }, force, E_star, 0.0,
                    0.1 * r);
}

Shtayerman Shtayerman::parabola(double R, double force, double E, double nu) {
  return Shtayerman([R](double t) { return t / R; }, [R](double) { return 1 / R; }, force, E, nu,
                    0.1 * R);
}

double Shtayerman::pressure(double y) const {
  if (std::abs(y) >= b_) return 0.0;
  const auto& w = rule().weights;
  const double fy = df_(y);
  double s = 0;
  for (size_t i = 0; i < t_.size(); ++i) {
    const double t = t_[i];
    const double dd = std::abs(t - y) > 1e-9 * b_ ? (df_t_[i] - fy) / (t - y) : d2f_(y);
    s += 0.5 * pi * w[i] * dd;
  }
  return std::sqrt(b_ * b_ - y * y) / (pi * K_) * s;
}

}  // namespace hpcontact::analytic
