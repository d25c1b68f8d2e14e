// Structured blocks of hexahedra and the 48 symmetries of the cube, shared by the hex unit tests.
#pragma once

#include <algorithm>
#include <array>
#include <numeric>
#include <random>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"

namespace hpcontact::hex_test {

/// Elements (VTK vertex order) of an nx × ny × nz block of unit cubes, and each node's integer
/// grid position; node (i, j, k) has index i + (nx + 1)(j + (ny + 1) k).
struct HexBlock {
  std::vector<std::array<int, 8>> hexes;
  std::vector<std::array<int, 3>> positions;
  int n_nodes() const { return static_cast<int>(positions.size()); }
};

inline HexBlock hex_block(int nx, int ny, int nz) {
  HexBlock block;
  auto node = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) block.positions.push_back({i, j, k});
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        std::array<int, 8> h;
        for (int v = 0; v < 8; ++v) {
          const auto* x = basis::kHexVertexCoordinates[v];
          h[v] = node(i + (x[0] > 0), j + (x[1] > 0), k + (x[2] > 0));
        }
        block.hexes.push_back(h);
      }
  return block;
}

/// The 48 symmetries of the reference cube (24 rotations, 24 with a reflection) as vertex
/// permutations pi: the element renumbered by a symmetry has as its local vertex v the old local
/// vertex pi[v]. The identity comes first.
inline std::vector<std::array<int, 8>> cube_symmetries() {
  auto vertex_at = [](const std::array<int, 3>& x) {
    for (int v = 0; v < 8; ++v) {
      const auto* y = basis::kHexVertexCoordinates[v];
      if (y[0] == x[0] && y[1] == x[1] && y[2] == x[2]) return v;
    }
    return -1;
  };
  std::vector<std::array<int, 8>> symmetries;
  std::array<int, 3> axes{0, 1, 2};
  do {
    for (int signs = 0; signs < 8; ++signs) {
      std::array<int, 8> pi;
      for (int v = 0; v < 8; ++v) {
        const auto* x = basis::kHexVertexCoordinates[v];
        std::array<int, 3> y;
        for (int d = 0; d < 3; ++d) y[d] = ((signs >> d) & 1 ? -1 : 1) * x[axes[d]];
        pi[v] = vertex_at(y);
      }
      symmetries.push_back(pi);
    }
  } while (std::next_permutation(axes.begin(), axes.end()));
  return symmetries;
}

/// The element's node list renumbered by the symmetry pi (cube_symmetries()).
inline std::array<int, 8> renumbered(const std::array<int, 8>& nodes,
                                     const std::array<int, 8>& pi) {
  std::array<int, 8> out;
  for (int v = 0; v < 8; ++v) out[v] = nodes[pi[v]];
  return out;
}

/// A random permutation of n node indices.
inline std::vector<int> random_relabelling(int n, std::mt19937& rng) {
  std::vector<int> label(n);
  std::iota(label.begin(), label.end(), 0);
  std::shuffle(label.begin(), label.end(), rng);
  return label;
}

/// The elements with every node index replaced by label[index].
inline std::vector<std::array<int, 8>> relabelled(std::vector<std::array<int, 8>> hexes,
                                                  const std::vector<int>& label) {
  for (auto& h : hexes)
    for (int& v : h) v = label[v];
  return hexes;
}

}  // namespace hpcontact::hex_test
