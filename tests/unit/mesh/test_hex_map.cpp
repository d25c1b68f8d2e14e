// Property tests of the hexahedron's maps: interpolation, Gmsh's HEX27 order, Jacobians, and the
// refusal of inverted and degenerate elements.
#include "hpcontact/mesh/hex_map.hpp"

#include <gtest/gtest.h>

#include <array>
#include <random>
#include <string>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/core/error.hpp"

using namespace hpcontact;
using namespace hpcontact::mesh;

namespace {

/// A triquadratic vector field of (xi, eta, zeta) with every monomial xi^a eta^b zeta^c (a, b, c
/// <= 2) present, and its Jacobian.
Vec3 field(const Vec3& s, Mat3* J = nullptr) {
  auto mono = [](double t, int k, double* d) {
    if (d) *d = k == 0 ? 0 : k == 1 ? 1 : 2 * t;
    return k == 0 ? 1 : k == 1 ? t : t * t;
  };
  Vec3 x = Vec3::Zero();
  if (J) J->setZero();
  for (int a = 0; a <= 2; ++a)
    for (int b = 0; b <= 2; ++b)
      for (int c = 0; c <= 2; ++c) {
        const Vec3 coef(0.1 * (1 + a + 2 * b + 3 * c), -0.05 * (a * b + c + 1), 0.07 * (a + b * c - 2));
        double da, db, dc;
        const double fa = mono(s(0), a, &da), fb = mono(s(1), b, &db), fc = mono(s(2), c, &dc);
        x += fa * fb * fc * coef;
        if (J) {
          J->col(0) += da * fb * fc * coef;
          J->col(1) += fa * db * fc * coef;
          J->col(2) += fa * fb * dc * coef;
        }
      }
  return x;
}

std::array<Vec3, 8> unit_cube_vertices() {
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = Vec3(0.5 * (c[0] + 1), 0.5 * (c[1] + 1), 0.5 * (c[2] + 1));
  }
  return v;
}

std::string refusal(const HexMap& map, int element) {
  try {
    check_hex_jacobian(map, "block", element, 4);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The trilinear map shall interpolate its vertices and reproduce an affine map x = A xi + b and
// its Jacobian A at random points to 1e-15 (measured: 2e-16).
TEST(HexMap, TrilinearReproducesAffineMaps) {
  Mat3 A;
  A << 1.0, 0.2, -0.1, 0.3, 0.8, 0.05, -0.2, 0.1, 1.3;
  const Vec3 b(0.5, -1, 2);
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = A * Vec3(c[0], c[1], c[2]) + b;
  }
  const HexMap map = HexMap::trilinear(v);
  EXPECT_EQ(map.polynomial_degree(), 1);
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    EXPECT_LE((map.map(c[0], c[1], c[2]) - v[i]).norm(), 1e-15);
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 20; ++k) {
    const Vec3 s(u(rng), u(rng), u(rng));
    Mat3 J;
    const Vec3 x = map.map(s(0), s(1), s(2), &J);
    EXPECT_LE((x - (A * s + b)).norm(), 1e-15 * 4);
    EXPECT_LE((J - A).norm(), 1e-15 * 4);
  }
}

// kHex27Nodes shall follow Gmsh's HEX27 documentation: node 8 + e the midpoint of Gmsh's edge e
// (V0V1, V0V3, V0V4, V1V2, V1V5, V2V3, V2V6, V3V7, V4V5, V4V7, V5V6, V6V7), node 20 + f the
// centre of Gmsh's face f (0321, 0154, 0473, 1265, 2376, 4567), node 26 the centre.
TEST(HexMap, Hex27NodeOrderIsGmsh) {
  const int edges[12][2] = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                            {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  const int faces[6][4] = {{0, 3, 2, 1}, {0, 1, 5, 4}, {0, 4, 7, 3},
                           {1, 2, 6, 5}, {2, 3, 7, 6}, {4, 5, 6, 7}};
  for (int v = 0; v < 8; ++v)
    for (int d = 0; d < 3; ++d) EXPECT_EQ(kHex27Nodes[v][d], basis::kHexVertexCoordinates[v][d]);
  for (int e = 0; e < 12; ++e)
    for (int d = 0; d < 3; ++d)
      EXPECT_EQ(2 * kHex27Nodes[8 + e][d], basis::kHexVertexCoordinates[edges[e][0]][d] +
                                               basis::kHexVertexCoordinates[edges[e][1]][d])
          << "edge node " << 8 + e;
  for (int f = 0; f < 6; ++f)
    for (int d = 0; d < 3; ++d) {
      int sum = 0;
      for (int v : faces[f]) sum += basis::kHexVertexCoordinates[v][d];
      EXPECT_EQ(4 * kHex27Nodes[20 + f][d], sum) << "face node " << 20 + f;
    }
  for (int d = 0; d < 3; ++d) EXPECT_EQ(kHex27Nodes[26][d], 0);
}

// The triquadratic map of nodes placed on a triquadratic field shall reproduce that field and its
// Jacobian everywhere, to 1e-14 (measured: 4e-16); a wrong node order would not.
TEST(HexMap, TriquadraticReproducesTriquadraticFields) {
  std::array<Vec3, 27> nodes;
  for (int n = 0; n < 27; ++n)
    nodes[n] = field(Vec3(kHex27Nodes[n][0], kHex27Nodes[n][1], kHex27Nodes[n][2]));
  const HexMap map = HexMap::triquadratic(nodes);
  EXPECT_EQ(map.polynomial_degree(), 2);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 50; ++k) {
    const Vec3 s(u(rng), u(rng), u(rng));
    Mat3 J, J_exact;
    const Vec3 x = map.map(s(0), s(1), s(2), &J);
    const Vec3 x_exact = field(s, &J_exact);
    EXPECT_LE((x - x_exact).norm(), 1e-14);
    EXPECT_LE((J - J_exact).norm(), 1e-14);
  }
}

// A HEX27 whose mid-edge, mid-face and centre nodes sit at the trilinear positions shall be the
// trilinear map of its vertices, to 1e-15 (measured: 2e-16).
TEST(HexMap, StraightHex27IsTrilinear) {
  std::array<Vec3, 8> v = unit_cube_vertices();
  v[6] += Vec3(0.3, 0.2, 0.4);
  v[1] += Vec3(0.1, -0.2, 0.05);
  const HexMap tri = HexMap::trilinear(v);
  std::array<Vec3, 27> nodes;
  for (int n = 0; n < 27; ++n) nodes[n] = tri.map(kHex27Nodes[n][0], kHex27Nodes[n][1], kHex27Nodes[n][2]);
  const HexMap quad = HexMap::triquadratic(nodes);
  for (double xi : {-0.7, 0.1, 0.9})
    for (double eta : {-0.3, 0.5})
      for (double zeta : {-1.0, 0.25}) {
        Mat3 J1, J2;
        EXPECT_LE((tri.map(xi, eta, zeta, &J1) - quad.map(xi, eta, zeta, &J2)).norm(), 1e-15);
        EXPECT_LE((J1 - J2).norm(), 1e-15);
      }
}

// check_hex_jacobian shall accept a distorted and a curved hex, and refuse with a MeshError naming
// the context, the element and the reference point: a mirrored (inverted) hex, a flat one, one with
// a collapsed edge (det J = 0 only along that edge), and a curved one whose face node is pushed
// through the element.
TEST(HexMap, InvertedAndDegenerateHexesAreRefused) {
  std::array<Vec3, 8> good = unit_cube_vertices();
  good[6] += Vec3(0.3, 0.2, 0.4);
  good[3] += Vec3(-0.1, 0.2, 0.0);
  EXPECT_EQ(refusal(HexMap::trilinear(good), 0), "");

  std::array<Vec3, 8> mirrored = good;
  for (Vec3& x : mirrored) x.x() = -x.x();
  const std::string inverted = refusal(HexMap::trilinear(mirrored), 7);
  EXPECT_NE(inverted.find("block: element 7 has a negative Jacobian determinant"), std::string::npos)
      << inverted;
  EXPECT_NE(inverted.find("at (xi, eta, zeta) = ("), std::string::npos) << inverted;

  std::array<Vec3, 8> flat = good;
  for (Vec3& x : flat) x.z() = 0;
  const std::string flat_message = refusal(HexMap::trilinear(flat), 3);
  EXPECT_NE(flat_message.find("element 3 has a vanishing"), std::string::npos) << flat_message;

  std::array<Vec3, 8> collapsed = good;
  collapsed[6] = collapsed[7];  // the edge V7V6 shrinks to a point
  const std::string collapsed_message = refusal(HexMap::trilinear(collapsed), 4);
  EXPECT_NE(collapsed_message.find("element 4 has a vanishing"), std::string::npos)
      << collapsed_message;
  EXPECT_NE(collapsed_message.find("(xi, eta, zeta) = (1, 1, 1)"), std::string::npos)
      << collapsed_message;

  const HexMap tri = HexMap::trilinear(good);
  std::array<Vec3, 27> nodes;
  for (int n = 0; n < 27; ++n) nodes[n] = tri.map(kHex27Nodes[n][0], kHex27Nodes[n][1], kHex27Nodes[n][2]);
  nodes[25] += Vec3(0, 0, 0.2);  // a gently bulging top face is fine
  EXPECT_EQ(refusal(HexMap::triquadratic(nodes), 1), "");
  nodes[25] -= Vec3(0, 0, 3.0);  // pushed through the bottom face
  const std::string folded = refusal(HexMap::triquadratic(nodes), 2);
  EXPECT_NE(folded.find("element 2 has a negative"), std::string::npos) << folded;
}
