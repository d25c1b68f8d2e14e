// A stress field sampled on small cells of the deformed mesh, for drawing (the HTML report).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/discretization.hpp"

namespace hpcontact::post {

struct FieldCells {
  /// Every element of every body split into n × n cells of its reference square, each cell's
  /// corners mapped to the deformed configuration x + u (true scale), counter-clockwise.
  std::vector<std::array<Vec2, 4>> corners;
  std::vector<double> values;  ///< von Mises at each cell's centre
  /// Per element, its deformed boundary: 4 n points, counter-clockwise from its first corner.
  std::vector<std::vector<Vec2>> outlines;
  int subdivisions = 1;  ///< n
};

/// The von Mises stress of u on the deformed mesh: n the largest of 1..8 with at most
/// `max_cells` cells in all (at least 1).
FieldCells von_mises_cells(const model::Discretization& d, const Eigen::VectorXd& u,
                           int max_cells = 20000);

/// The value below which a fraction `fraction` of `values` lie (nearest rank); 0 if empty.
double percentile(std::vector<double> values, double fraction);

}  // namespace hpcontact::post
