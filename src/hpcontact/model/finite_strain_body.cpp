// Dispatch of a body's finite-strain element on its plane.
#include "hpcontact/model/finite_strain_body.hpp"

#include "hpcontact/fem/axisymmetric_finite_strain.hpp"

namespace hpcontact::model {

fem::FiniteStrainElement finite_strain_element(const Body& body, int q, const fem::ElementValues& ev,
                                               const Eigen::VectorXd& u_e, bool tangent) {
  if (body.axisymmetric())
    return fem::axisymmetric_finite_strain_element(ev, body.finite_strain_law(q), u_e, tangent);
  return fem::finite_strain_element(ev, body.finite_strain_law(q), body.thickness, u_e, tangent);
}

}  // namespace hpcontact::model
