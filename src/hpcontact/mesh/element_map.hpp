// The map from the reference square [-1, 1]^2 onto one element: exact (blending) or isoparametric.
#pragma once

#include <vector>

#include "hpcontact/basis/quad_modes.hpp"
#include "hpcontact/geometry/blending.hpp"
#include "hpcontact/mesh/mesh.hpp"

namespace hpcontact::mesh {

/// Geometry of one element. Blending: the exact edges of the mesh (p-version, seed §2.2.4).
/// Isoparametric: Lagrange Q4/Q8/Q9 interpolation of nodes placed on the exact edges (h-version).
class ElementMap {
public:
  static ElementMap blending(const Mesh& mesh, int q);
  static ElementMap isoparametric(const Mesh& mesh, int q, basis::LagrangeType type);

  /// x(xi, eta); if J is given, J = [dx/dxi, dx/deta] (columns).
  Vec2 map(double xi, double eta, Mat2* J = nullptr) const;
  /// |det J| / |J|²: 1/2 for a square, 0 where the map is singular (a 180° corner, where two
  /// edges on one smooth curve meet); below 1e-6 stresses computed there are round-off.
  double regularity(double xi, double eta) const;

  /// Isoparametric nodes (Lagrange order), empty for blending.
  const std::vector<Vec2>& lagrange_nodes() const { return iso_nodes_; }

private:
  bool iso_ = false;
  geometry::BlendingQuad blend_;
  basis::LagrangeType type_ = basis::LagrangeType::q4;
  std::vector<Vec2> iso_nodes_;
};

/// Checks det J > 0 at an n×n Gauss grid and at the corners; throws MeshError naming the element.
void check_jacobian(const ElementMap& map, const Mesh& mesh, int q, int n_points);

}  // namespace hpcontact::mesh
