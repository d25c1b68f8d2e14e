// Coulomb's cone: the stick–slip test, and the return mapping of penalty-regularised friction.
#include "hpcontact/contact/friction.hpp"

#include <cmath>

namespace hpcontact::contact {

StickSlip stick_or_slip(const FrictionLaw& law, double t_t, double p_n) {
  const bool on_cone = std::abs(t_t) >= (1 - 1e-9) * law.mu * p_n;
  return law.kind == FrictionLaw::Kind::coulomb && on_cone ? StickSlip::slip : StickSlip::stick;
}

Tangential return_map(const FrictionLaw& law, double g_t, double slip_n, double p_n) {
  Tangential r;
  const double trial = law.eps_t * (g_t - slip_n);
  const double bound = law.mu * p_n;
  // A zero trial sticks even at the cone's apex, p_N = 0 (a point that just touches is held by
  // ε_T, not left without tangential stiffness).
  if (trial == 0 || stick_or_slip(law, trial, p_n) == StickSlip::stick) {
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
