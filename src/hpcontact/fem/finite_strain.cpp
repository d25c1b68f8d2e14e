// Total Lagrangian element. With δE = B δu, the rows of B for mode a and component i are
// (F_i1 N_a,1, F_i2 N_a,2, F_i1 N_a,2 + F_i2 N_a,1); the tangent is Bᵀ ℂ B (material) plus
// δ_ik ∇N_a · S ∇N_b (geometric). B of all points is stacked so that a few matrix products (one
// per block of points, fem/point_blocks.hpp) form Bᵀ ℂ B.
#include "hpcontact/fem/finite_strain.hpp"

#include <limits>
#include <vector>

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

  el.f_int = Eigen::VectorXd::Zero(2 * n);
  Eigen::MatrixXd B(3 * nq, 2 * n), CB;  // stacked B of all points; ℂ w B
  Eigen::VectorXd wS11(nq), wS22(nq), wS12(nq);
  if (tangent) CB.resize(3 * nq, 2 * n);
  for (int k = 0; k < nq; ++k) {
    const auto state = material::hyperelastic_state(law, F[k]);
    const double w = ev.JxW(k) * thickness;
    el.energy += w * state.W;
    const auto Nx = ev.dN_dx.col(k), Ny = ev.dN_dy.col(k);
    for (int i = 0; i < 2; ++i) {
      B.block(3 * k, i * n, 1, n) = F[k](i, 0) * Nx.transpose();
      B.block(3 * k + 1, i * n, 1, n) = F[k](i, 1) * Ny.transpose();
      B.block(3 * k + 2, i * n, 1, n) = (F[k](i, 0) * Ny + F[k](i, 1) * Nx).transpose();
    }
    el.f_int.noalias() += B.middleRows(3 * k, 3).transpose() * (w * state.S);
    if (!tangent) continue;
    CB.middleRows(3 * k, 3).noalias() = (w * state.C) * B.middleRows(3 * k, 3);
    wS11(k) = w * state.S(0);
    wS22(k) = w * state.S(1);
    wS12(k) = w * state.S(2);
  }
  if (!tangent) return el;
  el.K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for_point_blocks(nq, 24.0 * n * n, [&](int first, int count) {
    el.K.noalias() += B.middleRows(3 * first, 3 * count).transpose() *
                      CB.middleRows(3 * first, 3 * count);
  });
  add_geometric_stiffness(ev, wS11, wS22, wS12, el.K);
  return el;
}

}  // namespace hpcontact::fem
