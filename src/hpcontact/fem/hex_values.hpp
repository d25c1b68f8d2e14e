// Shape values and physical gradients of one hexahedron at its quadrature points.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/mesh/hex_map.hpp"

namespace hpcontact::fem {

/// Values at the n_xi × n_eta × n_zeta Gauss–Legendre points of the reference cube, point index
/// q = (i n_eta + j) n_zeta + k for the i-th xi, j-th eta, k-th zeta point. Matrices are
/// n_modes × n_points (a column per point), rows in the mode order of basis/hex_modes.hpp.
struct HexValues {
  Eigen::MatrixXd N, dN_dx, dN_dy, dN_dz;
  Eigen::VectorXd JxW;        ///< weight × det J (volume element)
  std::vector<mesh::Vec3> x;  ///< physical points
  int n_modes() const { return static_cast<int>(N.rows()); }
  int n_points() const { return static_cast<int>(N.cols()); }
  /// dN/dx_k, k = 0, 1, 2.
  const Eigen::MatrixXd& dN(int k) const { return k == 0 ? dN_dx : k == 1 ? dN_dy : dN_dz; }
};

/// Gauss points per reference direction for the stiffness of degree p_d along d on a map of
/// degree q (1 trilinear, 2 triquadratic): n_d = p_d + q.
///  - n = p + 1 integrates an affine element's stiffness (degree 2p per direction) exactly.
///  - The patch test needs less: for a field in the space with constant stress σ, the residual of
///    mode a is σ : ∫ adj(J)ᵀ ∇_ξ N_a dξ, a polynomial of degree p + 2q − 1 per direction
///    (adj(J)'s rows are cross products of columns of degree (q − 1, q, q) and permutations), so
///    Gauss with n ≥ p/2 + q points integrates it exactly and the patch test passes; n = p + q
///    keeps that margin for q = 2 and adds a point for the curvature of the map.
///  - A non-affine map's stiffness is rational in xi: no rule is exact, this one is p-consistent.
std::array<int, 3> hex_gauss_points(const basis::HierarchicHex& element, const mesh::HexMap& map);

/// Evaluates the modes and their physical gradients at the Gauss grid of n_points per direction.
/// Throws MeshError (naming nothing but the point; check_hex_jacobian names the element) where
/// det J <= 0.
HexValues hex_values(const basis::HierarchicHex& element, const mesh::HexMap& map,
                     const std::array<int, 3>& n_points);

}  // namespace hpcontact::fem
