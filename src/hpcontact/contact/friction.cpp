// The return mapping of penalty-regularised Coulomb friction.
#include "hpcontact/contact/friction.hpp"

#include <cmath>

namespace hpcontact::contact {

Tangential return_map(const FrictionLaw& law, double g_t, double slip_n, double p_n) {
  Tangential r;
  const double trial = law.eps_t * (g_t - slip_n);
  const double bound = law.mu * p_n;
  if (law.kind == FrictionLaw::Kind::stick || std::abs(trial) <= bound) {
    r.traction = trial;
    r.slip = slip_n;
    r.state = StickSlip::stick;
    return r;
  }
  r.traction = std::copysign(bound, trial);
  r.slip = g_t - r.traction / law.eps_t;
  r.state = StickSlip::slip;
  return r;
}

}  // namespace hpcontact::contact
