// Property tests of the hexahedral mode numbering: counts, internal modes last, minimum rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <climits>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "../mesh/hex_test_meshes.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/hex_dof_map.hpp"

using namespace hpcontact;

namespace {

fem::HexSpaceOptions uniform(int p, int n_elements, basis::Space space) {
  fem::HexSpaceOptions o;
  o.space = space;
  o.degrees.assign(n_elements, {p, p, p});
  return o;
}

/// Face modes phi_i phi_j (i, j >= 2, i + j <= p) of the trunk space of degree p, by hand.
int trunk_face(int p) { return p < 4 ? 0 : (p - 2) * (p - 3) / 2; }
/// Internal modes phi_i phi_j phi_k (i, j, k >= 2, i + j + k <= p) of the trunk space.
int trunk_internal(int p) { return p < 6 ? 0 : (p - 3) * (p - 4) * (p - 5) / 6; }

/// The 2×2×2 block with every element renumbered by a random cube symmetry and random node
/// labels (trial 0: as built).
std::vector<std::array<int, 8>> shuffled_block(int trial) {
  auto block = hex_test::hex_block(2, 2, 2);
  if (trial == 0) return block.hexes;
  std::mt19937 rng(100 + trial);
  const auto symmetries = hex_test::cube_symmetries();
  auto hexes = hex_test::relabelled(block.hexes, hex_test::random_relabelling(27, rng));
  for (auto& h : hexes) h = hex_test::renumbered(h, symmetries[rng() % symmetries.size()]);
  return hexes;
}

/// Every global mode is used by some element; each element's modes are distinct, begin with its
/// nodes' vertex modes, and end with its n_internal own internal modes (index >= n_external),
/// numbered element by element after all external modes.
void check_numbering(const mesh::HexTopology& t, const fem::HexDofMap& d, const std::string& what) {
  std::vector<int> used(d.n_modes(), 0);
  int next_internal = d.n_external_modes();
  for (int h = 0; h < t.n_hexes(); ++h) {
    const auto& es = d.element(h);
    ASSERT_EQ(es.n_modes(), es.hierarchic.n_modes()) << what << " element " << h;
    EXPECT_EQ(es.n_internal, es.hierarchic.n_internal_modes()) << what;
    EXPECT_EQ(std::set<int>(es.modes.begin(), es.modes.end()).size(), es.modes.size()) << what;
    for (int v = 0; v < 8; ++v) EXPECT_EQ(es.modes[v], d.vertex_mode(t.hex(h)[v])) << what;
    for (int a = 0; a < es.n_modes(); ++a) {
      const int g = es.modes[a];
      ASSERT_GE(g, 0);
      ASSERT_LT(g, d.n_modes());
      ++used[g];
      const bool internal = a >= es.n_modes() - es.n_internal;
      EXPECT_EQ(internal, g >= d.n_external_modes()) << what << " element " << h << " mode " << a;
      if (internal) EXPECT_EQ(g, next_internal++) << what << " element " << h;
    }
  }
  EXPECT_EQ(next_internal, d.n_modes()) << what;
  for (int g = 0; g < d.n_modes(); ++g) EXPECT_GT(used[g], 0) << what << " mode " << g;
  EXPECT_EQ(d.n_dofs(), 3 * d.n_modes());
}

}  // namespace

// On a 2×2×2 block of uniform degree p the tensor-product space shall have (2p + 1)^3 modes:
// 27 vertex, 54(p−1) edge, 36(p−1)^2 face and 8(p−1)^3 internal, p = 1..5, whatever the
// elements' node orders and the node labels.
TEST(HexDofMap, TensorProductCountsOnBlock) {
  for (int trial = 0; trial < 4; ++trial) {
    const mesh::HexTopology t(shuffled_block(trial), 27);
    for (int p = 1; p <= 5; ++p) {
      const fem::HexDofMap d(t, uniform(p, 8, basis::Space::tensor_product));
      const int q = p - 1;
      EXPECT_EQ(d.n_external_modes(), 27 + 54 * q + 36 * q * q) << "p = " << p;
      EXPECT_EQ(d.n_modes(), (2 * p + 1) * (2 * p + 1) * (2 * p + 1)) << "p = " << p;
      EXPECT_EQ(d.n_modes(), 27 + 54 * q + 36 * q * q + 8 * q * q * q);
      for (int e = 0; e < t.n_edges(); ++e) EXPECT_EQ(d.edge_degree(e), p);
      for (int f = 0; f < t.n_faces(); ++f) EXPECT_EQ(d.face_degree(f), (std::array<int, 2>{p, p}));
      check_numbering(t, d, "tensor p = " + std::to_string(p) + ", trial " + std::to_string(trial));
    }
  }
}

// The trunk space on the 2×2×2 block shall have 27 + 54(p−1) + 36 (p−2)(p−3)/2 [p >= 4]
// + 8 (p−3)(p−4)(p−5)/6 [p >= 6] modes, p = 1..7.
TEST(HexDofMap, TrunkCountsOnBlock) {
  for (int trial = 0; trial < 3; ++trial) {
    const mesh::HexTopology t(shuffled_block(trial), 27);
    for (int p = 1; p <= 7; ++p) {
      const fem::HexDofMap d(t, uniform(p, 8, basis::Space::trunk));
      EXPECT_EQ(d.n_external_modes(), 27 + 54 * (p - 1) + 36 * trunk_face(p)) << "p = " << p;
      EXPECT_EQ(d.n_modes(), 27 + 54 * (p - 1) + 36 * trunk_face(p) + 8 * trunk_internal(p));
      for (int h = 0; h < 8; ++h) EXPECT_EQ(d.element(h).n_internal, trunk_internal(p));
      check_numbering(t, d, "trunk p = " + std::to_string(p) + ", trial " + std::to_string(trial));
    }
  }
}

// Two elements of degrees 3 and 5 shall share a face of degrees (3, 3) and its four edges of
// degree 3, the other edges of the degree-5 element keeping 5; by hand on a 2×1×1 block, an
// anisotropic pair (2, 4, 6) | (5, 3, 2) shall share the face x = 1 with global axes (y, z)
// (its smallest node 1 has neighbours 4 along y and 7 along z) of degrees (3, 2).
TEST(HexDofMap, MinimumRuleByHand) {
  const auto block = hex_test::hex_block(2, 1, 1);  // node (i, j, k) = i + 3 (j + 2 k)
  const mesh::HexTopology t(block.hexes, 12);
  const int shared = t.find_face({1, 4, 10, 7});
  ASSERT_GE(shared, 0);
  EXPECT_EQ(t.face(shared).vertices, (std::array<int, 4>{1, 4, 10, 7}));

  fem::HexSpaceOptions o;
  o.degrees = {{3, 3, 3}, {5, 5, 5}};
  const fem::HexDofMap d(t, o);
  EXPECT_EQ(d.face_degree(shared), (std::array<int, 2>{3, 3}));
  EXPECT_EQ(d.n_face_modes(shared), 4);
  for (auto [a, b] : std::vector<std::array<int, 2>>{{1, 4}, {4, 10}, {7, 10}, {1, 7}})
    EXPECT_EQ(d.edge_degree(t.find_edge(a, b)), 3) << a << "-" << b;
  for (auto [a, b] : std::vector<std::array<int, 2>>{{1, 2}, {2, 5}, {11, 8}, {5, 11}})
    EXPECT_EQ(d.edge_degree(t.find_edge(a, b)), 5) << a << "-" << b;
  // 12 vertex; edges: 8 of element 0 alone (2 each), 4 shared (2 each), 8 of element 1 (4 each);
  // faces: 5 of element 0 (4 each), the shared one (4), 5 of element 1 (16 each); 8 + 64 internal.
  EXPECT_EQ(d.n_modes(), 12 + (8 * 2 + 4 * 2 + 8 * 4) + (5 * 4 + 4 + 5 * 16) + 8 + 64);
  check_numbering(t, d, "3 | 5");

  o.degrees = {{2, 4, 6}, {5, 3, 2}};
  const fem::HexDofMap a(t, o);
  EXPECT_EQ(a.face_degree(shared), (std::array<int, 2>{3, 2}));
  EXPECT_EQ(a.edge_degree(t.find_edge(1, 4)), 3);  // along y: min(4, 3)
  EXPECT_EQ(a.edge_degree(t.find_edge(7, 10)), 3);
  EXPECT_EQ(a.edge_degree(t.find_edge(1, 7)), 2);  // along z: min(6, 2)
  EXPECT_EQ(a.edge_degree(t.find_edge(0, 1)), 2);  // along x, element 0 only
  EXPECT_EQ(a.edge_degree(t.find_edge(1, 2)), 5);  // along x, element 1 only
  EXPECT_EQ(a.edge_degree(t.find_edge(0, 6)), 6);  // along z, element 0 only
  // Element 1 sees the shared face (its F0, axes (eta, zeta) = (y, z), identity) at (3, 2).
  EXPECT_EQ(a.element(1).hierarchic.face_degree[0], (std::array<int, 2>{3, 2}));
  EXPECT_EQ(a.element(0).hierarchic.face_degree[1], (std::array<int, 2>{3, 2}));
  check_numbering(t, a, "anisotropic");
}

// Minimum rule on a 2×2×1 block whose elements have random node orders, node labels and
// anisotropic degrees: every edge's degree shall be the smallest degree along its direction in
// the grid among the elements holding it, every face's degrees the smaller along the grid
// directions of its global axes (read from the nodes' grid positions, not from orientations);
// each element's HierarchicHex shall carry them, in its local face axes, and evaluate.
TEST(HexDofMap, MinimumRuleFollowsGridDirections) {
  const auto block = hex_test::hex_block(2, 2, 1);
  const auto symmetries = hex_test::cube_symmetries();
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> degree(1, 6);
  for (int trial = 0; trial < 40; ++trial) {
    const auto label = hex_test::random_relabelling(block.n_nodes(), rng);
    std::vector<std::array<int, 3>> position(block.n_nodes());
    for (int n = 0; n < block.n_nodes(); ++n) position[label[n]] = block.positions[n];
    auto hexes = hex_test::relabelled(block.hexes, label);
    for (auto& h : hexes) h = hex_test::renumbered(h, symmetries[rng() % symmetries.size()]);
    const mesh::HexTopology t(hexes, block.n_nodes());
    fem::HexSpaceOptions o;
    o.space = trial % 2 ? basis::Space::trunk : basis::Space::tensor_product;
    for (int h = 0; h < t.n_hexes(); ++h)
      o.degrees.push_back({degree(rng), degree(rng), degree(rng)});
    const fem::HexDofMap d(t, o);

    auto direction = [&](int a, int b) {  // grid axis along which nodes a and b differ
      for (int g = 0; g < 3; ++g)
        if (position[a][g] != position[b][g]) return g;
      return -1;
    };
    // Each element's degree along each grid axis: its local axis d runs from V0 to V1 (xi),
    // V3 (eta), V4 (zeta).
    std::vector<std::array<int, 3>> along(t.n_hexes());
    for (int h = 0; h < t.n_hexes(); ++h) {
      const auto& v = t.hex(h);
      along[h][direction(v[0], v[1])] = o.degrees[h][0];
      along[h][direction(v[0], v[3])] = o.degrees[h][1];
      along[h][direction(v[0], v[4])] = o.degrees[h][2];
    }
    for (int e = 0; e < t.n_edges(); ++e) {
      const int g = direction(t.edge(e).v0, t.edge(e).v1);
      int expected = INT_MAX;
      for (int h = 0; h < t.n_hexes(); ++h)
        for (int le = 0; le < 12; ++le)
          if (t.hex_edge(h, le) == e) expected = std::min(expected, along[h][g]);
      EXPECT_EQ(d.edge_degree(e), expected) << "trial " << trial << " edge " << e;
    }
    for (int f = 0; f < t.n_faces(); ++f) {
      const auto& face = t.face(f);
      const int g_S = direction(face.vertices[0], face.vertices[1]);
      const int g_T = direction(face.vertices[0], face.vertices[3]);
      std::array<int, 2> expected{INT_MAX, INT_MAX};
      for (int side = 0; side < 2; ++side) {
        if (face.hexes[side] < 0) continue;
        expected[0] = std::min(expected[0], along[face.hexes[side]][g_S]);
        expected[1] = std::min(expected[1], along[face.hexes[side]][g_T]);
      }
      EXPECT_EQ(d.face_degree(f), expected) << "trial " << trial << " face " << f;
    }
    for (int h = 0; h < t.n_hexes(); ++h) {
      const auto& hex = d.element(h).hierarchic;
      for (int lf = 0; lf < 6; ++lf) {
        const auto o_f = t.hex_face_orientation(h, lf);
        EXPECT_EQ(hex.face_orientation[lf], o_f);
        const auto& global = d.face_degree(t.hex_face(h, lf));
        EXPECT_EQ(hex.face_degree[lf][o_f.swap ? 1 : 0], global[0]);
        EXPECT_EQ(hex.face_degree[lf][o_f.swap ? 0 : 1], global[1]);
      }
      for (int le = 0; le < 12; ++le) EXPECT_EQ(hex.edge_reversed[le], t.hex_edge_reversed(h, le));
      std::vector<double> N(hex.n_modes());
      EXPECT_NO_THROW(hex.evaluate(0.1, 0.2, 0.3, N.data(), nullptr, nullptr, nullptr));
    }
    check_numbering(t, d, "trial " + std::to_string(trial));
  }
}

// Missing or non-positive degrees shall be InputErrors naming the element.
TEST(HexDofMap, BadDegreesAreRejected) {
  const mesh::HexTopology t(hex_test::hex_block(2, 1, 1).hexes, 12);
  fem::HexSpaceOptions o;
  o.degrees = {{2, 2, 2}};
  EXPECT_THROW(fem::HexDofMap(t, o), InputError);
  o.degrees = {{2, 2, 2}, {2, 0, 2}};
  try {
    fem::HexDofMap d(t, o);
    ADD_FAILURE() << "no InputError for degree 0";
  } catch (const InputError& e) {
    EXPECT_NE(
        std::string(e.what()).find("element 1: polynomial degrees must be >= 1 (got 2, 0, 2)"),
        std::string::npos)
        << e.what();
  }
}

// modes_on_face is what a condition on a face constrains: on the shuffled 2×2×2 block (tensor
// p = 3, trunk p = 5), for every element and local face, the modes non-zero at a point inside
// the face (the element's own basis evaluated there) are exactly modes_on_face of its global
// face: (p + 1)² of them for the tensor space, none internal.
TEST(HexDofMap, ModesOnAFaceAreThoseNonZeroOnIt) {
  for (const auto& [p, space] : {std::pair{3, basis::Space::tensor_product}, std::pair{5, basis::Space::trunk}}) {
    const mesh::HexTopology t(shuffled_block(3), 27);
    const fem::HexDofMap d(t, uniform(p, t.n_hexes(), space));
    for (int h = 0; h < t.n_hexes(); ++h) {
      const auto& es = d.element(h);
      std::vector<double> N(es.n_modes());
      for (int lf = 0; lf < 6; ++lf) {
        const auto on_face = d.modes_on_face(t, t.hex_face(h, lf));
        const std::set<int> expected(on_face.begin(), on_face.end());
        ASSERT_EQ(expected.size(), on_face.size()) << "a mode listed twice";
        if (space == basis::Space::tensor_product) EXPECT_EQ(static_cast<int>(on_face.size()), (p + 1) * (p + 1));
        std::array<double, 3> xi{0.31, -0.47, 0.23};
        xi[basis::kHexFaceNormalAxis[lf]] = lf % 2 == 0 ? -1.0 : 1.0;
        es.hierarchic.evaluate(xi[0], xi[1], xi[2], N.data(), nullptr, nullptr, nullptr);
        std::set<int> nonzero;
        for (int a = 0; a < es.n_modes(); ++a)
          if (std::abs(N[a]) > 1e-12) nonzero.insert(es.modes[a]);
        EXPECT_EQ(nonzero, expected) << "element " << h << " face " << lf << " p " << p;
        for (int m : on_face) EXPECT_LT(m, d.n_external_modes());
      }
    }
  }
}
