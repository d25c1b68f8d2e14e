// The checks a hexahedral mesh from a reader or generator passes before it is used, and the
// elements of a structured grid (the generators' common part).
#include "hpcontact/mesh/hex_mesh.hpp"

#include <set>

#include "hpcontact/basis/hex_modes.hpp"
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

void add_structured_hexes(
    HexMesh& m, const std::array<int, 3>& n, const std::array<std::string, 6>& side_names,
    const std::function<HexMap(int, int, int, const std::array<Vec3, 8>&)>& make_map) {
  auto node = [&](int i, int j, int k) { return i + (n[0] + 1) * (j + (n[1] + 1) * k); };
  std::vector<std::array<int, 8>> hexes;
  for (const std::string& name : side_names) m.face_sets[name];
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const int element = static_cast<int>(hexes.size());
        std::array<int, 8> v;
        std::array<Vec3, 8> x;
        for (int c = 0; c < 8; ++c) {
          const auto* r = basis::kHexVertexCoordinates[c];
          v[c] = node(i + (r[0] > 0), j + (r[1] > 0), k + (r[2] > 0));
          x[c] = m.nodes[v[c]];
        }
        hexes.push_back(v);
        m.maps.push_back(make_map(i, j, k, x));
        const std::array<int, 3> index{i, j, k};
        for (int d = 0; d < 3; ++d) {
          if (index[d] == 0) m.face_sets[side_names[2 * d]].push_back({element, 2 * d});
          if (index[d] == n[d] - 1)
            m.face_sets[side_names[2 * d + 1]].push_back({element, 2 * d + 1});
        }
      }
  m.topology = HexTopology(std::move(hexes), static_cast<int>(m.nodes.size()), m.context);
  check_hex_mesh(m);
}

}  // namespace hpcontact::mesh
