// Total Lagrangian element. The internal force is f_ai = ∫ N_a,J P_iJ and the tangent
// ∫ N_a,J 𝔸_iJkL N_b,L with P = F S and 𝔸 = ∂P/∂F = δ_ik S_JL + F_iI ℂ_IJKL F_kK, which is
// Bᵀ ℂ B (material, B the rows (F_i1 N_a,1, F_i2 N_a,2, F_i1 N_a,2 + F_i2 N_a,1) of δE) plus
// δ_ik ∇N_a · S ∇N_b (geometric) in one: fem/gradient_tangent.hpp forms it in a few matrix
// products. add_geometric_stiffness is the geometric part alone, for the mixed element.
#include "hpcontact/fem/finite_strain.hpp"

#include <limits>
#include <vector>

#include "hpcontact/fem/gradient_tangent.hpp"
#include "hpcontact/fem/point_blocks.hpp"

namespace hpcontact::fem {

Eigen::Matrix2d deformation_gradient(const ElementValues& ev, int k, const Eigen::VectorXd& u_e) {
  const int n = ev.n_modes();
  const auto ux = u_e.head(n), uy = u_e.segment(n, n);
  Eigen::Matrix2d F;
  F << 1 + ux.dot(ev.dN_dx.col(k)), ux.dot(ev.dN_dy.col(k)), uy.dot(ev.dN_dx.col(k)),
      1 + uy.dot(ev.dN_dy.col(k));
  return F;
}

Eigen::Matrix2d deformation_gradient(const PointValues& pv, const Eigen::VectorXd& u_e) {
  const int n = static_cast<int>(pv.N.size());
  const auto ux = u_e.head(n), uy = u_e.segment(n, n);
  Eigen::Matrix2d F;
  F << 1 + ux.dot(pv.dN_dx), ux.dot(pv.dN_dy), uy.dot(pv.dN_dx), 1 + uy.dot(pv.dN_dy);
  return F;
}

void add_geometric_stiffness(const ElementValues& ev, const Eigen::VectorXd& wS11,
                             const Eigen::VectorXd& wS22, const Eigen::VectorXd& wS12,
                             Eigen::MatrixXd& K) {
  const int n = ev.n_modes();
  Eigen::MatrixXd G = Eigen::MatrixXd::Zero(n, n), XY = G;
  for_point_blocks(ev.n_points(), 6.0 * n * n, [&](int first, int count) {
    const auto nx = ev.dN_dx.middleCols(first, count), ny = ev.dN_dy.middleCols(first, count);
    G.noalias() += nx * wS11.segment(first, count).asDiagonal() * nx.transpose();
    G.noalias() += ny * wS22.segment(first, count).asDiagonal() * ny.transpose();
    XY.noalias() += nx * wS12.segment(first, count).asDiagonal() * ny.transpose();
  });
  G += XY + XY.transpose();
  K.topLeftCorner(n, n) += G;
  K.bottomRightCorner(n, n) += G;
}

FiniteStrainElement finite_strain_element(const ElementValues& ev, const material::FiniteStrainLaw& law,
                                          double thickness, const Eigen::VectorXd& u_e, bool tangent) {
  const int n = ev.n_modes(), nq = ev.n_points();
  FiniteStrainElement el;
  std::vector<Eigen::Matrix2d> F(nq);
  el.min_J = std::numeric_limits<double>::infinity();
  for (int k = 0; k < nq; ++k) {
    F[k] = deformation_gradient(ev, k, u_e);
    if (const double J = F[k].determinant(); !(J > el.min_J) ) {
      el.min_J = J;
      el.min_J_point = k;
    }
  }
  if (el.inverted()) return el;

  // D: the modes' gradients point after point; P and 𝔸 on the slots F_11, F_12, F_21, F_22
  constexpr int kSlots = static_cast<int>(kPlaneSlots.size());
  Eigen::MatrixXd D(n, 2 * nq), A;
  Eigen::VectorXd p0(2 * nq), p1(2 * nq);
  if (tangent) A.resize(kSlots, kSlots * nq);
  for (int k = 0; k < nq; ++k) {
    const auto state = material::hyperelastic_state(law, F[k]);
    const double w = ev.JxW(k) * thickness;
    el.energy += w * state.W;
    D.col(2 * k) = ev.dN_dx.col(k);
    D.col(2 * k + 1) = ev.dN_dy.col(k);
    const Eigen::Matrix3d F3 = plane_tensor(F[k], 1.0);
    const Eigen::Matrix3d S3 = plane_tensor(state.S, state.S33);
    const auto P = first_piola(kPlaneSlots, F3, S3, w);
    p0.segment(2 * k, 2) = P.head<2>();
    p1.segment(2 * k, 2) = P.tail<2>();
    if (tangent) A.middleCols(kSlots * k, kSlots) = first_elasticity(kPlaneSlots, F3, S3, state.C, w);
  }
  el.f_int.resize(2 * n);
  el.f_int.head(n).noalias() = D * p0;
  el.f_int.tail(n).noalias() = D * p1;
  if (tangent) el.K = gradient_tangent(D, D, 2, 2, A);
  return el;
}

}  // namespace hpcontact::fem
