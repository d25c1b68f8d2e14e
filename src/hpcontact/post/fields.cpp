// Field evaluation and energy integrals.
#include "hpcontact/post/fields.hpp"

#include <cmath>

#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/elasticity.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/body_stress.hpp"
#include "hpcontact/model/finite_strain_body.hpp"

namespace hpcontact::post {

double von_mises(double sxx, double syy, double szz, double sxy) {
  return von_mises(std::array<double, 6>{sxx, syy, szz, 0, 0, sxy});
}

double von_mises(const std::array<double, 6>& s) {
  return std::sqrt(0.5 * ((s[0] - s[1]) * (s[0] - s[1]) + (s[1] - s[2]) * (s[1] - s[2]) +
                          (s[2] - s[0]) * (s[2] - s[0])) +
                   3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

std::array<double, 2> principal_stresses(double sxx, double syy, double sxy) {
  const double c = 0.5 * (sxx + syy), R = std::hypot(0.5 * (sxx - syy), sxy);
  return {c + R, c - R};
}

PointResult evaluate(const model::Body& body, int q, double xi, double eta, const Eigen::VectorXd& u) {
  const auto pv = fem::point_values(body.dofs.element(q), body.maps[q], xi, eta);
  const Eigen::VectorXd ue = body.element_coefficients(q, u);
  const int n = static_cast<int>(pv.N.size());
  PointResult r;
  r.x = pv.x;
  r.u = Vec2(ue.head(n).dot(pv.N), ue.segment(n, n).dot(pv.N));
  const auto pressure = [&](double x, double y) { return body.mixed ? model::mixed_pressure(body, q, x, y, u) : 0.0; };
  double p = pressure(xi, eta);
  auto ps = model::point_stress(body, q, pv, ue, p);
  // det J = 0 at a corner of 180° (two edges on one circle, node 3 of the Hertz 2×2 mesh): there
  // the strain is round-off divided by round-off (von Mises 2e7 for a peak of 1.4e4), and next
  // to it the discrete field's gradient grows like 1/distance (the map's singularity), so it is
  // taken inside the element, 0.02 of the reference square towards its centre (a tenth of the
  // default VTU sample spacing).
  if (!(body.maps[q].regularity(xi, eta) > 1e-6) || !ps.strain.allFinite() ||
      !ps.stress.allFinite()) {
    const auto inner = fem::point_values(body.dofs.element(q), body.maps[q], xi * (1 - 2e-2),
                                         eta * (1 - 2e-2));
    p = pressure(xi * (1 - 2e-2), eta * (1 - 2e-2));
    ps = model::point_stress(body, q, inner, ue, p);
  }
  r.strain = ps.strain;
  if (body.axisymmetric()) {
    const double radius = pv.x.x(), on_axis = 1e-12 * (1 + body.mesh.size());
    const double stretch = radius > on_axis ? r.u.x() / radius : r.strain(0);
    r.strain_hoop = body.finite_strain() && radius > on_axis ? stretch + 0.5 * stretch * stretch : stretch;
  }
  r.stress = ps.stress;
  r.stress_zz = ps.stress_zz;
  r.pressure = p;  // where the stress is taken
  r.von_mises = von_mises(r.stress(0), r.stress(1), r.stress_zz, r.stress(2));
  const auto principal = principal_stresses(r.stress(0), r.stress(1), r.stress(2));
  r.principal_1 = principal[0];
  r.principal_2 = principal[1];
  return r;
}

double strain_energy(const model::Discretization& d, const Eigen::VectorXd& u) {
  double U = 0;
  for (const auto& body : d.bodies) {
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const auto ev = fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q],
                                          body.mesh, q);
      if (body.finite_strain()) {
        U += model::finite_strain_element(body, q, ev, u, false).energy;
        continue;
      }
      U += element_strain_energy(body, q, ev, body.element_coefficients(q, u));
    }
  }
  return U;
}

double energy_error_squared(const model::Discretization& d, const Eigen::VectorXd& u,
                            const ExactStrain& exact, int extra_points) {
  double E2 = 0;
  for (const auto& body : d.bodies) {
    HPC_REQUIRE(!body.axisymmetric() || exact.hoop, InputError, "body '", body.name,
                "': the energy error of an axisymmetric body needs the exact hoop strain");
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const auto& m = body.material_of(q);
      const auto ev = fem::element_values(body.dofs.element(q), body.maps[q],
                                          body.n_gauss[q] + extra_points, body.mesh, q);
      const Eigen::VectorXd ue = body.element_coefficients(q, u);
      const Eigen::Matrix3Xd eps = fem::strains(ev, ue);
      if (body.axisymmetric()) {
        const Eigen::VectorXd ur = ev.N.transpose() * ue.head(ev.n_modes());
        for (int k = 0; k < ev.n_points(); ++k) {
          const Eigen::Vector3d e = exact.in_plane(ev.x[k]) - eps.col(k);
          const double e_hoop = exact.hoop(ev.x[k]) - ur(k) / ev.x[k].x();
          double s_hoop = 0;
          const Eigen::Vector3d s = m.axisymmetric_stress(e, e_hoop, &s_hoop);
          E2 += 0.5 * body.out_of_plane().at(ev.x[k]) * ev.JxW(k) * (e.dot(s) + s_hoop * e_hoop);
        }
        continue;
      }
      const auto D = m.D();
      for (int k = 0; k < ev.n_points(); ++k) {
        const Eigen::Vector3d e = exact.in_plane(ev.x[k]) - eps.col(k);
        E2 += 0.5 * body.thickness * ev.JxW(k) * e.dot(D * e);
      }
    }
  }
  return E2;
}

double element_strain_energy(const model::Body& body, int q, const fem::ElementValues& ev,
                             const Eigen::VectorXd& ue) {
  const auto& m = body.material_of(q);
  const Eigen::Matrix3Xd eps = fem::strains(ev, ue);
  double U = 0;
  if (body.axisymmetric()) {
    // the hoop strain u_r / r, over 2π r dA
    const Eigen::VectorXd ur = ev.N.transpose() * ue.head(ev.n_modes());
    for (int k = 0; k < ev.n_points(); ++k) {
      const double hoop = ur(k) / ev.x[k].x();
      double s_hoop = 0;
      const Eigen::Vector3d s = m.axisymmetric_stress(eps.col(k), hoop, &s_hoop);
      U += 0.5 * body.out_of_plane().at(ev.x[k]) * ev.JxW(k) * (eps.col(k).dot(s) + s_hoop * hoop);
    }
    return U;
  }
  const auto D = m.D();
  for (int k = 0; k < ev.n_points(); ++k)
    U += 0.5 * body.thickness * ev.JxW(k) * eps.col(k).dot(D * eps.col(k));
  return U;
}

std::vector<std::vector<double>> element_strain_energies(const model::Discretization& d,
                                                         const Eigen::VectorXd& u) {
  std::vector<std::vector<double>> out(d.bodies.size());
  for (size_t b = 0; b < d.bodies.size(); ++b) {
    const auto& body = d.bodies[b];
    out[b].assign(body.mesh.n_quads(), 0.0);
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const auto ev = fem::element_values(body.dofs.element(q), body.maps[q], body.n_gauss[q],
                                          body.mesh, q);
      out[b][q] = element_strain_energy(body, q, ev, body.element_coefficients(q, u));
    }
  }
  return out;
}

}  // namespace hpcontact::post
