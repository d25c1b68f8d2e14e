// Shape values and physical gradients of one element at its quadrature points.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/mesh/element_map.hpp"

namespace hpcontact::fem {

/// Values at the n_gauss × n_gauss Gauss–Legendre points of the reference square.
/// Matrices are n_modes × n_points (a column per quadrature point).
struct ElementValues {
  Eigen::MatrixXd N, dN_dx, dN_dy;
  Eigen::VectorXd JxW;  ///< weight × det J (area element, without thickness)
  std::vector<Vec2> x;  ///< physical points
  int n_modes() const { return static_cast<int>(N.rows()); }
  int n_points() const { return static_cast<int>(N.cols()); }
};

/// Evaluates the element space through the element map. A non-positive det J is a MeshError.
ElementValues element_values(const ElementSpace& space, const mesh::ElementMap& map,
                             int n_gauss, const mesh::Mesh& mesh, int q);

/// Shape values and physical gradients at one reference point (xi, eta).
struct PointValues {
  Eigen::VectorXd N, dN_dx, dN_dy;
  Vec2 x;
  double det_J = 0;
};
PointValues point_values(const ElementSpace& space, const mesh::ElementMap& map, double xi,
                         double eta);

}  // namespace hpcontact::fem
