// The return mapping of penalty-regularised Coulomb friction.
#include "hpcontact/contact/friction.hpp"

#include <cmath>

namespace hpcontact::contact {

Tangential return_map(const FrictionLaw& law, double g_t, double slip_n, double p_n) {
  Tangential r;
  const double trial = law.eps_t * (g_t - slip_n);
  const double bound = law.mu * p_n;
  // Stick inside the cone; a zero trial sticks even at p_N = 0 (a point that just touches is
  // held by ε_T, not left without tangential stiffness).
  if (law.kind == FrictionLaw::Kind::stick || trial == 0 || std::abs(trial) < (1 - 1e-9) * bound) {
    r.traction = trial;
    r.slip = slip_n;
    r.state = StickSlip::stick;
    r.dt_dgt = law.eps_t;
    return r;
  }
  r.traction = std::copysign(bound, trial);
  r.slip = g_t - r.traction / law.eps_t;
  r.state = StickSlip::slip;
  r.dt_dp = std::copysign(law.mu, trial);
  return r;
}

}  // namespace hpcontact::contact
