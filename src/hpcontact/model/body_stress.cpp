// Point stresses of linear and finite-strain bodies.
#include "hpcontact/model/body_stress.hpp"

#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/finite_strain.hpp"

namespace hpcontact::model {

PointStress point_stress(const Body& body, int q, const fem::PointValues& pv, const Eigen::VectorXd& u_e) {
  const auto& m = body.material_of(q);
  PointStress ps;
  if (!body.finite_strain()) {
    ps.strain = fem::strain(pv, u_e);
    ps.stress = m.D() * ps.strain;
    ps.stress_zz = m.sigma_zz(ps.stress);
    return ps;
  }
  ps.F = fem::deformation_gradient(pv, u_e);
  const Eigen::Matrix2d E = 0.5 * (ps.F.transpose() * ps.F - Eigen::Matrix2d::Identity());
  ps.strain = {E(0, 0), E(1, 1), 2 * E(0, 1)};
  const auto state = material::hyperelastic_state(m, body.law, ps.F);
  ps.stress = material::cauchy_stress(state, ps.F, &ps.stress_zz);
  return ps;
}

}  // namespace hpcontact::model
