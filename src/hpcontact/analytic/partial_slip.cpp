// Cattaneo–Mindlin partial slip in 2-D: Hertz's pressure, and the shear as mu times it less a
// Hertz-like correction over the stick zone.
#include "hpcontact/analytic/partial_slip.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/core/error.hpp"

namespace hpcontact::analytic {

namespace {
/// sqrt(1 - x²/w²) for |x| < w, else 0.
double ellipse(double x, double w) { return std::abs(x) < w ? std::sqrt(1 - (x / w) * (x / w)) : 0.0; }
}  // namespace

PartialSlip::PartialSlip(double R, double P, double E_star, double mu, double Q) : mu_(mu) {
  HPC_ASSERT(P > 0 && mu > 0 && Q >= 0 && Q <= mu * P, "PartialSlip: needs P > 0, mu > 0 and ",
             "0 <= Q <= mu P (got P = ", P, ", mu = ", mu, ", Q = ", Q, ")");
  const Hertz h = Hertz::pair(R, P, E_star);
  a_ = h.half_width();
  p0_ = h.peak_pressure();
  c_ = a_ * std::sqrt(std::max(0.0, 1 - Q / (mu * P)));
}

double PartialSlip::pressure(double x) const { return p0_ * ellipse(x, a_); }

double PartialSlip::shear(double x) const {
  return mu_ * p0_ * (ellipse(x, a_) - (c_ / a_) * ellipse(x, c_));
}

}  // namespace hpcontact::analytic
