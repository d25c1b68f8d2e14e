// A .msh text of the box [-1, 1]^3 in 2 x 2 x 2 hexahedra with its six faces as physical surfaces,
// written for the tests of the 3D Gmsh reader and import.
#pragma once

#include <array>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "hpcontact/mesh/hex_map.hpp"

namespace hpcontact::test {

/// What box_msh writes. Physical surfaces x0, x1, y0, y1, z0, z1 (x = -1, x = 1, ...; tags 1-6,
/// surface entities 1-6) and the volume "box" (tag 7, volume entity 1); with `split`, the volumes
/// "left" (x < 0, tag 7, entity 1) and "right" (x > 0, tag 8, entity 2) and the surface "mid"
/// (x = 0, tag 9, surface entity 7).
struct Box {
  int order = 1;             ///< 1: 8-node hexahedra, 4-node quads; 2: 27 and 9 nodes
  bool serendipity = false;  ///< with order 2: 20-node hexahedra, 8-node quads
  bool split = false;
  /// Node positions: shape(x) for the point x of the regular grid of [-1, 1]^3; none: x.
  std::function<mesh::Vec3(const mesh::Vec3&)> shape;
  struct Entity {
    int dim, tag, phys;
    std::string name;
  };
  std::vector<Entity> entities;  ///< more entities, each with a physical group of its own
  struct Block {
    int dim, entity, type;
    std::vector<std::vector<int>> elements;  ///< node tags; element tags from 1001 on
  };
  std::vector<Block> blocks;  ///< more element blocks, after the box's
};

/// Grid nodes (i, j, k), 0 <= i, j, k < m = 2 order + 1, have the tag 1 + i + m (j + m k), all
/// in one block; the quads come first (tags from 1), then the hexahedra. Every grid node is
/// written, also those a 20-node hexahedron does not use.
inline std::string box_msh(const Box& box) {
  const int n = 2, m = box.order * n + 1;
  const auto node = [&](int i, int j, int k) { return 1 + i + m * (j + m * k); };
  const int n_hex_nodes = box.order == 1 ? 8 : box.serendipity ? 20 : 27;
  const int hex_type = box.order == 1 ? 5 : box.serendipity ? 17 : 12;
  const int quad_type = box.order == 1 ? 3 : box.serendipity ? 16 : 10;
  const int n_quad_nodes = box.order == 1 ? 4 : box.serendipity ? 8 : 9;

  struct Block {
    int dim, entity, type;
    std::vector<std::vector<int>> elements;
  };
  std::vector<Block> blocks;
  // The quads of the plane grid index `at` along `axis`, over the cells of the other two axes.
  const auto face_quads = [&](int axis, int at) {
    const int a1 = axis == 0 ? 1 : 0, a2 = axis == 2 ? 1 : 2;
    constexpr int ref[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1},
                               {1, 0},   {0, 1},  {-1, 0}, {0, 0}};
    std::vector<std::vector<int>> quads;
    for (int v = 0; v < n; ++v)
      for (int u = 0; u < n; ++u) {
        std::vector<int> q;
        for (int r = 0; r < n_quad_nodes; ++r) {
          std::array<int, 3> g{};
          g[axis] = at;
          g[a1] = box.order * u + box.order * (ref[r][0] + 1) / 2;
          g[a2] = box.order * v + box.order * (ref[r][1] + 1) / 2;
          q.push_back(node(g[0], g[1], g[2]));
        }
        quads.push_back(q);
      }
    return quads;
  };
  for (int f = 0; f < 6; ++f)
    blocks.push_back({2, f + 1, quad_type, face_quads(f / 2, f % 2 * (m - 1))});
  if (box.split) blocks.push_back({2, 7, quad_type, face_quads(0, (m - 1) / 2)});
  for (int volume = 0; volume < (box.split ? 2 : 1); ++volume) {
    Block b{3, volume + 1, hex_type, {}};
    for (int c = 0; c < n; ++c)
      for (int bb = 0; bb < n; ++bb)
        for (int a = 0; a < n; ++a) {
          if (box.split && a != volume) continue;
          std::vector<int> h;
          for (int r = 0; r < n_hex_nodes; ++r) {
            const int* x = mesh::kHex27Nodes[r];
            h.push_back(node(box.order * a + box.order * (x[0] + 1) / 2,
                             box.order * bb + box.order * (x[1] + 1) / 2,
                             box.order * c + box.order * (x[2] + 1) / 2));
          }
          b.elements.push_back(h);
        }
    blocks.push_back(b);
  }
  const std::size_t n_box_blocks = blocks.size();
  for (const Box::Block& b : box.blocks) blocks.push_back({b.dim, b.entity, b.type, b.elements});

  std::vector<Box::Entity> entities;
  const char* faces[] = {"x0", "x1", "y0", "y1", "z0", "z1"};
  for (int f = 0; f < 6; ++f) entities.push_back({2, f + 1, f + 1, faces[f]});
  if (box.split) {
    entities.push_back({2, 7, 9, "mid"});
    entities.push_back({3, 1, 7, "left"});
    entities.push_back({3, 2, 8, "right"});
  } else {
    entities.push_back({3, 1, 7, "box"});
  }
  entities.insert(entities.end(), box.entities.begin(), box.entities.end());

  std::ostringstream os;
  os.precision(17);
  os << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n" << entities.size() << "\n";
  for (const auto& e : entities) os << e.dim << " " << e.phys << " \"" << e.name << "\"\n";
  os << "$EndPhysicalNames\n$Entities\n0 0 ";
  int n_surfaces = 0, n_volumes = 0;
  for (const auto& e : entities) (e.dim == 2 ? n_surfaces : n_volumes) += 1;
  os << n_surfaces << " " << n_volumes << "\n";
  for (int dim : {2, 3})
    for (const auto& e : entities)
      if (e.dim == dim) os << e.tag << " -1 -1 -1 1 1 1 1 " << e.phys << " 0\n";
  os << "$EndEntities\n";
  const int n_nodes = m * m * m;
  os << "$Nodes\n1 " << n_nodes << " 1 " << n_nodes << "\n3 1 0 " << n_nodes << "\n";
  for (int t = 1; t <= n_nodes; ++t) os << t << "\n";
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        const double h = 2.0 / (m - 1);
        const mesh::Vec3 grid(-1 + h * i, -1 + h * j, -1 + h * k);
        const mesh::Vec3 x = box.shape ? box.shape(grid) : grid;
        os << x[0] << " " << x[1] << " " << x[2] << "\n";
      }
  os << "$EndNodes\n";
  std::size_t n_elements = 0;
  for (const Block& b : blocks) n_elements += b.elements.size();
  os << "$Elements\n" << blocks.size() << " " << n_elements << " 1 " << 1000 + n_elements << "\n";
  int tag = 1;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Block& b = blocks[i];
    if (i == n_box_blocks) tag = 1001;
    os << b.dim << " " << b.entity << " " << b.type << " " << b.elements.size() << "\n";
    for (const auto& e : b.elements) {
      os << tag++;
      for (int v : e) os << " " << v;
      os << "\n";
    }
  }
  os << "$EndElements\n";
  return os.str();
}

/// The 1-based line of `text` that starts with `start`, 0 if none.
inline int line_starting(const std::string& text, const std::string& start) {
  int line = 1;
  for (std::size_t at = 0; at < text.size(); ++line) {
    if (text.compare(at, start.size(), start) == 0) return line;
    const std::size_t end = text.find('\n', at);
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return 0;
}

}  // namespace hpcontact::test
