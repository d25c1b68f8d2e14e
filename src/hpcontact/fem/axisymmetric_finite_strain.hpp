// Total Lagrangian element of an axisymmetric body (x = R, y = Z): the plane element's terms
// with the hoop stretch F_θθ = 1 + u_r / R added, every integral over the ring, 2π R dA.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/material/hyperelastic.hpp"

namespace hpcontact::fem {

/// The hoop stretch F_θθ = 1 + u_r / R at a point of radius R > 0 with shape values N, local
/// coefficients u_e (component-blocked); on the axis (R ≤ 1e-12 of the point's size, where
/// u_r = 0) its limit 1 + ∂u_r/∂R, passed as F_rr.
double hoop_stretch(const Eigen::VectorXd& N, const Vec2& X, const Eigen::VectorXd& u_e, double F_rr);

/// The deformation at each Gauss point of an element: the in-plane F, the out-of-plane stretch
/// F33 (a ring: the hoop stretch 1 + u_r / R, with 1 / R; else 1 and 0), and the smallest
/// J = det F · F33 and its point (both factors must be positive: two negatives are a fold too).
struct GaussKinematics {
  std::vector<Eigen::Matrix2d> F;
  Eigen::VectorXd F33, inv_R;
  double min_J = 0;
  int min_J_point = -1;
};
GaussKinematics gauss_kinematics(const ElementValues& ev, const Eigen::VectorXd& u_e, bool ring);

/// The element at local coefficients u_e: f_int = ∫ Bᵀ S 2π R dA with the hoop row
/// δE_θθ = F_θθ N_a / R δu_r besides the plane rows, K = Bᵀ ℂ B (4 × 4 ℂ) plus the geometric
/// δ_ik ∇N_a · S ∇N_b and S_θθ N_a N_b / R² on the u_r–u_r block, energy ∫ W 2π R dA.
/// R is that of the Gauss points, never 0. Inverted (det F ≤ 0 or F_θθ ≤ 0 at a point): as
/// finite_strain_element.
FiniteStrainElement axisymmetric_finite_strain_element(const ElementValues& ev,
                                                       const material::FiniteStrainLaw& law,
                                                       const Eigen::VectorXd& u_e, bool tangent);

}  // namespace hpcontact::fem
