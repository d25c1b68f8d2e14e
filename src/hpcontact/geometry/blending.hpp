// Gordon–Hall blending map of the reference quadrilateral onto an element with exact (curved) edges.
#pragma once

#include <array>

#include "hpcontact/geometry/curve.hpp"

namespace hpcontact::geometry {

/// Geometry of one quadrilateral for the blending function method (seed eq. 2.74–2.76).
///
/// vertices: X1..X4 counter-clockwise, X1 the image of (-1,-1) (see basis/quad_modes.hpp).
/// edges[e]: the curve of local edge E(e+1), oriented in the local direction
/// (E1: X1->X2, E2: X2->X3, E3: X4->X3, E4: X1->X4), or null for a straight edge.
struct BlendingQuad {
  std::array<Vec2, 4> vertices;
  std::array<CurvePtr, 4> edges;

  /// x(xi, eta) and, if J is not null, the Jacobian J = [dx/dxi, dx/deta] (columns).
  Vec2 map(double xi, double eta, Mat2* J = nullptr) const;
};

}  // namespace hpcontact::geometry
