// Hexahedron stiffness and body force by sum factorisation: the Gauss grid and the modes are
// tensor products, so the sums over points are taken one direction at a time, O(p⁷) instead of
// the O(p⁹) of the per-mode-pair products (hex_elasticity.hpp, the reference kernel).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/mesh/hex_map.hpp"

namespace hpcontact::fem {

/// A map's geometry at the n_xi × n_eta × n_zeta Gauss–Legendre grid, point index
/// q = (i n_eta + j) n_zeta + k as in HexValues: what the factored kernels need of it.
struct HexGridGeometry {
  std::array<int, 3> n_points{};
  Eigen::VectorXd JxW;            ///< weight × det J
  std::vector<mesh::Mat3> J_inv;  ///< J⁻¹ (rows: reference directions, columns: x, y, z)
  int size() const { return static_cast<int>(JxW.size()); }
};

/// Evaluates the map's Jacobian at the grid. Throws MeshError (naming the point) where
/// det J <= 0, as hex_values does.
HexGridGeometry hex_grid_geometry(const mesh::HexMap& map, const std::array<int, 3>& n_points);

/// K_e of hex_stiffness (the same 3n × 3n matrix, component-blocked, exactly symmetric) without
/// evaluating the modes at the points. With ∂N/∂x_k = Σ_r (J⁻¹)_rk ∂N/∂ξ_r,
///   K_(i a),(j b) = Σ_{r,s} Σ_q A^ij_rs(q) ∂_r N_a(q) ∂_s N_b(q),
///   A^ij_rs = w det J [λ (J⁻¹)_ri (J⁻¹)_sj + μ (J⁻¹)_rj (J⁻¹)_si + μ δ_ij (J⁻¹ J⁻ᵀ)_rs],
/// and every mode is ± a(ξ) b(η) c(ζ), so ∂_r N_a ∂_s N_b factors into three 1D pair tables
/// (value·value, derivative·value, value·derivative or derivative·derivative along each
/// direction). The sum over ζ points, then η, then ξ gives the matrix over all (p+1)³ tensor
/// products, whose rows and columns of the element's modes are kept (with their signs):
/// O(p⁷) operations and O(p⁶) memory for the tensor space, and as many for a trunk space, whose
/// modes are a subset.
Eigen::MatrixXd hex_stiffness_factored(const basis::HierarchicHex& element,
                                       const HexGridGeometry& geometry,
                                       const material::LinearElastic& material);

/// f_e of hex_body_force (3n, component-blocked) for a constant body force b, factored alike.
Eigen::VectorXd hex_body_force_factored(const basis::HierarchicHex& element,
                                        const HexGridGeometry& geometry, const mesh::Vec3& b);

}  // namespace hpcontact::fem
