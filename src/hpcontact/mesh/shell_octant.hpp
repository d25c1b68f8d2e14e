// A hexahedral mesh of one octant of a thick spherical shell with exact spherical faces.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "hpcontact/mesh/hex_map.hpp"
#include "hpcontact/mesh/hex_mesh.hpp"
#include "hpcontact/mesh/hex_topology.hpp"

namespace hpcontact::mesh {

/// The octant x, y, z >= 0 of the shell a <= |x| <= b (centre at the origin) in 3 n_layers
/// blending hexahedra: the octant of the sphere is cut into three curvilinear quadrilaterals (the
/// cubed-sphere construction, one per axis: its axis point, the two mid-points of the octant's
/// arcs next to it, and the octant's centre (1, 1, 1)/√3, joined by great-circle arcs), each
/// extruded radially through n_layers equal layers. Every face at a radius lies on its sphere,
/// the faces on the coordinate planes on Plane surfaces, the faces between the patches are the
/// transfinite interpolants of their edges. Local axes: zeta runs outwards (F4 inner, F5 outer).
struct ShellOctantMesh {
  HexTopology topology;
  std::vector<Vec3> nodes;
  std::vector<HexMap> maps;  ///< blending maps, one per element
  std::vector<ElementFace> inner, outer;        ///< faces on |x| = a and on |x| = b
  std::array<std::vector<ElementFace>, 3> symmetry;  ///< faces on the planes x = 0, y = 0, z = 0
};

/// Throws InputError unless 0 < a < b and n_layers >= 1.
ShellOctantMesh shell_octant_mesh(double inner_radius, double outer_radius, int n_layers);

}  // namespace hpcontact::mesh
