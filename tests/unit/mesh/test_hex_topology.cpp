// Unit tests of the hexahedral mesh topology: counts, global orientations, refused meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "hex_test_meshes.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/mesh/hex_topology.hpp"

using namespace hpcontact;

namespace {

/// Global coordinates (S, T) of a local face corner at local (s, t) under orientation o
/// (basis/hex_modes.hpp): S = ±(swap ? t : s), T = ±(swap ? s : t).
std::array<int, 2> global_face_coordinates(int s, int t, const basis::HexFaceOrientation& o) {
  return {(o.flip1 ? -1 : 1) * (o.swap ? t : s), (o.flip2 ? -1 : 1) * (o.swap ? s : t)};
}

/// Every edge runs from its smaller node to its larger; every element's local edge is that edge,
/// reversed exactly when its local start is the larger node. Every face lists its corners in the
/// global orientation rule's order; every element's local face maps onto them by its orientation.
void check_orientations(const mesh::HexTopology& t) {
  for (int e = 0; e < t.n_edges(); ++e) EXPECT_LT(t.edge(e).v0, t.edge(e).v1) << "edge " << e;
  for (int f = 0; f < t.n_faces(); ++f) {
    const auto& v = t.face(f).vertices;
    // The origin is the smallest corner, S runs to the smaller of its two neighbours (the
    // neighbours of the origin are vertices[1] and vertices[3]; vertices[2] is opposite).
    EXPECT_EQ(*std::min_element(v.begin(), v.end()), v[0]) << "face " << f;
    EXPECT_LT(v[1], v[3]) << "face " << f;
  }
  constexpr int kS[4] = {-1, 1, 1, -1}, kT[4] = {-1, -1, 1, 1};
  for (int h = 0; h < t.n_hexes(); ++h) {
    const auto& nodes = t.hex(h);
    for (int le = 0; le < 12; ++le) {
      const int a = nodes[basis::kHexEdgeVertices[le][0]],
                b = nodes[basis::kHexEdgeVertices[le][1]];
      const auto& edge = t.edge(t.hex_edge(h, le));
      EXPECT_EQ(std::minmax(a, b), std::minmax(edge.v0, edge.v1));
      EXPECT_EQ(t.hex_edge_reversed(h, le), a > b) << "element " << h << " edge " << le;
      EXPECT_EQ(t.find_edge(b, a), t.hex_edge(h, le));
    }
    for (int lf = 0; lf < 6; ++lf) {
      const int f = t.hex_face(h, lf);
      const auto& face = t.face(f);
      const auto o = t.hex_face_orientation(h, lf);
      std::array<int, 4> corners;
      for (int k = 0; k < 4; ++k) {
        corners[k] = nodes[basis::kHexFaceVertices[lf][k]];
        // The local corner at (s, t) sits at (S, T) in the face's global axes: the global corner
        // list holds it at the position of (S, T).
        const auto ST = global_face_coordinates(kS[k], kT[k], o);
        int position = -1;
        for (int g = 0; g < 4; ++g)
          if (kS[g] == ST[0] && kT[g] == ST[1]) position = g;
        EXPECT_EQ(face.vertices[position], corners[k])
            << "element " << h << " face " << lf << " corner " << k;
      }
      EXPECT_EQ(t.find_face(corners), f);
      const int side = face.hexes[0] == h ? 0 : 1;
      EXPECT_EQ(face.hexes[side], h);
      EXPECT_EQ(face.local_face[side], lf);
    }
  }
}

/// Number of elements around each edge.
std::vector<int> elements_per_edge(const mesh::HexTopology& t) {
  std::vector<int> count(t.n_edges(), 0);
  for (int h = 0; h < t.n_hexes(); ++h)
    for (int le = 0; le < 12; ++le) ++count[t.hex_edge(h, le)];
  return count;
}

/// Throws MeshError whose message contains `what`.
void expect_refused(const std::vector<std::array<int, 8>>& hexes, int n_nodes,
                    const std::string& what) {
  try {
    mesh::HexTopology t(hexes, n_nodes);
    ADD_FAILURE() << "no MeshError for " << what;
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

}  // namespace

// A 2×2×2 block shall have 27 nodes, 54 edges (24 with one element, 24 with two, 6 with four),
// 36 faces of which 24 on the boundary; V − E + F − C = 1 for the solid, V − E + F = 2 for its
// boundary surface, and 6C = 2F − F_boundary. The same with every element renumbered by a random
// cube symmetry and the nodes relabelled at random.
TEST(HexTopology, TwoByTwoByTwoBlockCounts) {
  const auto block = hex_test::hex_block(2, 2, 2);
  const auto symmetries = hex_test::cube_symmetries();
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    auto hexes = block.hexes;
    if (trial > 0) {
      hexes = hex_test::relabelled(hexes, hex_test::random_relabelling(block.n_nodes(), rng));
      for (auto& h : hexes) h = hex_test::renumbered(h, symmetries[rng() % symmetries.size()]);
    }
    const mesh::HexTopology t(hexes, block.n_nodes());
    EXPECT_EQ(t.n_nodes(), 27);
    EXPECT_EQ(t.n_hexes(), 8);
    EXPECT_EQ(t.n_edges(), 54);
    EXPECT_EQ(t.n_faces(), 36);
    const auto boundary = t.boundary_faces();
    EXPECT_EQ(boundary.size(), 24u);
    EXPECT_EQ(t.n_nodes() - t.n_edges() + t.n_faces() - t.n_hexes(), 1);
    EXPECT_EQ(6 * t.n_hexes(), 2 * t.n_faces() - static_cast<int>(boundary.size()));
    std::set<int> boundary_nodes;
    std::set<std::pair<int, int>> boundary_edges;
    for (int f : boundary) {
      const auto& v = t.face(f).vertices;
      EXPECT_EQ(t.face(f).hexes[1], -1);
      for (int k = 0; k < 4; ++k) {
        boundary_nodes.insert(v[k]);
        boundary_edges.insert(std::minmax(v[k], v[(k + 1) % 4]));
      }
    }
    EXPECT_EQ(boundary_nodes.size(), 26u);  // all but the centre
    EXPECT_EQ(boundary_edges.size(), 48u);
    EXPECT_EQ(static_cast<int>(boundary_nodes.size()) - static_cast<int>(boundary_edges.size()) +
                  static_cast<int>(boundary.size()),
              2);
    std::map<int, int> histogram;
    for (int c : elements_per_edge(t)) ++histogram[c];
    EXPECT_EQ(histogram, (std::map<int, int>{{1, 24}, {2, 24}, {4, 6}})) << "trial " << trial;
    check_orientations(t);
  }
}

// In the unpermuted block, neighbours along x shall meet on F1 of the left and F0 of the right
// element, along y on F3 / F2, along z on F5 / F4; the global face of F4 of element 0 shall be
// its bottom face with the corners (0, 1, 4, 3) in the rule's order.
TEST(HexTopology, NeighboursMeetOnOppositeLocalFaces) {
  const auto block = hex_test::hex_block(2, 2, 2);
  const mesh::HexTopology t(block.hexes, block.n_nodes());
  // Elements are numbered x fastest: element 0's neighbours are 1 (x), 2 (y), 4 (z).
  for (auto [other, face_here, face_there] :
       std::vector<std::array<int, 3>>{{1, 1, 0}, {2, 3, 2}, {4, 5, 4}}) {
    const int f = t.hex_face(0, face_here);
    EXPECT_EQ(t.hex_face(other, face_there), f);
    EXPECT_EQ(t.face(f).hexes, (std::array<int, 2>{0, other}));
    EXPECT_EQ(t.face(f).local_face, (std::array<int, 2>{face_here, face_there}));
  }
  EXPECT_EQ(t.face(t.hex_face(0, 4)).vertices, (std::array<int, 4>{0, 1, 4, 3}));
  EXPECT_TRUE(t.face(t.hex_face(0, 4)).on_boundary());
  check_orientations(t);
}

// Renumbering one element by each of the 48 cube symmetries, with random node labels, shall give
// its faces all 8 orientations and reverse edges both ways, always consistent with the rules.
TEST(HexTopology, EveryFaceOrientationOccurs) {
  const auto block = hex_test::hex_block(2, 1, 1);
  std::set<std::array<bool, 3>> orientations;
  std::set<bool> reversals;
  std::mt19937 rng(9);
  for (const auto& pi : hex_test::cube_symmetries())
    for (int trial = 0; trial < 3; ++trial) {
      auto hexes = hex_test::relabelled(block.hexes, hex_test::random_relabelling(12, rng));
      hexes[1] = hex_test::renumbered(hexes[1], pi);
      const mesh::HexTopology t(hexes, 12);
      EXPECT_EQ(t.n_faces(), 11);
      EXPECT_EQ(t.n_edges(), 20);
      EXPECT_EQ(t.boundary_faces().size(), 10u);
      for (int lf = 0; lf < 6; ++lf) {
        const auto o = t.hex_face_orientation(1, lf);
        orientations.insert({o.swap, o.flip1, o.flip2});
      }
      for (int le = 0; le < 12; ++le) reversals.insert(t.hex_edge_reversed(1, le));
      check_orientations(t);
    }
  EXPECT_EQ(orientations.size(), 8u);
  EXPECT_EQ(reversals.size(), 2u);
}

// An element with a repeated node shall be refused with a MeshError naming the element's index
// and the node; so shall a node index out of range, an element given twice, a face shared by
// three elements and two elements going round a face in different orders.
TEST(HexTopology, BadMeshesAreRefused) {
  auto hexes = hex_test::hex_block(2, 1, 1).hexes;  // nodes 0..11
  hexes.push_back({0, 1, 2, 3, 4, 5, 6, 6});
  expect_refused(hexes, 12, "element 2 has node 6 twice (as its vertices V6 and V7)");
  expect_refused({{0, 1, 2, 3, 4, 5, 6, 12}}, 12, "element 0 vertex V7 refers to node 12");
  expect_refused({{0, 1, 2, 3, 4, 5, 6, 7}, {4, 5, 6, 7, 0, 1, 2, 3}}, 8,
                 "elements 0 and 1 have the same nodes");
  // Elements 1 and 2 both stand on element 0's top face (nodes 4 5 6 7).
  expect_refused(
      {{0, 1, 2, 3, 4, 5, 6, 7}, {4, 5, 6, 7, 8, 9, 10, 11}, {4, 5, 6, 7, 12, 13, 14, 15}}, 16,
      "belongs to elements 0, 1 and 2");
  // Element 1's bottom goes 4 6 5 7: the same four nodes, another quadrilateral.
  expect_refused({{0, 1, 2, 3, 4, 5, 6, 7}, {4, 6, 5, 7, 8, 9, 10, 11}}, 12,
                 "elements 0 and 1 go round the face");
  expect_refused({}, 0, "no elements");
}
