// A 3D solution's stresses at Gauss points (summary) and on subdivided elements (solution.vtu).
#include "hpcontact/post/solid_fields.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "hpcontact/fem/hex_elasticity.hpp"
#include "hpcontact/fem/hex_values.hpp"
#include "hpcontact/post/fields.hpp"
#include "hpcontact/post/vtk_grid.hpp"

namespace hpcontact::post {

namespace {

using Voigt = std::array<double, 6>;  // xx, yy, zz, yz, xz, xy

Voigt stress(const material::Elasticity3& D, const Eigen::Matrix<double, 6, 1>& strain) {
  const Eigen::Matrix<double, 6, 1> s = D * strain;
  return {s(0), s(1), s(2), s(3), s(4), s(5)};
}

/// Principal stresses, descending.
std::array<double, 3> principal(const Voigt& s) {
  Eigen::Matrix3d t;
  t << s[0], s[5], s[4], s[5], s[1], s[3], s[4], s[3], s[2];
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(t, Eigen::EigenvaluesOnly).eigenvalues();
  return {ev(2), ev(1), ev(0)};
}

/// Displacement and stress at one reference point of an element.
struct PointValue {
  std::array<double, 3> x{}, u{};
  Voigt sigma{};
};

PointValue evaluate(const model::SolidDiscretization& d, const material::Elasticity3& D, int h,
                    const Eigen::VectorXd& u_e, double xi, double eta, double zeta) {
  const basis::HierarchicHex& element = d.dofs.element(h).hierarchic;
  const int n = element.n_modes();
  Eigen::VectorXd N(n);
  Eigen::MatrixXd ref(n, 3);
  element.evaluate(xi, eta, zeta, N.data(), ref.col(0).data(), ref.col(1).data(),
                   ref.col(2).data());
  mesh::Mat3 J;
  const mesh::Vec3 x = d.mesh.maps[h].map(xi, eta, zeta, &J);
  const Eigen::MatrixXd grad = ref * J.inverse();  // dN/dx_k in column k
  Eigen::Matrix3d G;                              // G(i, k) = du_i/dx_k
  PointValue p;
  for (int i = 0; i < 3; ++i) {
    const auto ui = u_e.segment(i * n, n);
    p.u[i] = N.dot(ui);
    p.x[i] = x(i);
    for (int k = 0; k < 3; ++k) G(i, k) = grad.col(k).dot(ui);
  }
  Eigen::Matrix<double, 6, 1> eps;
  eps << G(0, 0), G(1, 1), G(2, 2), G(1, 2) + G(2, 1), G(0, 2) + G(2, 0), G(0, 1) + G(1, 0);
  p.sigma = stress(D, eps);
  return p;
}

}  // namespace

SolidFields solid_fields(const model::SolidDiscretization& d, const Eigen::VectorXd& u) {
  SolidFields out;
  const material::Elasticity3 D = d.material.D3();
  for (int h = 0; h < d.mesh.topology.n_hexes(); ++h) {
    const fem::HexElementSpace& space = d.dofs.element(h);
    const auto values = fem::hex_values(space.hierarchic, d.mesh.maps[h],
                                        fem::hex_gauss_points(space.hierarchic, d.mesh.maps[h]));
    const Eigen::VectorXd u_e = model::element_coefficients(d, h, u);
    const auto strains = fem::hex_strains(values, u_e);
    const int n = space.n_modes();
    for (int q = 0; q < values.n_points(); ++q) {
      const Voigt sigma = stress(D, strains.col(q));
      double work = 0;
      for (int k = 0; k < 6; ++k) work += sigma[k] * strains(k, q);
      out.strain_energy += 0.5 * work * values.JxW(q);
      out.volume += values.JxW(q);
      if (const double vm = von_mises(sigma); vm > out.von_mises_max) {
        out.von_mises_max = vm;
        out.von_mises_max_at = {values.x[q](0), values.x[q](1), values.x[q](2)};
        out.von_mises_max_element = h;
      }
      mesh::Vec3 uq;
      for (int c = 0; c < 3; ++c) uq(c) = values.N.col(q).dot(u_e.segment(c * n, n));
      out.displacement_max = std::max(out.displacement_max, uq.norm());
    }
  }
  for (int v = 0; v < d.mesh.topology.n_nodes(); ++v)
    if (const int mode = d.dofs.vertex_mode(v); mode >= 0)
      out.displacement_max = std::max(
          out.displacement_max, mesh::Vec3(u(3 * mode), u(3 * mode + 1), u(3 * mode + 2)).norm());
  return out;
}

void write_solid_vtu(const std::string& path, const model::SolidDiscretization& d,
                     const Eigen::VectorXd& u, int subdivisions) {
  const material::Elasticity3 D = d.material.D3();
  std::vector<std::array<double, 3>> points;
  std::vector<PointValue> values;
  std::vector<std::vector<int>> cells;
  std::vector<int> cell_element, cell_degree;
  for (int h = 0; h < d.mesh.topology.n_hexes(); ++h) {
    const auto& p = d.dofs.element(h).hierarchic.p;
    const int degree = *std::max_element(p.begin(), p.end());
    const int m = subdivisions > 0 ? subdivisions : std::max(1, degree);
    const Eigen::VectorXd u_e = model::element_coefficients(d, h, u);
    const int first = static_cast<int>(points.size());
    const auto index = [&](int i, int j, int k) { return first + (k * (m + 1) + j) * (m + 1) + i; };
    for (int k = 0; k <= m; ++k)
      for (int j = 0; j <= m; ++j)
        for (int i = 0; i <= m; ++i) {
          values.push_back(evaluate(d, D, h, u_e, -1 + 2.0 * i / m, -1 + 2.0 * j / m,
                                    -1 + 2.0 * k / m));
          points.push_back(values.back().x);
        }
    for (int k = 0; k < m; ++k)
      for (int j = 0; j < m; ++j)
        for (int i = 0; i < m; ++i) {
          cells.push_back({index(i, j, k), index(i + 1, j, k), index(i + 1, j + 1, k),
                           index(i, j + 1, k), index(i, j, k + 1), index(i + 1, j, k + 1),
                           index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)});
          cell_element.push_back(h);
          cell_degree.push_back(degree);
        }
  }
  constexpr int kVtkHexahedron = 12;
  VtkGrid grid(path, points, cells, kVtkHexahedron, 10);
  grid.begin_point_data("displacement", "von_mises");
  grid.point_components("displacement", 3, [&](std::size_t i, int c) { return values[i].u[c]; });
  const char* names[6] = {"sigma_xx", "sigma_yy", "sigma_zz", "sigma_yz", "sigma_xz", "sigma_xy"};
  for (int k = 0; k < 6; ++k)
    grid.point_scalar(names[k], [&](std::size_t i) { return values[i].sigma[k]; });
  grid.point_scalar("von_mises", [&](std::size_t i) { return von_mises(values[i].sigma); });
  std::vector<std::array<double, 3>> principals(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) principals[i] = principal(values[i].sigma);
  grid.point_components("principal_stress", 3,
                        [&](std::size_t i, int c) { return principals[i][c]; });
  grid.begin_cell_data("element");
  grid.cell_scalar("element", [&](std::size_t c) { return cell_element[c]; });
  grid.cell_scalar("degree", [&](std::size_t c) { return cell_degree[c]; });
  grid.finish();
}

}  // namespace hpcontact::post
