// A small ASCII VTU writer: no VTK dependency, output that ParaView and meshio read.
#include "hpcontact/post/vtu.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/post/fields.hpp"

namespace hpcontact::post {

void write_vtu(const std::string& path, const model::Discretization& d, const Eigen::VectorXd& u,
               int subdivisions) {
  std::vector<PointResult> points;
  std::vector<std::array<int, 4>> cells;
  std::vector<int> cell_body, cell_element, cell_degree;
  for (int b = 0; b < static_cast<int>(d.bodies.size()); ++b) {
    const auto& body = d.bodies[b];
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const int p = body.dofs.element(q).max_degree();
      const int s = subdivisions > 0 ? subdivisions : std::clamp(p, 2, 16);
      const int base = static_cast<int>(points.size());
      for (int j = 0; j <= s; ++j)
        for (int i = 0; i <= s; ++i)
          points.push_back(evaluate(body, q, -1 + 2.0 * i / s, -1 + 2.0 * j / s, u));
      for (int j = 0; j < s; ++j)
        for (int i = 0; i < s; ++i) {
          const int a = base + j * (s + 1) + i;
          cells.push_back({a, a + 1, a + s + 2, a + s + 1});
          cell_body.push_back(b);
          cell_element.push_back(body.mesh.quad_id(q));
          cell_degree.push_back(p);
        }
    }
  }
  std::ofstream out(path);
  HPC_REQUIRE(out, IoError, path, ": cannot open for writing");
  out << std::setprecision(10);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\"" << cells.size()
      << "\">\n";
  out << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : points) out << p.x.x() << ' ' << p.x.y() << " 0\n";
  out << "</DataArray>\n</Points>\n";
  out << "<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& c : cells) out << c[0] << ' ' << c[1] << ' ' << c[2] << ' ' << c[3] << '\n';
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (size_t i = 0; i < cells.size(); ++i) out << 4 * (i + 1) << '\n';
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (size_t i = 0; i < cells.size(); ++i) out << "9\n";  // VTK_QUAD
  out << "</DataArray>\n</Cells>\n";

  out << "<PointData Vectors=\"displacement\" Scalars=\"von_mises\">\n";
  out << "<DataArray type=\"Float64\" Name=\"displacement\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (const auto& p : points) out << p.u.x() << ' ' << p.u.y() << " 0\n";
  out << "</DataArray>\n";
  auto scalar = [&](const char* name, auto get) {
    out << "<DataArray type=\"Float64\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (const auto& p : points) out << get(p) << '\n';
    out << "</DataArray>\n";
  };
  scalar("strain_xx", [](const PointResult& p) { return p.strain(0); });
  scalar("strain_yy", [](const PointResult& p) { return p.strain(1); });
  scalar("gamma_xy", [](const PointResult& p) { return p.strain(2); });
  scalar("sigma_xx", [](const PointResult& p) { return p.stress(0); });
  scalar("sigma_yy", [](const PointResult& p) { return p.stress(1); });
  scalar("sigma_zz", [](const PointResult& p) { return p.stress_zz; });
  scalar("sigma_xy", [](const PointResult& p) { return p.stress(2); });
  scalar("von_mises", [](const PointResult& p) { return p.von_mises; });
  scalar("principal_1", [](const PointResult& p) { return p.principal_1; });
  scalar("principal_2", [](const PointResult& p) { return p.principal_2; });
  out << "</PointData>\n<CellData>\n";
  auto cell_int = [&](const char* name, const std::vector<int>& v) {
    out << "<DataArray type=\"Int32\" Name=\"" << name << "\" format=\"ascii\">\n";
    for (int x : v) out << x << '\n';
    out << "</DataArray>\n";
  };
  cell_int("body", cell_body);
  cell_int("element", cell_element);
  cell_int("degree", cell_degree);
  out << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  HPC_REQUIRE(out.good(), IoError, path, ": write failed");
}

}  // namespace hpcontact::post
