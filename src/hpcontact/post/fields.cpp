// Field evaluation and energy integrals.
#include "hpcontact/post/fields.hpp"

#include <cmath>

#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/element_values.hpp"

namespace hpcontact::post {

Eigen::VectorXd element_coefficients(const model::Body& body, int q, const Eigen::VectorXd& u) {
  const int n = 2 * body.dofs.element(q).n_modes();
  Eigen::VectorXd ue(n);
  for (int a = 0; a < n; ++a) ue(a) = u(body.global_dof(q, a));
  return ue;
}

double von_mises(double sxx, double syy, double szz, double sxy) {
  return std::sqrt(0.5 * ((sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) +
                          (szz - sxx) * (szz - sxx)) +
                   3 * sxy * sxy);
}

PointResult evaluate(const model::Body& body, int q, double xi, double eta, const Eigen::VectorXd& u) {
  const auto pv = fem::point_values(body.dofs.element(q), body.maps[q], xi, eta);
  const Eigen::VectorXd ue = element_coefficients(body, q, u);
  const int n = static_cast<int>(pv.N.size());
  const auto ux = ue.head(n), uy = ue.tail(n);
  PointResult r;
  r.x = pv.x;
  r.u = Vec2(ux.dot(pv.N), uy.dot(pv.N));
  r.strain = Eigen::Vector3d(ux.dot(pv.dN_dx), uy.dot(pv.dN_dy), ux.dot(pv.dN_dy) + uy.dot(pv.dN_dx));
  r.stress = body.material.D() * r.strain;
  r.stress_zz = body.material.sigma_zz(r.stress);
  r.von_mises = von_mises(r.stress(0), r.stress(1), r.stress_zz, r.stress(2));
  const double c = 0.5 * (r.stress(0) + r.stress(1));
  const double R = std::hypot(0.5 * (r.stress(0) - r.stress(1)), r.stress(2));
  r.principal_1 = c + R;
  r.principal_2 = c - R;
  return r;
}

double strain_energy(const model::Discretization& d, const Eigen::VectorXd& u) {
  double U = 0;
  for (const auto& body : d.bodies) {
    const auto D = body.material.D();
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const auto ev = fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q],
                                          body.mesh, q);
      const Eigen::Matrix3Xd eps = fem::strains(ev, element_coefficients(body, q, u));
      for (int k = 0; k < ev.n_points(); ++k)
        U += 0.5 * body.thickness * ev.JxW(k) * eps.col(k).dot(D * eps.col(k));
    }
  }
  return U;
}

double energy_error_squared(const model::Discretization& d, const Eigen::VectorXd& u,
                            const StrainField& exact, int extra_points) {
  double E2 = 0;
  for (const auto& body : d.bodies) {
    const auto D = body.material.D();
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const auto ev = fem::element_values(body.dofs.element(q), body.maps[q],
                                          body.n_gauss[q] + extra_points, body.mesh, q);
      const Eigen::Matrix3Xd eps = fem::strains(ev, element_coefficients(body, q, u));
      for (int k = 0; k < ev.n_points(); ++k) {
        const Eigen::Vector3d e = exact(ev.x[k]) - eps.col(k);
        E2 += 0.5 * body.thickness * ev.JxW(k) * e.dot(D * e);
      }
    }
  }
  return E2;
}

}  // namespace hpcontact::post
