// Gauss–Legendre and Gauss–Lobatto rules by Newton iteration on Legendre polynomials, cached.
#include "hpcontact/basis/quadrature.hpp"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>

#include "hpcontact/core/error.hpp"

namespace hpcontact::basis {

namespace {

constexpr int max_newton_iterations = 100;
/// Absolute size of the last Newton step on [-1, 1]; the step after it would be below round-off.
constexpr double newton_step_tolerance = 1e-15;

/// L_n(x) and L_{n-1}(x) for n >= 1, by Bonnet's recursion (eq. 2.64).
struct LegendrePair {
  double L_n;
  double L_nm1;
};

LegendrePair legendre_pair(int n, double x) {
  double L_nm1 = 1.0;
  double L_n = x;
  for (int k = 2; k <= n; ++k) {
    const double L_k = ((2 * k - 1) * x * L_n - (k - 1) * L_nm1) / k;
    L_nm1 = L_n;
    L_n = L_k;
  }
  return {L_n, L_nm1};
}

/// L'_n(x) for n >= 1 as the Gegenbauer polynomial C^{3/2}_{n-1}, by its own three-term recursion
/// k C_k = (2k+1) x C_{k-1} - (k+1) C_{k-2}, C_0 = 1, C_1 = 3x; regular on all of [-1, 1].
double legendre_derivative(int n, double x) {
  double C_km2 = 1.0;
  double C_km1 = 3.0 * x;
  if (n == 1) return C_km2;
  for (int k = 2; k <= n - 1; ++k) {
    const double C_k = ((2 * k + 1) * x * C_km1 - (k + 1) * C_km2) / k;
    C_km2 = C_km1;
    C_km1 = C_k;
  }
  return C_km1;
}

/// The n roots of L_n, ascending, and w_i = 2 / ((1 - x_i^2) L'_n(x_i)^2).
QuadratureRule1D compute_gauss_legendre(int n) {
  QuadratureRule1D rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  // 1 - x^2 is formed as (1 - x)(1 + x) throughout: no cancellation next to the end points.
  // L'_n = n (L_{n-1} - x L_n) / (1 - x^2) is accurate at interior points, where the roots are.
  auto derivative = [n](double x, const LegendrePair& L) {
    return n * (L.L_nm1 - x * L.L_n) / ((1.0 - x) * (1.0 + x));
  };
  // Roots come in pairs +-x; compute the positive one of each pair (from near 1 inwards) and
  // mirror it, so the rule is exactly symmetric. For odd n the middle root is 0.
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double x = 0.0;
    if (2 * i + 1 != n) {
      // Initial guess: x_i ~ cos(pi (i + 3/4) / (n + 1/2)), close enough for quadratic convergence.
      x = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5));
      for (int it = 0; it < max_newton_iterations; ++it) {
        const LegendrePair L = legendre_pair(n, x);
        const double step = L.L_n / derivative(x, L);
        x -= step;
        if (std::abs(step) <= newton_step_tolerance) break;
      }
    }
    // The stored x is the root r rounded, off by delta = r - x ~ -L_n / L'_n (below an ulp). Near
    // the ends the weight is sensitive to that (d ln w / dx ~ -2x / (1 - x^2)), so evaluate
    // D = (1 - x^2) L'_n^2 at r to first order, with D' = 2 L'_n (x L'_n - n(n+1) L_n) from the
    // Legendre equation (eq. 2.61).
    const LegendrePair L = legendre_pair(n, x);
    const double dL = derivative(x, L);
    const double delta = -L.L_n / dL;
    const double D = (1.0 - x) * (1.0 + x) * dL * dL +
                     delta * 2.0 * dL * (x * dL - n * (n + 1.0) * L.L_n);
    const double w = 2.0 / D;
    rule.points[i] = -x;  // written first so that the middle root of odd n is +0
    rule.points[n - 1 - i] = x;
    rule.weights[i] = w;
    rule.weights[n - 1 - i] = w;
  }
  return rule;
}

/// End points and the n-2 roots of L'_{n-1}, ascending; w_i = 2 / (n (n-1) L_{n-1}(x_i)^2).
QuadratureRule1D compute_gauss_lobatto(int n) {
  const int m = n - 1;  // the interior points are the roots of L'_m
  QuadratureRule1D rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  // The roots of L'_m interlace with those of L_m (Rolle), one in each gap between Gauss points:
  // a safeguarded Newton iteration in that bracket cannot miss or repeat a root.
  const QuadratureRule1D& gauss = gauss_legendre(m);
  for (int i = 0; i < n / 2; ++i) {
    double x = 1.0;
    if (i > 0) {
      // Root between the Gauss points g_{m-i-1} < x < g_{m-i} (positive half, from 1 inwards).
      double lo = gauss.points[m - i - 1];
      double hi = gauss.points[m - i];
      const bool f_lo_positive = legendre_derivative(m, lo) > 0.0;
      // Initial guess: the Chebyshev–Gauss–Lobatto point cos(pi i / m), kept inside the bracket.
      x = std::cos(std::numbers::pi * i / m);
      if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
      for (int it = 0; it < max_newton_iterations; ++it) {
        // Newton on f = L'_m with f' = L''_m = (2x L'_m - m(m+1) L_m) / (1 - x^2) (eq. 2.61).
        const double f = legendre_derivative(m, x);
        if (f == 0.0) break;
        const double df = (2.0 * x * f - m * (m + 1.0) * legendre_pair(m, x).L_n) /
                          ((1.0 - x) * (1.0 + x));
        ((f > 0.0) == f_lo_positive ? lo : hi) = x;  // keep the root bracketed
        double x_new = x - f / df;
        const bool bisect = !(x_new >= lo && x_new <= hi);  // Newton left the bracket
        if (bisect) x_new = 0.5 * (lo + hi);
        const double step = x_new - x;
        x = x_new;
        if (!bisect && std::abs(step) <= newton_step_tolerance) break;
      }
    }
    // L_m is stationary at the roots of L'_m, so the weight is insensitive to the node's rounding.
    const double L = legendre_pair(m, x).L_n;
    const double w = 2.0 / (n * m * L * L);
    rule.points[i] = -x;
    rule.points[n - 1 - i] = x;
    rule.weights[i] = w;
    rule.weights[n - 1 - i] = w;
  }
  if (n % 2 == 1) {
    const double L = legendre_pair(m, 0.0).L_n;
    rule.points[n / 2] = 0.0;
    rule.weights[n / 2] = 2.0 / (n * m * L * L);
  }
  return rule;
}

/// Rules computed once per size and kept for the life of the program; the references handed
/// out stay valid because each rule lives in its own heap allocation.
class RuleCache {
public:
  explicit RuleCache(QuadratureRule1D (*compute)(int)) : compute_(compute) {}

  const QuadratureRule1D& get(int n) {
    {
      std::lock_guard lock(mutex_);
      if (auto it = rules_.find(n); it != rules_.end()) return *it->second;
    }
    // Compute outside the lock (Lobatto asks for a Gauss rule); if another thread got there
    // first, its rule is kept and ours is dropped.
    auto rule = std::make_unique<QuadratureRule1D>(compute_(n));
    std::lock_guard lock(mutex_);
    return *rules_.try_emplace(n, std::move(rule)).first->second;
  }

private:
  QuadratureRule1D (*compute_)(int);
  std::mutex mutex_;
  std::map<int, std::unique_ptr<QuadratureRule1D>> rules_;
};

}  // namespace

const QuadratureRule1D& gauss_legendre(int n_points) {
  HPC_REQUIRE(n_points >= 1, InputError,
              "gauss_legendre: n_points must be >= 1 (got ", n_points, ")");
  static RuleCache cache(compute_gauss_legendre);
  return cache.get(n_points);
}

const QuadratureRule1D& gauss_lobatto(int n_points) {
  HPC_REQUIRE(n_points >= 2, InputError,
              "gauss_lobatto: n_points must be >= 2 (got ", n_points, ")");
  static RuleCache cache(compute_gauss_lobatto);
  return cache.get(n_points);
}

}  // namespace hpcontact::basis
