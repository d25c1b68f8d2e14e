// Axisymmetric total Lagrangian element. A mode's u_r moves F_rr, F_rz and the hoop stretch
// F_θθ (δF_θθ = N_a δu_r / R), its u_z F_zr and F_zz: the force and the tangent are the plane
// element's ∫ ∂N_a ⋅ P and ∫ ∂N_a ⋅ 𝔸 ⋅ ∂N_b on these five slots (fem/gradient_tangent.hpp),
// N_a / R the derivative along the hoop slot. As B: the plane rows (F_i1 N_a,1, F_i2 N_a,2,
// F_i1 N_a,2 + F_i2 N_a,1) and a hoop row F_θθ N_a / R on u_r, with the geometric part
// δ_ik ∇N_a · S ∇N_b plus S_θθ N_a N_b / R² on u_r–u_r. The weight of a point is w = JxW · 2π R.
#include "hpcontact/fem/axisymmetric_finite_strain.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/fem/gradient_tangent.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
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

  // D0: u_r's slot derivatives (N_,r, N_,z, N / R) point after point, D1: u_z's (N_,r, N_,z)
  constexpr int kSlots = static_cast<int>(kAxisymmetricSlots.size());
  Eigen::MatrixXd D0(n, 3 * nq), D1(n, 2 * nq), A;
  Eigen::VectorXd p0(3 * nq), p1(2 * nq);
  if (tangent) A.resize(kSlots, kSlots * nq);
  const OutOfPlane ring(0, true);
  for (int k = 0; k < nq; ++k) {
    const auto state = material::hoop_hyperelastic_state(law, F[k], F_hoop(k));
    const double w = ev.JxW(k) * ring.at(ev.x[k]);
    el.energy += w * state.W;
    D0.col(3 * k) = D1.col(2 * k) = ev.dN_dx.col(k);
    D0.col(3 * k + 1) = D1.col(2 * k + 1) = ev.dN_dy.col(k);
    D0.col(3 * k + 2) = inv_R(k) * ev.N.col(k);
    const Eigen::Matrix3d F3 = plane_tensor(F[k], F_hoop(k));
    const Eigen::Matrix3d S3 = plane_tensor(Eigen::Vector3d(state.S.head<3>()), state.S(3));
    const auto P = first_piola(kAxisymmetricSlots, F3, S3, w);
    p0.segment(3 * k, 3) = P.head<3>();
    p1.segment(2 * k, 2) = P.tail<2>();
    if (tangent) A.middleCols(kSlots * k, kSlots) = first_elasticity(kAxisymmetricSlots, F3, S3, state.C, w);
  }
  el.f_int.resize(2 * n);
  el.f_int.head(n).noalias() = D0 * p0;
  el.f_int.tail(n).noalias() = D1 * p1;
  if (tangent) el.K = gradient_tangent(D0, D1, 3, 2, A);
  return el;
}

}  // namespace hpcontact::fem
