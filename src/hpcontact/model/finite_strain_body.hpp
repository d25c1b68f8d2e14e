// The finite-strain element of a body, whichever its plane: the plane element with the body's
// thickness, or the axisymmetric one over the ring.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// Element q of a finite-strain body with values ev at local coefficients u_e.
fem::FiniteStrainElement finite_strain_element(const Body& body, int q, const fem::ElementValues& ev,
                                               const Eigen::VectorXd& u_e, bool tangent);

}  // namespace hpcontact::model
