// A small ASCII VTU writer: no VTK dependency, output that ParaView and meshio read.
#include "hpcontact/post/vtu.hpp"

#include <algorithm>
#include <vector>

#include "hpcontact/post/fields.hpp"
#include "hpcontact/post/vtk_grid.hpp"

namespace hpcontact::post {

SampledMesh sample_mesh(const model::Discretization& d, const Eigen::VectorXd& u, int subdivisions) {
  SampledMesh m;
  for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b) {
    const auto& body = d.bodies[b];
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const int p = body.dofs.element(q).max_degree();
      const int s = subdivisions > 0 ? subdivisions : std::clamp(p, 2, 16);
      const int base = static_cast<int>(m.points.size());
      for (int j = 0; j <= s; ++j)
        for (int i = 0; i <= s; ++i)
          m.points.push_back(evaluate(body, q, -1 + 2.0 * i / s, -1 + 2.0 * j / s, u));
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const int a = base + j * (s + 1) + i;
          m.cells.push_back({a, a + 1, a + s + 2, a + s + 1});
          m.cell_body.push_back(b);
          m.cell_element.push_back(body.mesh.quad_id(q));
          m.cell_degree.push_back(p);
        }
    }
  }
  return m;
}

void write_vtu(const std::string& path, const model::Discretization& d, const Eigen::VectorXd& u,
               int subdivisions) {
  const SampledMesh m = sample_mesh(d, u, subdivisions);
  const auto& points = m.points;
  const auto& cells = m.cells;
  const auto &cell_body = m.cell_body, &cell_element = m.cell_element, &cell_degree = m.cell_degree;
  std::vector<Vec2> xs;
  for (const auto& p : points) xs.push_back(p.x);
  VtkGrid grid(path, xs, cells, 9 /* VTK_QUAD */, 10);
  grid.begin_point_data("displacement", "von_mises");
  grid.point_vector("displacement", [&](std::size_t i) { return points[i].u; });
  auto scalar = [&](const char* name, auto get) {
    grid.point_scalar(name, [&](std::size_t i) { return get(points[i]); });
  };
  scalar("strain_xx", [](const PointResult& p) { return p.strain(0); });
  scalar("strain_yy", [](const PointResult& p) { return p.strain(1); });
  scalar("gamma_xy", [](const PointResult& p) { return p.strain(2); });
  if (std::any_of(d.bodies.begin(), d.bodies.end(), [](const model::Body& b) { return b.axisymmetric(); }))
    scalar("strain_hoop", [](const PointResult& p) { return p.strain_hoop; });
  scalar("sigma_xx", [](const PointResult& p) { return p.stress(0); });
  scalar("sigma_yy", [](const PointResult& p) { return p.stress(1); });
  scalar("sigma_zz", [](const PointResult& p) { return p.stress_zz; });
  scalar("sigma_xy", [](const PointResult& p) { return p.stress(2); });
  scalar("von_mises", [](const PointResult& p) { return p.von_mises; });
  scalar("principal_1", [](const PointResult& p) { return p.principal_1; });
  scalar("principal_2", [](const PointResult& p) { return p.principal_2; });
  // the mixed element's pressure (discontinuous: every element has its own points), when a body
  // has one
  if (std::any_of(d.bodies.begin(), d.bodies.end(), [](const model::Body& b) { return b.mixed; }))
    scalar("pressure_mixed", [](const PointResult& p) { return p.pressure; });
  grid.begin_cell_data();
  auto cell_int = [&](const char* name, const std::vector<int>& v) {
    grid.cell_scalar(name, [&](std::size_t i) { return v[i]; });
  };
  cell_int("body", cell_body);
  cell_int("element", cell_element);
  cell_int("degree", cell_degree);
  grid.finish();
}

}  // namespace hpcontact::post
