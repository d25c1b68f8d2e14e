// Static condensation with a Cholesky factorisation of the internal block (K_ii is SPD).
#include "hpcontact/fem/condensation.hpp"

#include "hpcontact/core/error.hpp"
#include "hpcontact/core/stop.hpp"

namespace hpcontact::fem {

CondensedElement condense(const Eigen::MatrixXd& K, const Eigen::VectorXd& f, int n_modes,
                          int n_internal, int n_components) {
  CondensedElement c;
  for (int comp = 0; comp < n_components; ++comp)
    for (int a = 0; a < n_modes; ++a)
      (a < n_modes - n_internal ? c.external : c.internal).push_back(comp * n_modes + a);
  const int ne = static_cast<int>(c.external.size()), ni = static_cast<int>(c.internal.size());
  Eigen::MatrixXd Kee(ne, ne), Kei(ne, ni), Kii(ni, ni);
  Eigen::VectorXd fe(ne), fi(ni);
  for (int r = 0; r < ne; ++r) {
    fe(r) = f(c.external[r]);
    for (int s = 0; s < ne; ++s) Kee(r, s) = K(c.external[r], c.external[s]);
    for (int s = 0; s < ni; ++s) Kei(r, s) = K(c.external[r], c.internal[s]);
  }
  for (int r = 0; r < ni; ++r) {
    fi(r) = f(c.internal[r]);
    for (int s = 0; s < ni; ++s) Kii(r, s) = K(c.internal[r], c.internal[s]);
  }
  if (ni == 0) {
    c.K = Kee;
    c.f = fe;
    return c;
  }
  // A stop request is honoured between the dense phases: at high degree each is a fraction of
  // a second.
  stop_point("assembling");
  Eigen::LLT<Eigen::MatrixXd> llt(Kii);
  HPC_REQUIRE(llt.info() == Eigen::Success, NumericalError,
              "static condensation: the internal block of an element stiffness is not positive "
              "definite");
  stop_point("assembling");
  c.Kii_inv_Kie = llt.solve(Kei.transpose());
  c.Kii_inv_fi = llt.solve(fi);
  c.K = Kee - Kei * c.Kii_inv_Kie;
  c.f = fe - Kei * c.Kii_inv_fi;
  return c;
}

Eigen::VectorXd CondensedElement::recover(const Eigen::VectorXd& u_external, double load_factor) const {
  Eigen::VectorXd u(external.size() + internal.size());
  for (size_t r = 0; r < external.size(); ++r) u(external[r]) = u_external(r);
  if (!internal.empty()) {
    const Eigen::VectorXd ui = load_factor * Kii_inv_fi - Kii_inv_Kie * u_external;
    for (size_t r = 0; r < internal.size(); ++r) u(internal[r]) = ui(r);
  }
  return u;
}

}  // namespace hpcontact::fem
