// VTU (ParaView) output of a solution, each element subdivided so the high-order field shows.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/discretization.hpp"
#include "hpcontact/post/fields.hpp"

namespace hpcontact::post {

/// The solution sampled for viewing: each element on an (s+1)×(s+1) grid of its reference
/// square, s = subdivisions (0: the element's degree, at least 2 and at most 16), as linear
/// quads (`cells`, four point indices counter-clockwise), with the body, element id and degree of
/// each cell. What solution.vtu holds, and what the Python module's Result.mesh() returns.
struct SampledMesh {
  std::vector<PointResult> points;
  std::vector<std::vector<int>> cells;
  std::vector<int> cell_body, cell_element, cell_degree;
};
SampledMesh sample_mesh(const model::Discretization& d, const Eigen::VectorXd& u, int subdivisions = 0);

/// Writes an unstructured grid: each element sampled on an (s+1)×(s+1) grid of its reference
/// square, s = subdivisions (0: the element's degree, at least 2 and at most 16), as linear quads.
/// Point data: displacement, strains (strain_xx, strain_yy, gamma_xy: Green–Lagrange under finite
/// strain), stress components, von Mises, principal stresses; cell data: body,
/// element id, degree. Throws IoError if the file cannot be written.
void write_vtu(const std::string& path, const model::Discretization& d, const Eigen::VectorXd& u,
               int subdivisions = 0);

}  // namespace hpcontact::post
