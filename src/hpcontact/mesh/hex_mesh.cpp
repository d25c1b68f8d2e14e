// The checks a hexahedral mesh from a reader or generator passes before it is used.
#include "hpcontact/mesh/hex_mesh.hpp"

#include <set>

#include "hpcontact/core/error.hpp"

namespace hpcontact::mesh {

void check_hex_mesh(const HexMesh& mesh) {
  const HexTopology& t = mesh.topology;
  HPC_REQUIRE(static_cast<int>(mesh.maps.size()) == t.n_hexes(), MeshError, mesh.context, ": ",
              mesh.maps.size(), " maps for ", t.n_hexes(), " elements");
  HPC_REQUIRE(static_cast<int>(mesh.nodes.size()) == t.n_nodes(), MeshError, mesh.context, ": ",
              mesh.nodes.size(), " node positions for ", t.n_nodes(), " nodes");
  for (const auto& [name, faces] : mesh.face_sets) {
    std::set<ElementFace> seen;
    for (const auto& [h, lf] : faces) {
      HPC_REQUIRE(h >= 0 && h < t.n_hexes() && lf >= 0 && lf < 6, MeshError, mesh.context,
                  ": face set '", name, "' holds (element ", h, ", face ", lf,
                  "), outside the mesh's ", t.n_hexes(), " elements and faces 0..5");
      HPC_REQUIRE(t.face(t.hex_face(h, lf)).on_boundary(), MeshError, mesh.context,
                  ": face set '", name, "' holds (element ", h, ", face ", lf,
                  "), which is not on the boundary");
      HPC_REQUIRE(seen.insert({h, lf}).second, MeshError, mesh.context, ": face set '", name,
                  "' holds (element ", h, ", face ", lf, ") twice");
    }
  }
}

}  // namespace hpcontact::mesh
