// A body meshed with hexahedra as the readers and the structured generators give it: nodes,
// topology, one geometric map per element and named sets of boundary faces.
#pragma once

#include <array>
#include <functional>
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

/// The elements of a structured grid of n[0] × n[1] × n[2] hexahedra over `mesh.nodes`, which
/// must hold the (n[0] + 1)(n[1] + 1)(n[2] + 1) grid points with i fastest, then j, then k:
/// element (i, j, k) has the vertices of grid cell (i, j, k) in the order of basis/hex_modes.hpp
/// and the map make_map(i, j, k, its vertex positions); its local face 2d (2d + 1) goes into the
/// set side_names[2d] (side_names[2d + 1]) where it is first (last) along axis d. Builds the
/// topology and checks the mesh (check_hex_mesh).
void add_structured_hexes(
    HexMesh& mesh, const std::array<int, 3>& n, const std::array<std::string, 6>& side_names,
    const std::function<HexMap(int, int, int, const std::array<Vec3, 8>&)>& make_map);

}  // namespace hpcontact::mesh
