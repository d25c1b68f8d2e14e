// The finite-strain element of a body, whichever its plane and formulation: the plane element
// with the body's thickness, the axisymmetric one over the ring, or the mixed u–p element.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// Element q of a finite-strain body with values ev at the state u (all dofs). Its f_int and K
/// are over the element's local dofs (Body::global_dof): the displacements, then for a mixed
/// body its pressures.
fem::FiniteStrainElement finite_strain_element(const Body& body, int q, const fem::ElementValues& ev,
                                               const Eigen::VectorXd& u, bool tangent);

/// The pressure of a mixed body's element q at the reference point (xi, eta) at the state u (all
/// dofs).
double mixed_pressure(const Body& body, int q, double xi, double eta, const Eigen::VectorXd& u);

}  // namespace hpcontact::model
