// A structured mesh of a hollow cylinder's sector in blending hexahedra with exact cylinders.
#pragma once

#include <array>

#include "hpcontact/mesh/hex_mesh.hpp"

namespace hpcontact::mesh {

/// The sector a <= r <= b, angle0 <= θ <= angle1, 0 <= z <= length of the hollow cylinder about
/// the z axis (angles in radians, from the x axis towards the y axis).
struct CylinderSector {
  double inner_radius = 1, outer_radius = 2;
  double angle0 = 0, angle1 = 1.5707963267948966;  ///< a quarter by default
  double length = 1;
};

/// The sector cut into n[0] × n[1] × n[2] blending hexahedra, equal steps in r, θ and z, each
/// with its local axes (xi, eta, zeta) along (r, θ, z): the faces xi = ±1 on the cylinders
/// r = r_i (exact, geometry::Cylinder; its circular edges uniform in angle, so that every section
/// z = const is the 2D blending map of an annulus sector with CircularArc edges, which is the
/// polar map r(xi) (cos θ(eta), sin θ(eta))), the faces eta = ±1 on the planes θ = θ_j through
/// the axis and zeta = ±1 on the planes z = z_k (geometry::Plane). Node (i, j, k) at
/// (r_i cos θ_j, r_i sin θ_j, z_k) has index i + (n[0] + 1)(j + (n[1] + 1) k), element (i, j, k)
/// index i + n[0](j + n[1] k). Face sets, in element order: "inner", "outer" (F0 on r = a, F1
/// on r = b), "theta0", "theta1" (F2 on θ = angle0, F3 on θ = angle1), "z0", "z1" (F4 on z = 0,
/// F5 on z = length).
/// Throws InputError unless 0 < a < b, angle0 < angle1 < angle0 + 2π (a closed ring would need
/// its first and last nodes merged, which this generator does not do), each element's angle
/// (angle1 − angle0)/n[1] < π (a circular edge runs the shorter way round), length > 0 and every
/// n[d] >= 1.
HexMesh cylinder_sector_mesh(const CylinderSector& sector, std::array<int, 3> n);

}  // namespace hpcontact::mesh
