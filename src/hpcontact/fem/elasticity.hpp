// Element stiffness matrix and body-force vector of linear elasticity (seed eq. 2.44, 2.47).
#pragma once

#include <Eigen/Dense>

#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
#include "hpcontact/material/linear_elastic.hpp"

namespace hpcontact::fem {

/// Local dof order of element matrices and vectors: component-blocked, the x components of all
/// local modes first, then the y components: local dof = component * n_modes + local mode.

/// K_e = t ∫ B^T D B dA (eq. 2.44), 2n × 2n, symmetric.
Eigen::MatrixXd stiffness(const ElementValues& ev, const material::Elasticity& D, double thickness);

/// The stiffness of an axisymmetric element (x = r): ∫ Bᵀ D₄ B 2π r dA with the hoop row
/// ε_θθ = u_r / r (N_a / r on the u_r dofs) besides the plane rows; r is that of each Gauss
/// point, never 0 (Gauss points are inside the element).
Eigen::MatrixXd axisymmetric_stiffness(const ElementValues& ev, const material::LinearElastic& m);


/// f_e = t ∫ N^T b dA (eq. 2.47) for a constant body force b (force per volume).
Eigen::VectorXd body_force(const ElementValues& ev, const Vec2& b, const OutOfPlane& measure);

/// Strain (Voigt xx, yy, gamma_xy) at every quadrature point for local coefficients u_e
/// (component-blocked); 3 × n_points.
Eigen::Matrix3Xd strains(const ElementValues& ev, const Eigen::VectorXd& u_e);

/// Strain (xx, yy, gamma_xy) at one point for local coefficients u_e (component-blocked).
Eigen::Vector3d strain(const PointValues& pv, const Eigen::VectorXd& u_e);

}  // namespace hpcontact::fem
