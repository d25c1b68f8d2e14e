// Point stresses of linear and finite-strain bodies.
#include "hpcontact/model/body_stress.hpp"

#include <cmath>

#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/axisymmetric_finite_strain.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/material/hyperelastic_hoop.hpp"
#include "hpcontact/material/mixed_rubber.hpp"

namespace hpcontact::model {

PointStress point_stress(const Body& body, int q, const fem::PointValues& pv, const Eigen::VectorXd& u_e,
                         double pressure) {
  const auto& m = body.material_of(q);
  PointStress ps;
  if (!body.finite_strain()) {
    ps.strain = fem::strain(pv, u_e);
    if (body.axisymmetric()) {
      // ε_θθ = u_r / r; on the axis (u_r = 0 there) its limit ∂u_r/∂r
      const double r = pv.x.x(), ur = pv.N.dot(u_e.head(pv.N.size()));
      const double hoop = r > 1e-12 * (1 + std::abs(pv.x.y())) ? ur / r : ps.strain(0);
      ps.stress = m.axisymmetric_stress(ps.strain, hoop, &ps.stress_zz);
      return ps;
    }
    ps.stress = m.D() * ps.strain;
    ps.stress_zz = m.sigma_zz(ps.stress);
    return ps;
  }
  ps.F = fem::deformation_gradient(pv, u_e);
  const Eigen::Matrix2d E = 0.5 * (ps.F.transpose() * ps.F - Eigen::Matrix2d::Identity());
  ps.strain = {E(0, 0), E(1, 1), 2 * E(0, 1)};
  if (body.mixed) {
    const double F33 = body.axisymmetric() ? fem::hoop_stretch(pv.N, pv.x, u_e, ps.F(0, 0)) : 1.0;
    const auto mixed = material::mixed_rubber_state(body.rubber, ps.F, F33, pressure);
    material::HoopHyperelasticState state;
    state.S = mixed.S;
    state.J = mixed.J;
    ps.stress = material::hoop_cauchy_stress(state, ps.F, F33, &ps.stress_zz);
    return ps;
  }
  if (body.axisymmetric()) {
    const double F_hoop = fem::hoop_stretch(pv.N, pv.x, u_e, ps.F(0, 0));
    const auto state = material::hoop_hyperelastic_state(body.finite_strain_law(q), ps.F, F_hoop);
    ps.stress = material::hoop_cauchy_stress(state, ps.F, F_hoop, &ps.stress_zz);
    return ps;
  }
  const auto state = material::hyperelastic_state(body.finite_strain_law(q), ps.F);
  ps.stress = material::cauchy_stress(state, ps.F, &ps.stress_zz);
  return ps;
}

}  // namespace hpcontact::model
