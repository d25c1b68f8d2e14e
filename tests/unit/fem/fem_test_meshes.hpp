// One- and four-element meshes shared by the fem unit tests.
#pragma once

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "hpcontact/geometry/curve.hpp"
#include "hpcontact/mesh/mesh.hpp"

namespace hpcontact::fem_test {

/// One straight-sided, distorted (non-parallelogram) convex quadrilateral.
inline mesh::Mesh distorted_quad() {
  return mesh::Mesh({Vec2(0, 0), Vec2(2, 0.3), Vec2(2.4, 1.9), Vec2(-0.2, 1.5)}, {1, 2, 3, 4},
                    {{0, 1, 2, 3}}, {1}, {}, "distorted quad");
}

/// One annular-sector element 1 <= r <= 2, 0 <= theta <= pi/3 with exact arcs: E2 outer, E4 inner.
inline mesh::Mesh sector_quad(double r1 = 1, double r2 = 2, double theta = std::numbers::pi / 3) {
  auto polar = [](double r, double t) { return Vec2(r * std::cos(t), r * std::sin(t)); };
  const std::vector<Vec2> x = {polar(r1, 0), polar(r2, 0), polar(r2, theta), polar(r1, theta)};
  std::vector<mesh::EdgeCurve> curves = {
      {1, 2, std::make_shared<geometry::CircularArc>(Vec2(0, 0), r2, 0.0, theta)},
      {0, 3, std::make_shared<geometry::CircularArc>(Vec2(0, 0), r1, 0.0, theta)}};
  return mesh::Mesh(x, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {1}, curves, "sector");
}

/// The square [0,2]² as 2×2 elements (node ids 1..9 row by row, element ids 1..4); the centre
/// node is moved to (1.1, 0.9). Element 4 starts at its upper right corner so that some of its
/// local edges run against the global direction.
inline mesh::Mesh mesh_2x2() {
  std::vector<Vec2> nodes;
  std::vector<int> ids;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      nodes.emplace_back(i, j);
      ids.push_back(1 + 3 * j + i);
    }
  nodes[4] = Vec2(1.1, 0.9);
  std::vector<std::array<int, 4>> quads = {{0, 1, 4, 3}, {1, 2, 5, 4}, {3, 4, 7, 6}, {8, 7, 4, 5}};
  return mesh::Mesh(nodes, ids, quads, {1, 2, 3, 4}, {}, "2x2");
}

}  // namespace hpcontact::fem_test
