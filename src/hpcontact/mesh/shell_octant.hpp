// A hexahedral mesh of one octant of a thick spherical shell with exact spherical faces.
#pragma once

#include "hpcontact/mesh/hex_mesh.hpp"

namespace hpcontact::mesh {

/// The octant x, y, z >= 0 of the shell a <= |x| <= b (centre at the origin) in 3 n_layers
/// blending hexahedra: the octant of the sphere is cut into three curvilinear quadrilaterals (the
/// cubed-sphere construction, one per axis: its axis point, the two mid-points of the octant's
/// arcs next to it, and the octant's centre (1, 1, 1)/√3, joined by great-circle arcs), each
/// extruded radially through n_layers equal layers. Every face at a radius lies on its sphere,
/// the faces on the coordinate planes on Plane surfaces, the faces between the patches are the
/// transfinite interpolants of their edges. Local axes: zeta runs outwards (F4 inner, F5 outer).
/// Face sets: "inner" and "outer" (on |x| = a and |x| = b, one face per patch), "x0", "y0", "z0"
/// (on the planes x = 0, y = 0, z = 0, two patches each).
/// Throws InputError unless 0 < a < b and n_layers >= 1.
HexMesh shell_octant_mesh(double inner_radius, double outer_radius, int n_layers);

}  // namespace hpcontact::mesh
