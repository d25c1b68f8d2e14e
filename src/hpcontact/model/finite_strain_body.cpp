// Dispatch of a body's finite-strain element on its plane and formulation.
#include "hpcontact/model/finite_strain_body.hpp"

#include "hpcontact/fem/axisymmetric_finite_strain.hpp"
#include "hpcontact/fem/mixed_finite_strain.hpp"

namespace hpcontact::model {

fem::FiniteStrainElement finite_strain_element(const Body& body, int q, const fem::ElementValues& ev,
                                               const Eigen::VectorXd& u, bool tangent) {
  const Eigen::VectorXd u_e = body.element_coefficients(q, u);
  if (body.mixed) {
    const Eigen::MatrixXd psi =
        fem::pressure_modes_at_gauss_points(fem::pressure_degree(body.dofs.element(q)), body.n_gauss[q]);
    return fem::mixed_finite_strain_element(ev, psi, body.rubber, body.inverse_bulk, body.out_of_plane(),
                                            u_e, body.element_pressures(q, u), tangent);
  }
  if (body.axisymmetric())
    return fem::axisymmetric_finite_strain_element(ev, body.finite_strain_law(q), u_e, tangent);
  return fem::finite_strain_element(ev, body.finite_strain_law(q), body.thickness, u_e, tangent);
}

double mixed_pressure(const Body& body, int q, double xi, double eta, const Eigen::VectorXd& u) {
  const int degree = fem::pressure_degree(body.dofs.element(q));
  return fem::pressure_modes(degree, xi, eta).dot(body.element_pressures(q, u));
}

}  // namespace hpcontact::model
