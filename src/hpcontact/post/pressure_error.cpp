// Composite Gauss quadrature of the pressure error integrals.
#include "hpcontact/post/pressure_error.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/basis/quadrature.hpp"

namespace hpcontact::post {

PressureErrors pressure_errors(const std::function<double(double)>& p,
                               const std::function<double(double)>& p_ref, double b_ref, double p0,
                               const std::vector<double>& breaks, int points) {
  const auto& rule = basis::gauss_legendre(points);
  std::vector<double> cuts(breaks);
  std::sort(cuts.begin(), cuts.end());
  double diff2 = 0, ref2 = 0, ref1 = 0;
  auto gauss = [&](double a, double b) {
    for (int i = 0; i < rule.size(); ++i) {
      const double x = 0.5 * (a + b) + 0.5 * (b - a) * rule.points[i];
      const double w = 0.5 * (b - a) * rule.weights[i];
      const double pr = p_ref(x), d = pr - p(x);
      diff2 += w * d * d;
      ref2 += w * pr * pr;
      ref1 += w * pr;
    }
  };
  // one piece [a, b], split at the cuts strictly inside it
  auto integrate = [&](double a, double b) {
    double from = a;
    for (auto it = std::upper_bound(cuts.begin(), cuts.end(), a); it != cuts.end() && *it < b; ++it) {
      gauss(from, *it);
      from = *it;
    }
    gauss(from, b);
  };
  // [0, b_ref] in 200 pieces graded towards b_ref (the square-root end), [b_ref, 1.5 b_ref] in 50.
  const int n1 = 200, n2 = 50;
  for (int k = 0; k < n1; ++k) {
    // x = b (1 - (1 - s)²): pieces shrink quadratically towards b
    const double s0 = double(k) / n1, s1 = double(k + 1) / n1;
    integrate(b_ref * (1 - (1 - s0) * (1 - s0)), b_ref * (1 - (1 - s1) * (1 - s1)));
  }
  for (int k = 0; k < n2; ++k) integrate(b_ref * (1 + 0.5 * k / n2), b_ref * (1 + 0.5 * (k + 1) / n2));
  PressureErrors e;
  e.e_L2 = 100 * std::sqrt(diff2 / ref2);
  // d(x/b) = dx / b in both integrals of e_seed, so b cancels; p0 does not.
  e.e_seed = 100 * (diff2 / (p0 * p0)) / (ref1 / p0);
  return e;
}

}  // namespace hpcontact::post
