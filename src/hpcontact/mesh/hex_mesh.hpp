// A body meshed with hexahedra as the readers and the structured generators give it: nodes,
// topology, one geometric map per element and named sets of boundary faces.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "hpcontact/mesh/hex_map.hpp"
#include "hpcontact/mesh/hex_topology.hpp"

namespace hpcontact::mesh {

/// A local face of an element: (element, local face 0..5 in the order of basis/hex_modes.hpp).
using ElementFace = std::pair<int, int>;

/// A hexahedral mesh of one body. Its face sets hold faces of the boundary only (a reader or
/// generator checks this); their names are those a problem's input refers to (Gmsh's physical
/// surfaces, a generator's "x0", "x1", ...).
struct HexMesh {
  HexTopology topology;
  std::vector<Vec3> nodes;   ///< node i's position; topology's node indices index it
  std::vector<HexMap> maps;  ///< one per element: trilinear, triquadratic or blending
  std::map<std::string, std::vector<ElementFace>> face_sets;
  std::string context = "hexahedral mesh";  ///< names the mesh in messages (file or generator)
};

/// Checks what a HexMesh promises: one map per element, one position per node, and face sets of
/// boundary faces only, each face at most once in a set. Throws MeshError naming the mesh's
/// context, the set and the entry.
void check_hex_mesh(const HexMesh& mesh);

}  // namespace hpcontact::mesh
