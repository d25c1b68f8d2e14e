// Axisymmetric total Lagrangian element. The rows of B for mode a are the plane element's
// (F_i1 N_a,1, F_i2 N_a,2, F_i1 N_a,2 + F_i2 N_a,1) for component i, and a fourth, the hoop
// row F_θθ N_a / R on u_r only (δF_θθ = δu_r / R). Its geometric tangent: the plane
// δ_ik ∇N_a · S ∇N_b plus, from δ(F_θθ / R) N_a = N_a N_b / R² δu_r, S_θθ N_a N_b / R² on the
// u_r–u_r block. The weight of a point is w = JxW · 2π R.
#include "hpcontact/fem/axisymmetric_finite_strain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
#include "hpcontact/fem/point_blocks.hpp"
#include "hpcontact/material/hyperelastic_hoop.hpp"

namespace hpcontact::fem {

double hoop_stretch(const Eigen::VectorXd& N, const Vec2& X, const Eigen::VectorXd& u_e, double F_rr) {
  const double R = X.x();
  if (R <= 1e-12 * (1 + std::abs(X.y()))) return F_rr;
  return 1 + N.dot(u_e.head(N.size())) / R;
}

GaussKinematics gauss_kinematics(const ElementValues& ev, const Eigen::VectorXd& u_e, bool ring) {
  const int n = ev.n_modes(), nq = ev.n_points();
  GaussKinematics g{std::vector<Eigen::Matrix2d>(nq), Eigen::VectorXd::Ones(nq), Eigen::VectorXd::Zero(nq),
                    std::numeric_limits<double>::infinity(), -1};
  const Eigen::VectorXd u_r = ev.N.transpose() * u_e.head(n);
  for (int k = 0; k < nq; ++k) {
    g.F[k] = deformation_gradient(ev, k, u_e);
    if (ring) {
      g.inv_R(k) = 1 / ev.x[k].x();  // Gauss points are inside the element: R > 0
      g.F33(k) = 1 + u_r(k) * g.inv_R(k);
    }
    const double det = g.F[k].determinant();
    // J = det F_plane · F33; both factors must be positive (two negatives are a fold too)
    const double J = det > 0 && g.F33(k) > 0 ? det * g.F33(k) : std::min(det, g.F33(k));
    if (!(J > g.min_J)) {
      g.min_J = J;
      g.min_J_point = k;
    }
  }
  return g;
}

FiniteStrainElement axisymmetric_finite_strain_element(const ElementValues& ev,
                                                       const material::FiniteStrainLaw& law,
                                                       const Eigen::VectorXd& u_e, bool tangent) {
  const int n = ev.n_modes(), nq = ev.n_points();
  FiniteStrainElement el;
  const GaussKinematics kin = gauss_kinematics(ev, u_e, true);
  const auto& F = kin.F;
  const Eigen::VectorXd &F_hoop = kin.F33, &inv_R = kin.inv_R;
  el.min_J = kin.min_J;
  el.min_J_point = kin.min_J_point;
  if (el.inverted()) return el;

  el.f_int = Eigen::VectorXd::Zero(2 * n);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(4 * nq, 2 * n), CB;  // stacked B; ℂ w B
  Eigen::VectorXd wS11(nq), wS22(nq), wS12(nq), wShoop(nq);
  if (tangent) CB.resize(4 * nq, 2 * n);
  const OutOfPlane ring(0, true);
  for (int k = 0; k < nq; ++k) {
    const auto state = material::hoop_hyperelastic_state(law, F[k], F_hoop(k));
    const double w = ev.JxW(k) * ring.at(ev.x[k]);
    el.energy += w * state.W;
    const auto Nx = ev.dN_dx.col(k), Ny = ev.dN_dy.col(k);
    for (int i = 0; i < 2; ++i) {
      B.block(4 * k, i * n, 1, n) = F[k](i, 0) * Nx.transpose();
      B.block(4 * k + 1, i * n, 1, n) = F[k](i, 1) * Ny.transpose();
      B.block(4 * k + 2, i * n, 1, n) = (F[k](i, 0) * Ny + F[k](i, 1) * Nx).transpose();
    }
    B.block(4 * k + 3, 0, 1, n) = (F_hoop(k) * inv_R(k)) * ev.N.col(k).transpose();
    el.f_int.noalias() += B.middleRows(4 * k, 4).transpose() * (w * state.S);
    if (!tangent) continue;
    CB.middleRows(4 * k, 4).noalias() = (w * state.C) * B.middleRows(4 * k, 4);
    wS11(k) = w * state.S(0);
    wS22(k) = w * state.S(1);
    wS12(k) = w * state.S(2);
    wShoop(k) = w * state.S(3) * inv_R(k) * inv_R(k);
  }
  if (!tangent) return el;
  el.K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  for_point_blocks(nq, 32.0 * n * n, [&](int first, int count) {
    el.K.noalias() += B.middleRows(4 * first, 4 * count).transpose() *
                      CB.middleRows(4 * first, 4 * count);
  });
  add_geometric_stiffness(ev, wS11, wS22, wS12, el.K);
  for_point_blocks(nq, 2.0 * n * n, [&](int first, int count) {
    const auto N = ev.N.middleCols(first, count);
    el.K.topLeftCorner(n, n).noalias() +=
        N * wShoop.segment(first, count).asDiagonal() * N.transpose();
  });
  return el;
}

}  // namespace hpcontact::fem
