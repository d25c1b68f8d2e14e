// Conformity of hexahedral hierarchic spaces: neighbours' fields agree on shared faces and edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../mesh/hex_test_meshes.hpp"
#include "hpcontact/fem/hex_dof_map.hpp"

using namespace hpcontact;

namespace {

using Point = std::array<double, 3>;

/// A point of the mesh given by weights on global nodes (a bilinear point of a face, or a linear
/// point of an edge); its reference coordinates in an element are the same weights on the
/// reference coordinates of the element's local vertices at those nodes (the faces and edges of
/// the reference cube are flat, so this is the element's own parametrisation of the point).
using NodeWeights = std::map<int, double>;

Point reference_point(const std::array<int, 8>& hex, const NodeWeights& weights) {
  Point x{0.0, 0.0, 0.0};
  for (const auto& [node, w] : weights) {
    const int v = static_cast<int>(std::find(hex.begin(), hex.end(), node) - hex.begin());
    EXPECT_LT(v, 8) << "node " << node << " not in the element";
    for (int d = 0; d < 3; ++d) x[d] += w * basis::kHexVertexCoordinates[v][d];
  }
  return x;
}

/// The field sum_m c[mode m] N_m of an element (its nodes and space) at a mesh point.
double field(const std::array<int, 8>& hex, const fem::HexElementSpace& es,
             const std::vector<double>& c, const NodeWeights& weights) {
  const Point x = reference_point(hex, weights);
  std::vector<double> N(es.n_modes());
  es.hierarchic.evaluate(x[0], x[1], x[2], N.data(), nullptr, nullptr, nullptr);
  double u = 0.0;
  for (int m = 0; m < es.n_modes(); ++m) u += c[es.modes[m]] * N[m];
  return u;
}

double field(const mesh::HexTopology& t, const fem::HexDofMap& d, const std::vector<double>& c,
             int h, const NodeWeights& weights) {
  return field(t.hex(h), d.element(h), c, weights);
}

/// Random coefficients in [-1, 1], one per global mode.
std::vector<double> random_coefficients(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<double> c(n);
  for (double& x : c) x = U(rng);
  return c;
}

/// Random points of face f as weights on its corners (bilinear in (u, v) over the corner cycle).
std::vector<NodeWeights> face_points(const mesh::HexTopology& t, int f, std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  const auto& v = t.face(f).vertices;
  std::vector<NodeWeights> points;
  for (int i = 0; i < n; ++i) {
    const double a = U(rng), b = U(rng);
    points.push_back({{v[0], (1 - a) * (1 - b) / 4},
                      {v[1], (1 + a) * (1 - b) / 4},
                      {v[2], (1 + a) * (1 + b) / 4},
                      {v[3], (1 - a) * (1 + b) / 4}});
  }
  return points;
}

/// Random points of the edge between nodes a and b.
std::vector<NodeWeights> edge_points(int a, int b, std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::vector<NodeWeights> points;
  for (int i = 0; i < n; ++i) {
    const double s = U(rng);
    points.push_back({{a, (1 - s) / 2}, {b, (1 + s) / 2}});
  }
  return points;
}

/// Largest difference between the fields of the elements sharing a face or an edge, over random
/// points of every interior face and every edge of two or more elements; random coefficients.
double largest_jump(const mesh::HexTopology& t, const fem::HexDofMap& d, std::mt19937& rng) {
  const auto c = random_coefficients(d.n_modes(), rng);
  double jump = 0.0;
  for (int f = 0; f < t.n_faces(); ++f) {
    const auto& face = t.face(f);
    if (face.on_boundary()) continue;
    for (const auto& x : face_points(t, f, rng, 6))
      jump = std::max(
          jump, std::abs(field(t, d, c, face.hexes[0], x) - field(t, d, c, face.hexes[1], x)));
  }
  std::vector<std::vector<int>> around(t.n_edges());
  for (int h = 0; h < t.n_hexes(); ++h)
    for (int le = 0; le < 12; ++le) around[t.hex_edge(h, le)].push_back(h);
  for (int e = 0; e < t.n_edges(); ++e) {
    if (around[e].size() < 2) continue;
    for (const auto& x : edge_points(t.edge(e).v0, t.edge(e).v1, rng, 4)) {
      const double u0 = field(t, d, c, around[e][0], x);
      for (std::size_t k = 1; k < around[e].size(); ++k)
        jump = std::max(jump, std::abs(u0 - field(t, d, c, around[e][k], x)));
    }
  }
  return jump;
}

struct DegreePair {
  std::array<int, 3> first, second;
};

/// The degree pairs of the two-element tests: uniform p = 1..6, 3 | 5, and anisotropic ones.
std::vector<DegreePair> degree_pairs() {
  std::vector<DegreePair> pairs;
  for (int p = 1; p <= 6; ++p) pairs.push_back({{p, p, p}, {p, p, p}});
  pairs.push_back({{3, 3, 3}, {5, 5, 5}});
  pairs.push_back({{5, 5, 5}, {3, 3, 3}});
  pairs.push_back({{2, 4, 6}, {5, 3, 2}});
  pairs.push_back({{6, 5, 4}, {4, 6, 5}});
  pairs.push_back({{3, 6, 2}, {6, 2, 5}});
  return pairs;
}

}  // namespace

// Two hexahedra sharing a face, the second renumbered by each of the 48 cube symmetries (and the
// first by a varying one), the nodes relabelled at random: with random global coefficients the two
// elements' fields shall agree at random points of the shared face and its edges to 1e-13, for
// uniform p = 1..6, degrees 3 | 5 and anisotropic pairs, tensor and trunk. Both elements' local
// faces shall meet the shared face in all 8 orientations along the way.
TEST(HexConformity, TwoElementsAgreeOnTheirFaceInEveryOrientation) {
  const auto block = hex_test::hex_block(2, 1, 1);
  const auto symmetries = hex_test::cube_symmetries();
  std::mt19937 rng(2024);
  std::set<std::array<bool, 3>> seen_first, seen_second;
  double worst = 0.0;
  for (std::size_t s = 0; s < symmetries.size(); ++s) {
    auto hexes = hex_test::relabelled(block.hexes, hex_test::random_relabelling(12, rng));
    hexes[0] = hex_test::renumbered(hexes[0], symmetries[(7 * s) % symmetries.size()]);
    hexes[1] = hex_test::renumbered(hexes[1], symmetries[s]);
    const mesh::HexTopology t(hexes, 12);
    int shared = -1;
    for (int f = 0; f < t.n_faces(); ++f)
      if (!t.face(f).on_boundary()) shared = f;
    ASSERT_GE(shared, 0);
    const auto& face = t.face(shared);
    for (int side = 0; side < 2; ++side) {
      const auto o = t.hex_face_orientation(face.hexes[side], face.local_face[side]);
      (face.hexes[side] == 0 ? seen_first : seen_second).insert({o.swap, o.flip1, o.flip2});
    }
    for (const auto& pair : degree_pairs())
      for (auto space : {basis::Space::tensor_product, basis::Space::trunk}) {
        fem::HexSpaceOptions o;
        o.space = space;
        o.degrees = {pair.first, pair.second};
        const fem::HexDofMap d(t, o);
        const double jump = largest_jump(t, d, rng);
        worst = std::max(worst, jump);
        EXPECT_LT(jump, 1e-13) << "symmetry " << s << ", degrees " << pair.first[0] << pair.first[1]
                               << pair.first[2] << " | " << pair.second[0] << pair.second[1]
                               << pair.second[2]
                               << (space == basis::Space::trunk ? ", trunk" : ", tensor");
      }
  }
  EXPECT_EQ(seen_first.size(), 8u);
  EXPECT_EQ(seen_second.size(), 8u);
  std::ostringstream measured;
  measured << std::scientific << worst;
  RecordProperty("largest_jump", measured.str());
}

// The check above shall be able to fail: with the shared face's orientation in one element
// changed to any of the 7 wrong ones, or a shared edge's reversal flipped, the two elements'
// fields on the shared face differ.
TEST(HexConformity, AWrongOrientationIsSeen) {
  const mesh::HexTopology t(hex_test::hex_block(2, 1, 1).hexes, 12);
  fem::HexSpaceOptions o;
  o.degrees = {{5, 4, 6}, {4, 5, 6}};
  const fem::HexDofMap d(t, o);
  std::mt19937 rng(1);
  ASSERT_LT(largest_jump(t, d, rng), 1e-13);
  const int shared = t.find_face({1, 4, 10, 7});
  ASSERT_EQ(t.face(shared).hexes, (std::array<int, 2>{0, 1}));
  const auto c = random_coefficients(d.n_modes(), rng);
  auto jump_with = [&](const fem::HexElementSpace& second) {
    double jump = 0.0;
    for (const auto& x : face_points(t, shared, rng, 10))
      jump = std::max(jump, std::abs(field(t, d, c, 0, x) - field(t.hex(1), second, c, x)));
    return jump;
  };
  EXPECT_LT(jump_with(d.element(1)), 1e-13);
  const int local = t.face(shared).local_face[1];
  for (int code = 1; code < 8; ++code) {
    fem::HexElementSpace wrong = d.element(1);
    wrong.hierarchic.face_orientation[local] = {(code & 1) != 0, (code & 2) != 0, (code & 4) != 0};
    EXPECT_GT(jump_with(wrong), 1e-3) << "orientation " << code;
  }
  fem::HexElementSpace wrong = d.element(1);
  wrong.hierarchic.edge_reversed[3] = !wrong.hierarchic.edge_reversed[3];  // E3: nodes 1 -> 4
  EXPECT_GT(jump_with(wrong), 1e-3) << "edge reversal";
}

// Four hexahedra around an edge (a 2×2×1 block), each renumbered by a random cube symmetry, the
// nodes relabelled at random and random anisotropic degrees 1..6: the fields shall agree on the
// central edge among all four elements, and on every interior face, to 1e-13; tensor and trunk.
TEST(HexConformity, FourElementsAgreeAroundAnEdge) {
  const auto block = hex_test::hex_block(2, 2, 1);
  const auto symmetries = hex_test::cube_symmetries();
  std::mt19937 rng(77);
  std::uniform_int_distribution<int> degree(1, 6);
  for (int trial = 0; trial < 60; ++trial) {
    const auto label = hex_test::random_relabelling(block.n_nodes(), rng);
    auto hexes = hex_test::relabelled(block.hexes, label);
    for (auto& h : hexes) h = hex_test::renumbered(h, symmetries[rng() % symmetries.size()]);
    const mesh::HexTopology t(hexes, block.n_nodes());
    // The central edge joins grid nodes (1, 1, 0) = 4 and (1, 1, 1) = 13.
    const int centre = t.find_edge(label[4], label[13]);
    ASSERT_GE(centre, 0);
    int around = 0;
    for (int h = 0; h < 4; ++h)
      for (int le = 0; le < 12; ++le) around += t.hex_edge(h, le) == centre;
    ASSERT_EQ(around, 4);
    fem::HexSpaceOptions o;
    o.space = trial % 2 ? basis::Space::trunk : basis::Space::tensor_product;
    for (int h = 0; h < 4; ++h) o.degrees.push_back({degree(rng), degree(rng), degree(rng)});
    if (trial < 4) o.degrees.assign(4, {6, 6, 6});  // the central edge at degree 6
    const fem::HexDofMap d(t, o);
    EXPECT_LT(largest_jump(t, d, rng), 1e-13) << "trial " << trial;
  }
}

// The whole 2×2×2 block with random element node orders, labels and degrees 1..5 shall be
// conforming across all its 12 interior faces and 30 shared edges.
TEST(HexConformity, BlockIsConforming) {
  const auto block = hex_test::hex_block(2, 2, 2);
  const auto symmetries = hex_test::cube_symmetries();
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> degree(1, 5);
  for (int trial = 0; trial < 10; ++trial) {
    auto hexes = hex_test::relabelled(block.hexes, hex_test::random_relabelling(27, rng));
    for (auto& h : hexes) h = hex_test::renumbered(h, symmetries[rng() % symmetries.size()]);
    const mesh::HexTopology t(hexes, 27);
    fem::HexSpaceOptions o;
    o.space = trial % 2 ? basis::Space::trunk : basis::Space::tensor_product;
    for (int h = 0; h < 8; ++h) o.degrees.push_back({degree(rng), degree(rng), degree(rng)});
    const fem::HexDofMap d(t, o);
    EXPECT_LT(largest_jump(t, d, rng), 1e-13) << "trial " << trial;
  }
}
