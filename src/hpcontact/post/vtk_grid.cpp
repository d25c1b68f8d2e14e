// The XML skeleton of an ASCII .vtu file: header, points, cells, data arrays, footer.
#include "hpcontact/post/vtk_grid.hpp"

#include <charconv>

namespace hpcontact::post {

VtkGrid::VtkGrid(const std::string& path, const std::vector<Vec2>& points,
                 const std::vector<std::vector<int>>& cells, int vtk_cell_type, int precision)
    : file_(path), out_(file_.stream()), precision_(precision) {
  write_grid(
      points.size(), [&](std::size_t i, int c) { return c < 2 ? points[i][c] : 0.0; }, cells,
      vtk_cell_type);
}

VtkGrid::VtkGrid(const std::string& path, const std::vector<std::array<double, 3>>& points,
                 const std::vector<std::vector<int>>& cells, int vtk_cell_type, int precision)
    : file_(path), out_(file_.stream()), precision_(precision) {
  write_grid(
      points.size(), [&](std::size_t i, int c) { return points[i][c]; }, cells, vtk_cell_type);
}

void VtkGrid::write_grid(std::size_t n_points, const std::function<double(std::size_t, int)>& point,
                         const std::vector<std::vector<int>>& cells, int vtk_cell_type) {
  n_points_ = n_points;
  n_cells_ = cells.size();
  out_ << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
       << "<UnstructuredGrid>\n"
       << "<Piece NumberOfPoints=\"" << n_points << "\" NumberOfCells=\"" << cells.size()
       << "\">\n";
  out_ << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n_points; ++i)
    for (int c = 0; c < 3; ++c) {
      number(point(i, c));
      out_ << (c < 2 ? ' ' : '\n');
    }
  out_ << "</DataArray>\n</Points>\n";
  out_ << "<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& c : cells) {
    for (std::size_t i = 0; i < c.size(); ++i) out_ << c[i] << (i + 1 < c.size() ? ' ' : '\n');
  }
  out_ << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for (const auto& c : cells) out_ << (offset += c.size()) << '\n';
  out_ << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < cells.size(); ++i) out_ << vtk_cell_type << '\n';
  out_ << "</DataArray>\n</Cells>\n";
}

void VtkGrid::begin_point_data(const std::string& vectors, const std::string& scalars) {
  out_ << "<PointData Vectors=\"" << vectors << "\" Scalars=\"" << scalars << "\">\n";
}

void VtkGrid::point_vector(const std::string& name, const std::function<Vec2(std::size_t)>& value) {
  out_ << "<DataArray type=\"Float64\" Name=\"" << name
       << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n_points_; ++i) {
    vector(value(i));
  }
  out_ << "</DataArray>\n";
}

void VtkGrid::point_components(const std::string& name, int n_components,
                               const std::function<double(std::size_t, int)>& value) {
  out_ << "<DataArray type=\"Float64\" Name=\"" << name << "\" NumberOfComponents=\""
       << n_components << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n_points_; ++i)
    for (int c = 0; c < n_components; ++c) {
      number(value(i, c));
      out_ << (c + 1 < n_components ? ' ' : '\n');
    }
  out_ << "</DataArray>\n";
}

void VtkGrid::point_scalar(const std::string& name, const std::function<double(std::size_t)>& value,
                           const std::string& type) {
  array(name, type, n_points_, value);
}

void VtkGrid::begin_cell_data(const std::string& scalars) {
  out_ << "</PointData>\n";
  out_ << (scalars.empty() ? std::string("<CellData>\n") : "<CellData Scalars=\"" + scalars + "\">\n");
}

void VtkGrid::cell_scalar(const std::string& name, const std::function<double(std::size_t)>& value,
                          const std::string& type) {
  array(name, type, n_cells_, value);
}

void VtkGrid::finish() {
  out_ << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  file_.close();
}

void VtkGrid::array(const std::string& name, const std::string& type, std::size_t n,
                    const std::function<double(std::size_t)>& value) {
  out_ << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    number(value(i));
    out_ << '\n';
  }
  out_ << "</DataArray>\n";
}

void VtkGrid::number(double v) {
  // as `out_ << v` at this precision writes it (printf's %g), without the stream's locale work:
  // a third of the time of writing a field
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::general, precision_).ptr;
  out_.write(buffer, end - buffer);
}

void VtkGrid::vector(const Vec2& v) {
  number(v.x());
  out_ << ' ';
  number(v.y());
  out_ << " 0\n";
}

}  // namespace hpcontact::post
