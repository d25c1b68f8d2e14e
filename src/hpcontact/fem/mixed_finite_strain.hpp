// Mixed displacement–pressure element of the rubber laws at finite strain (total Lagrangian),
// plane strain and axisymmetric: the displacement in the element's p-version space of degree p,
// the pressure discontinuous, of total degree p − 1 in the reference coordinates (P_{p−1}), in
// the perturbed-Lagrangian form
//   Π_e(u, p) = ∫ W_iso(C̄) + p (J − 1) − p² / (2K) dV,
// dV = t dA or 2π R dA. 1/K = 0 is the incompressible limit (J = 1 weakly, p its multiplier); a
// finite K gives p = K (J − 1) in the weak sense, the compressible law at the continuum level.
// docs/theory.md §12.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
#include "hpcontact/material/rubber.hpp"

namespace hpcontact::fem {

/// The pressure's total degree on an element space: its largest degree − 1 (0 for Q4).
int pressure_degree(const ElementSpace& space);
/// Pressure modes of total degree m: (m + 1)(m + 2) / 2.
int n_pressure_modes(int degree);
/// The pressure modes L_i(ξ) L_j(η) (Legendre), i + j ≤ degree, i outer, j inner, at (xi, eta) of
/// the reference square [-1, 1]²: mode 0 is the constant 1.
Eigen::VectorXd pressure_modes(int degree, double xi, double eta);
/// The same at the Gauss points of element_values with n_gauss points per direction, in its
/// order: n_pressure_modes × n_gauss².
Eigen::MatrixXd pressure_modes_at_gauss_points(int degree, int n_gauss);

/// The element at displacement coefficients u_e (component-blocked, 2 n) and pressure
/// coefficients p_e (m): f_int = ∂Π_e/∂(u_e, p_e) (size 2 n + m: the displacement rows
/// ∫ Bᵀ (S_iso + J p C⁻¹) dV, then the pressure rows ∫ ψ (J − 1 − p/K) dV), K its derivative
/// (symmetric, indefinite; its pressure block −∫ ψ ψᵀ / K dV, zero when inverse_bulk = 0),
/// energy = Π_e. psi: the pressure modes at ev's points (pressure_modes_at_gauss_points).
/// Axisymmetric (out_of_plane.axisymmetric, x = R): J includes the hoop stretch 1 + u_r / R.
/// Inverted (det F ≤ 0 or a hoop stretch ≤ 0 at a point): as finite_strain_element.
FiniteStrainElement mixed_finite_strain_element(const ElementValues& ev, const Eigen::MatrixXd& psi,
                                                const material::RubberConstants& constants,
                                                double inverse_bulk, const OutOfPlane& out_of_plane,
                                                const Eigen::VectorXd& u_e, const Eigen::VectorXd& p_e,
                                                bool tangent);

}  // namespace hpcontact::fem
