// Writing a VTK XML unstructured grid (.vtu) in ASCII: the part every .vtu file of ours shares.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "hpcontact/geometry/vec2.hpp"
#include "hpcontact/post/output_file.hpp"

namespace hpcontact::post {

/// A .vtu file written in order: the grid (points in the plane, cells of one VTK type), then
/// point data, then cell data. Values are printed with `precision` digits; a data array is given
/// by its value at each point (cell) index. Throws IoError if the file cannot be written.
class VtkGrid {
public:
  VtkGrid(const std::string& path, const std::vector<Vec2>& points,
          const std::vector<std::vector<int>>& cells, int vtk_cell_type, int precision);
  /// The same with points in space.
  VtkGrid(const std::string& path, const std::vector<std::array<double, 3>>& points,
          const std::vector<std::vector<int>>& cells, int vtk_cell_type, int precision);

  /// Starts the point data; `vectors` and `scalars` name the arrays ParaView shows first.
  void begin_point_data(const std::string& vectors, const std::string& scalars);
  void point_vector(const std::string& name, const std::function<Vec2(std::size_t)>& value);
  /// An array of n_components values per point: value(point, component).
  void point_components(const std::string& name, int n_components,
                        const std::function<double(std::size_t, int)>& value);
  void point_scalar(const std::string& name, const std::function<double(std::size_t)>& value,
                    const std::string& type = "Float64");
  /// Ends the point data and starts the cell data (`scalars`: the array shown first, or "").
  void begin_cell_data(const std::string& scalars = "");
  void cell_scalar(const std::string& name, const std::function<double(std::size_t)>& value,
                   const std::string& type = "Int32");
  /// Ends the cell data and closes the file, checked to the disk (OutputFile::close).
  void finish();

private:
  void array(const std::string& name, const std::string& type, std::size_t n,
             const std::function<double(std::size_t)>& value);
  /// Everything before the data: the piece's header, the points (point(i, coordinate)), cells.
  void write_grid(std::size_t n_points, const std::function<double(std::size_t, int)>& point,
                  const std::vector<std::vector<int>>& cells, int vtk_cell_type);

  OutputFile file_;
  std::ostream& out_;
  int precision_;
  /// v as text (significant digits: precision_), a point or vector as "x y 0\n".
  void number(double v);
  void vector(const Vec2& v);
  std::size_t n_points_ = 0, n_cells_ = 0;
};

}  // namespace hpcontact::post
