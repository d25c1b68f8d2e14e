// Element stiffness, body force and strains of 3D isotropic linear elasticity on a hexahedron.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/fem/hex_values.hpp"
#include "hpcontact/material/linear_elastic.hpp"

namespace hpcontact::fem {

/// Local dof order of hexahedron matrices and vectors, as in the plane (elasticity.hpp):
/// component-blocked, local dof = component * n_modes + local mode (component 0 = x, 1 = y,
/// 2 = z); HexDofMap's global dof of it is 3 * modes[local mode] + component.

/// K_e = ∫ Bᵀ D B dV (3n × 3n, symmetric) of the isotropic law (λ, μ of `material`; its
/// `plane` is ignored), formed without B: with M_kl = Σ_q w_q det J_q ∇_k N ∇_l Nᵀ (n × n, the
/// physical derivatives along k and l of every pair of modes),
///   K_(i a),(j b) = λ M_ij(a, b) + μ M_ji(a, b) + μ δ_ij Σ_k M_kk(a, b)
/// (from σ = λ tr(ε) I + 2μ ε: λ div v div u + μ ∇v : ∇u + μ ∇v : ∇uᵀ). The six M_kl, k <= l,
/// are dense products of n × n_points by n_points × n matrices.
Eigen::MatrixXd hex_stiffness(const HexValues& values, const material::LinearElastic& material);

/// f_e = ∫ N b dV (3n, component-blocked) for a constant body force b (force per volume).
Eigen::VectorXd hex_body_force(const HexValues& values, const mesh::Vec3& b);

/// Strains (Voigt xx, yy, zz, gamma_yz, gamma_xz, gamma_xy) at every quadrature point for local
/// coefficients u_e (component-blocked); 6 × n_points.
Eigen::Matrix<double, 6, Eigen::Dynamic> hex_strains(const HexValues& values,
                                                     const Eigen::VectorXd& u_e);

}  // namespace hpcontact::fem
