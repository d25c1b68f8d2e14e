// Contact-pressure error measures over [0, 1.5 b_ref] (docs/cases.md §1; the seed's eq. 5.11).
#pragma once

#include <functional>
#include <vector>

namespace hpcontact::post {

struct PressureErrors {
  /// 100 sqrt(∫ (p_ref - p)² dx / ∫ p_ref² dx) [%], the relative L2 error.
  double e_L2 = 0;
  /// 100 ∫ ((p_ref - p)/p0)² d(x/b) / ∫ (p_ref/p0) d(x/b) [%], the seed-style squared measure.
  double e_seed = 0;
};

/// Both measures of p against p_ref over [0, 1.5 b_ref], by composite Gauss quadrature: 250
/// pieces graded towards b_ref (where p_ref has its square-root end), each split further at the
/// `breaks` inside it, the points where p or p_ref is not smooth (the ends of the contact edges,
/// the samples of a sampled reference), so that every piece integrates a smooth function; `points`
/// Gauss points a piece (20 when nothing is split: the pieces then straddle the kinks). p0
/// normalises e_seed (Hertz's peak pressure).
PressureErrors pressure_errors(const std::function<double(double)>& p,
                               const std::function<double(double)>& p_ref, double b_ref, double p0,
                               const std::vector<double>& breaks = {}, int points = 20);

}  // namespace hpcontact::post
