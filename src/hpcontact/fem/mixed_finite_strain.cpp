// Mixed u–p element. Per point, with the rows of B for mode a and component i the plane
// element's (F_i1 N_a,1, F_i2 N_a,2, F_i1 N_a,2 + F_i2 N_a,1) and a fourth, the out-of-plane row
// F33 N_a / R on u_r in axisymmetry (zero in plane strain, where F33 = 1 is held):
//   r_u = ∫ Bᵀ S dV,  S = S_iso + J p C⁻¹;   r_p = ∫ ψ (J − 1 − p/K) dV;
//   K_uu = ∫ Bᵀ ℂ B dV + geometric (δ_ik ∇N_a · S ∇N_b, and S33 N_a N_b / R² on u_r–u_r),
//   K_up = ∫ Bᵀ (J C⁻¹) ψᵀ dV  (δJ = J C⁻¹ : δE),   K_pp = −∫ ψ ψᵀ / K dV.
#include "hpcontact/fem/mixed_finite_strain.hpp"

#include <algorithm>
#include <limits>
#include <vector>

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/fem/axisymmetric_finite_strain.hpp"
#include "hpcontact/fem/point_blocks.hpp"
#include "hpcontact/material/mixed_rubber.hpp"

namespace hpcontact::fem {

int pressure_degree(const ElementSpace& space) {
  if (space.is_lagrange) return std::max(space.max_degree() - 1, 0);
  // One below the element's lowest degree, its edges' included: an element of degree 6 whose
  // edges a degree-2 neighbour holds at 2 (the minimum rule of hp's graded degrees) cannot
  // control a P5 pressure along them (the tangent turned singular, Newton's first step 1e15).
  const auto& h = space.hierarchic;
  int lowest = std::min(h.p_xi, h.p_eta);
  for (int e : h.edge_degree) lowest = std::min(lowest, e);
  return std::max(lowest - 1, 0);
}

int n_pressure_modes(int degree) { return (degree + 1) * (degree + 2) / 2; }

Eigen::VectorXd pressure_modes(int degree, double xi, double eta) {
  std::vector<double> Lx(degree + 1), Ly(degree + 1);
  basis::legendre(degree, xi, Lx.data(), nullptr);
  basis::legendre(degree, eta, Ly.data(), nullptr);
  Eigen::VectorXd psi(n_pressure_modes(degree));
  int k = 0;
  for (int i = 0; i <= degree; ++i)
    for (int j = 0; i + j <= degree; ++j) psi(k++) = Lx[i] * Ly[j];
  return psi;
}

Eigen::MatrixXd pressure_modes_at_gauss_points(int degree, int n_gauss) {
  const auto& rule = basis::gauss_legendre(n_gauss);
  Eigen::MatrixXd psi(n_pressure_modes(degree), n_gauss * n_gauss);
  for (int i = 0, k = 0; i < n_gauss; ++i)
    for (int j = 0; j < n_gauss; ++j, ++k) psi.col(k) = pressure_modes(degree, rule.points[i], rule.points[j]);
  return psi;
}

FiniteStrainElement mixed_finite_strain_element(const ElementValues& ev, const Eigen::MatrixXd& psi,
                                                const material::RubberConstants& constants,
                                                double inverse_bulk, const OutOfPlane& out_of_plane,
                                                const Eigen::VectorXd& u_e, const Eigen::VectorXd& p_e,
                                                bool tangent) {
  const int n = ev.n_modes(), nq = ev.n_points(), m = static_cast<int>(p_e.size());
  const bool ring = out_of_plane.axisymmetric;
  FiniteStrainElement el;
  const GaussKinematics kin = gauss_kinematics(ev, u_e, ring);
  const auto& F = kin.F;
  const Eigen::VectorXd &F33 = kin.F33, &inv_R = kin.inv_R;
  el.min_J = kin.min_J;
  el.min_J_point = kin.min_J_point;
  if (el.inverted()) return el;

  el.f_int = Eigen::VectorXd::Zero(2 * n + m);
  const Eigen::VectorXd p_points = psi.transpose() * p_e;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(4 * nq, 2 * n), CB, dJ_psi;  // stacked B; ℂ w B; w dJ ψᵀ
  Eigen::VectorXd wS11(nq), wS22(nq), wS12(nq), wS33(nq), w_inv_K(nq);
  if (tangent) {
    CB.resize(4 * nq, 2 * n);
    dJ_psi.resize(4 * nq, m);
  }
  for (int k = 0; k < nq; ++k) {
    const auto s = material::mixed_rubber_state(constants, F[k], F33(k), p_points(k));
    const double w = ev.JxW(k) * out_of_plane.at(ev.x[k]), p = p_points(k);
    el.energy += w * (s.W_iso + p * (s.J - 1) - 0.5 * inverse_bulk * p * p);
    const auto Nx = ev.dN_dx.col(k), Ny = ev.dN_dy.col(k);
    for (int i = 0; i < 2; ++i) {
      B.block(4 * k, i * n, 1, n) = F[k](i, 0) * Nx.transpose();
      B.block(4 * k + 1, i * n, 1, n) = F[k](i, 1) * Ny.transpose();
      B.block(4 * k + 2, i * n, 1, n) = (F[k](i, 0) * Ny + F[k](i, 1) * Nx).transpose();
    }
    if (ring) B.block(4 * k + 3, 0, 1, n) = (F33(k) * inv_R(k)) * ev.N.col(k).transpose();
    el.f_int.head(2 * n).noalias() += B.middleRows(4 * k, 4).transpose() * (w * s.S);
    el.f_int.tail(m) += (w * (s.J - 1 - inverse_bulk * p)) * psi.col(k);
    if (!tangent) continue;
    CB.middleRows(4 * k, 4).noalias() = (w * s.C) * B.middleRows(4 * k, 4);
    dJ_psi.middleRows(4 * k, 4).noalias() = (w * s.dJ) * psi.col(k).transpose();
    wS11(k) = w * s.S(0);
    wS22(k) = w * s.S(1);
    wS12(k) = w * s.S(2);
    wS33(k) = w * s.S(3) * inv_R(k) * inv_R(k);
    w_inv_K(k) = w * inverse_bulk;
  }
  if (!tangent) return el;
  el.K = Eigen::MatrixXd::Zero(2 * n + m, 2 * n + m);
  auto Kuu = el.K.topLeftCorner(2 * n, 2 * n);
  for_point_blocks(nq, 32.0 * n * n, [&](int first, int count) {
    Kuu.noalias() += B.middleRows(4 * first, 4 * count).transpose() * CB.middleRows(4 * first, 4 * count);
  });
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  add_geometric_stiffness(ev, wS11, wS22, wS12, G);
  Kuu += G;
  if (ring) Kuu.topLeftCorner(n, n).noalias() += ev.N * wS33.asDiagonal() * ev.N.transpose();
  const Eigen::MatrixXd Kup = B.transpose() * dJ_psi;
  el.K.topRightCorner(2 * n, m) = Kup;
  el.K.bottomLeftCorner(m, 2 * n) = Kup.transpose();
  el.K.bottomRightCorner(m, m).noalias() = -psi * w_inv_K.asDiagonal() * psi.transpose();
  return el;
}

}  // namespace hpcontact::fem
