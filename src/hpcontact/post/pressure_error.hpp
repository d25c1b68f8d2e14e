// Contact-pressure error measures over [0, 1.5 b_ref] (docs/cases.md §1; the seed's eq. 5.11).
#pragma once

#include <functional>

namespace hpcontact::post {

struct PressureErrors {
  /// 100 sqrt(∫ (p_ref - p)² dx / ∫ p_ref² dx) [%], the relative L2 error.
  double e_L2 = 0;
  /// 100 ∫ ((p_ref - p)/p0)² d(x/b) / ∫ (p_ref/p0) d(x/b) [%], the seed-style squared measure.
  double e_seed = 0;
};

/// Both measures of p against p_ref over [0, 1.5 b_ref], by composite Gauss quadrature split at
/// b_ref (where p_ref has its square-root end). p0 normalises e_seed (Hertz's peak pressure).
PressureErrors pressure_errors(const std::function<double(double)>& p,
                               const std::function<double(double)>& p_ref, double b_ref, double p0);

}  // namespace hpcontact::post
