// Total Lagrangian element of finite-strain elasticity (seed §2.1.1): internal force, consistent
// tangent (material + geometric) and strain energy of one element.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/material/hyperelastic.hpp"

namespace hpcontact::fem {

/// Deformation gradient F = I + ∂u/∂X at quadrature point k for local coefficients u_e
/// (component-blocked).
Eigen::Matrix2d deformation_gradient(const ElementValues& ev, int k, const Eigen::VectorXd& u_e);
/// The same at one point.
Eigen::Matrix2d deformation_gradient(const PointValues& pv, const Eigen::VectorXd& u_e);

struct FiniteStrainElement {
  Eigen::VectorXd f_int;  ///< t ∫ Bᵀ S dA (component-blocked local order)
  Eigen::MatrixXd K;      ///< d f_int / d u_e, symmetric; empty unless asked for
  double energy = 0;      ///< t ∫ W dA
  double min_J = 0;       ///< smallest det F over the quadrature points
  int min_J_point = -1;   ///< where it is
  bool inverted() const { return !(min_J > 0); }
};

/// The element at local coefficients u_e. Where det F ≤ 0 at a quadrature point the element is
/// inverted: f_int, K and energy are left empty and zero, min_J says by how much.
/// K += the in-plane geometric stiffness δ_ik ∇N_a · S ∇N_b, the point weights times S's
/// components (11, 22, 12) given per quadrature point, on both displacement blocks.
void add_geometric_stiffness(const ElementValues& ev, const Eigen::VectorXd& wS11,
                             const Eigen::VectorXd& wS22, const Eigen::VectorXd& wS12,
                             Eigen::MatrixXd& K);

FiniteStrainElement finite_strain_element(const ElementValues& ev, const material::FiniteStrainLaw& law,
                                          double thickness, const Eigen::VectorXd& u_e, bool tangent);

}  // namespace hpcontact::fem
