// The Gauss points of a contact boundary, with the shape functions that live on them.
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/mesh/element_map.hpp"

namespace hpcontact::contact {

/// One Gauss–Legendre point of a contact edge (undeformed configuration).
struct ContactPoint {
  int element = -1, local_edge = -1;
  double t = 0;         ///< local edge parameter in [-1, 1]
  double weight = 0;    ///< Gauss weight × ds/dt × thickness: ∫ f ds t ≈ Σ weight f
  Vec2 X;               ///< undeformed position
  Vec2 normal;          ///< undeformed outward unit normal of the body
  std::vector<int> modes;  ///< body modes whose shape function is non-zero on this edge
  Eigen::VectorXd N;       ///< their values at the point
};

/// The contact points of a set of boundary edges of one body, edge by edge in the order given,
/// n_points per edge (seed: 50, independent of p).
std::vector<ContactPoint> contact_points(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                         const std::vector<mesh::ElementMap>& maps,
                                         const std::vector<int>& edges, int n_points,
                                         double thickness);

}  // namespace hpcontact::contact
