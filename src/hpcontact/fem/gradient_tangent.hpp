// The tangent of a total Lagrangian element written with the first elasticity tensor
// 𝔸 = ∂P/∂F (P = F S, the first Piola–Kirchhoff stress): K_(a i),(b k) = ∫ ∂N_a ⋅ 𝔸_ik ⋅ ∂N_b,
// one matrix product per block of components instead of Bᵀ ℂ B plus a geometric part.
#pragma once

#include <array>
#include <utility>

#include <Eigen/Dense>

namespace hpcontact::fem {

/// A slot is one component F_aA of the deformation gradient that a mode's displacement moves:
/// (spatial index a, material index A), 0 and 1 in the plane, (2, 2) the hoop stretch F_θθ of an
/// axisymmetric body (moved by u_r alone: δF_θθ = N δu_r / R).
using Slot = std::pair<int, int>;

/// The slots of a plane body, component by component: u_x moves F_11, F_12; u_y F_21, F_22.
inline constexpr std::array<Slot, 4> kPlaneSlots{{{0, 0}, {0, 1}, {1, 0}, {1, 1}}};
/// The slots of an axisymmetric body (x = r): u_r moves F_rr, F_rz and F_θθ; u_z F_zr, F_zz.
inline constexpr std::array<Slot, 5> kAxisymmetricSlots{{{0, 0}, {0, 1}, {2, 2}, {1, 0}, {1, 1}}};

/// The 3 × 3 tensor of an in-plane one and its out-of-plane (θθ) component.
inline Eigen::Matrix3d plane_tensor(const Eigen::Matrix2d& T, double T33) {
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  M.topLeftCorner<2, 2>() = T;
  M(2, 2) = T33;
  return M;
}
/// The same of a symmetric one in Voigt order (T11, T22, T12).
inline Eigen::Matrix3d plane_tensor(const Eigen::Vector3d& voigt, double T33) {
  Eigen::Matrix2d T;
  T << voigt(0), voigt(2), voigt(2), voigt(1);
  return plane_tensor(T, T33);
}

/// 𝔸_st = ∂P_aA/∂F_bB = δ_ab S_AB + Σ_IK F_aI ℂ_IAKB F_bK between the slots s = (a, A) and
/// t = (b, B), times w. F and S are 3 × 3 (F_θθ, S_θθ at (2, 2); zero where the plane and the
/// third direction meet); ℂ is given in Voigt order (E11, E22, 2 E12) and, if 4 × 4, E_θθ last.
/// Symmetric (ℂ's major symmetry).
template <std::size_t Slots>
Eigen::Matrix<double, Slots, Slots> first_elasticity(const std::array<Slot, Slots>& slots,
                                                     const Eigen::Matrix3d& F, const Eigen::Matrix3d& S,
                                                     const Eigen::Ref<const Eigen::MatrixXd>& C, double w);

/// P = F S on the slots, times w.
template <std::size_t Slots>
Eigen::Matrix<double, Slots, 1> first_piola(const std::array<Slot, Slots>& slots, const Eigen::Matrix3d& F,
                                            const Eigen::Matrix3d& S, double w);

/// The element tangent of two displacement components (component-blocked, 2n × 2n):
///   K_ik = Σ_q D_i,q 𝔸_q,ik D_k,qᵀ,
/// where D_i (n × s_i·n_q) holds, point after point, the derivative of every mode along each of
/// component i's s_i slots (∂N/∂X_A for an in-plane slot, N/R for the hoop), and A (s × s·n_q,
/// s = s_0 + s_1) the points' 𝔸 side by side, component 0's slots first. The diagonal blocks are
/// formed in their lower triangle and mirrored, K_01 = K_10ᵀ: K is exactly symmetric.
Eigen::MatrixXd gradient_tangent(const Eigen::MatrixXd& D0, const Eigen::MatrixXd& D1, int s0, int s1,
                                 const Eigen::MatrixXd& A);

}  // namespace hpcontact::fem
