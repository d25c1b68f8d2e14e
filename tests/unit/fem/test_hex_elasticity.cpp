// Property tests of the hexahedron's element stiffness: the block kernel against Bᵀ D B,
// symmetry, the rigid-body null space and its dimension.
#include "hpcontact/fem/hex_elasticity.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <string>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/fem/hex_values.hpp"
#include "hpcontact/mesh/hex_map.hpp"

using namespace hpcontact;
using mesh::Vec3;

namespace {

material::LinearElastic steel() {
  material::LinearElastic m;
  m.youngs_modulus = 210000;
  m.poisson_ratio = 0.3;
  return m;
}

/// A straight-sided hex with no parallel faces: a unit cube with its vertices moved.
mesh::HexMap distorted_hex() {
  std::array<Vec3, 8> v;
  const double moves[8][3] = {{0.05, -0.1, 0.0},  {0.1, 0.05, -0.08}, {0.2, 0.15, 0.1},
                              {-0.1, 0.1, 0.05},  {0.0, -0.05, 0.1},  {-0.1, 0.0, 0.2},
                              {0.25, 0.2, 0.3},   {-0.05, 0.1, -0.1}};
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = Vec3(0.5 * (c[0] + 1) + moves[i][0], 0.5 * (c[1] + 1) + moves[i][1],
                0.5 * (c[2] + 1) + moves[i][2]);
  }
  return mesh::HexMap::trilinear(v);
}

/// The distorted hex with its mid-edge, mid-face and centre nodes moved off the straight places.
mesh::HexMap curved_hex() {
  const mesh::HexMap straight = distorted_hex();
  std::array<Vec3, 27> nodes;
  for (int n = 0; n < 27; ++n) {
    const auto* c = mesh::kHex27Nodes[n];
    nodes[n] = straight.map(c[0], c[1], c[2]);
    if (n >= 8) nodes[n] += 0.06 * Vec3(std::sin(3.0 * n), std::cos(2.0 * n), std::sin(n + 1.0));
  }
  return mesh::HexMap::triquadratic(nodes);
}

/// Component-blocked coefficients of the six rigid motions (columns) on one element whose map is
/// of degree <= the element's: projected on the element space (the motion x ↦ c + ω × x(ξ) is a
/// polynomial of the map's degree in ξ, so it lies in the space and the projection is exact).
Eigen::MatrixXd rigid_motions(const fem::HexValues& v) {
  const int n = v.n_modes();
  const Eigen::MatrixXd M = v.N * v.JxW.asDiagonal() * v.N.transpose();
  Eigen::MatrixXd values(v.n_points(), 18);  // motion r, component i at column 3 r + i
  for (int q = 0; q < v.n_points(); ++q)
    for (int r = 0; r < 6; ++r) {
      Vec3 u = Vec3::Zero();
      if (r < 3) u(r) = 1;
      else u = Vec3::Unit(r - 3).cross(v.x[q]);
      for (int i = 0; i < 3; ++i) values(q, 3 * r + i) = u(i);
    }
  const Eigen::MatrixXd c = M.ldlt().solve(v.N * v.JxW.asDiagonal() * values);
  Eigen::MatrixXd R(3 * n, 6);
  for (int r = 0; r < 6; ++r)
    for (int i = 0; i < 3; ++i) R.col(r).segment(i * n, n) = c.col(3 * r + i);
  return R;
}

}  // namespace

// The block kernel shall equal the plain ∫ Bᵀ D3 B with D3 the 3D law, on a curved element at
// p = (2, 3, 1) tensor and p = 4 trunk, to 1e-13 relative (measured: 6e-16).
TEST(HexStiffness, BlockKernelIsBtDB) {
  const material::LinearElastic m = steel();
  const material::Elasticity3 D = m.D3();
  for (auto [p, space] : {std::pair{std::array<int, 3>{2, 3, 1}, basis::Space::tensor_product},
                          std::pair{std::array<int, 3>{4, 4, 4}, basis::Space::trunk}}) {
    const basis::HierarchicHex h = basis::hierarchic_hex(p, space);
    const mesh::HexMap map = curved_hex();
    const fem::HexValues v = fem::hex_values(h, map, fem::hex_gauss_points(h, map));
    const int n = v.n_modes();
    Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (int q = 0; q < v.n_points(); ++q) {
      Eigen::MatrixXd B = Eigen::MatrixXd::Zero(6, 3 * n);
      for (int a = 0; a < n; ++a) {
        const double dx = v.dN_dx(a, q), dy = v.dN_dy(a, q), dz = v.dN_dz(a, q);
        B(0, a) = dx;
        B(1, n + a) = dy;
        B(2, 2 * n + a) = dz;
        B(3, n + a) = dz;
        B(3, 2 * n + a) = dy;
        B(4, a) = dz;
        B(4, 2 * n + a) = dx;
        B(5, a) = dy;
        B(5, n + a) = dx;
      }
      reference += v.JxW(q) * B.transpose() * D * B;
    }
    const Eigen::MatrixXd K = fem::hex_stiffness(v, m);
    EXPECT_LE((K - reference).norm(), 1e-13 * reference.norm()) << "p " << p[0] << p[1] << p[2];
  }
}

// A free element's K shall be symmetric (exactly: its blocks are built so) and positive
// semi-definite with exactly 6 zero eigenvalues (the rigid motions) at p = 1, 2, 3, tensor and
// trunk, on the distorted straight hex; on the curved hex the same with tensor p = 2, 3, while
// p = 1 and the trunk spaces p = 2, 3 (which lack ξ²η²ζ²) have only the 3 translations. Zero
// means below 1e-12 of the largest eigenvalue (measured: ≤ 2e-16); the next one is above 1e-6 of
// it (measured: ≥ 2e-4).
TEST(HexStiffness, SymmetricWithRigidNullSpace) {
  for (bool curved : {false, true})
    for (auto space : {basis::Space::tensor_product, basis::Space::trunk})
      for (int p = 1; p <= 3; ++p) {
        const basis::HierarchicHex h = basis::hierarchic_hex({p, p, p}, space);
        const mesh::HexMap map = curved ? curved_hex() : distorted_hex();
        const fem::HexValues v = fem::hex_values(h, map, fem::hex_gauss_points(h, map));
        const Eigen::MatrixXd K = fem::hex_stiffness(v, steel());
        EXPECT_EQ((K - K.transpose()).norm(), 0.0);
        const Eigen::VectorXd e = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(K).eigenvalues();
        const double largest = e(e.size() - 1);
        const bool rotations_in_space =
            !curved || (p >= 2 && space == basis::Space::tensor_product);
        const int n_zero = rotations_in_space ? 6 : 3;
        const std::string where = "p " + std::to_string(p) + " curved " + std::to_string(curved) +
                                  (space == basis::Space::trunk ? " trunk" : " tensor");
        for (int k = 0; k < n_zero; ++k) EXPECT_LE(std::abs(e(k)), 1e-12 * largest) << where;
        EXPECT_GT(e(n_zero), 1e-6 * largest) << where;
      }
}

// K shall annihilate the 6 rigid motions: |K r| ≤ 1e-13 |K| |r| (measured: 4e-15 straight,
// 8e-15 curved, the projection's round-off included) at p = 1..4 on the straight hex and p = 2..4 on the curved one (whose rigid
// motions are triquadratic in ξ), tensor space.
TEST(HexStiffness, RigidMotionsAreInTheNullSpace) {
  for (bool curved : {false, true})
    for (int p = curved ? 2 : 1; p <= 4; ++p) {
      const basis::HierarchicHex h = basis::hierarchic_hex({p, p, p}, basis::Space::tensor_product);
      const mesh::HexMap map = curved ? curved_hex() : distorted_hex();
      const fem::HexValues v = fem::hex_values(h, map, fem::hex_gauss_points(h, map));
      const Eigen::MatrixXd K = fem::hex_stiffness(v, steel());
      const Eigen::MatrixXd R = rigid_motions(v);
      for (int r = 0; r < 6; ++r) {
        EXPECT_LE((K * R.col(r)).norm(), 1e-13 * K.norm() * R.col(r).norm())
            << "p " << p << " curved " << curved << " motion " << r;
      }
    }
}

// The body force's vertex entries shall sum to b × volume (the 8 vertex modes sum to 1), to 1e-14 relative (measured: 4e-16).
TEST(HexStiffness, BodyForceSumsToTheTotalForce) {
  const basis::HierarchicHex h = basis::hierarchic_hex({3, 3, 3}, basis::Space::tensor_product);
  const mesh::HexMap map = curved_hex();
  const fem::HexValues v = fem::hex_values(h, map, fem::hex_gauss_points(h, map));
  const Vec3 b(1.5, -2, 0.5);
  const Eigen::VectorXd f = fem::hex_body_force(v, b);
  const double volume = v.JxW.sum();
  const int n = v.n_modes();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(f.segment(i * n, 8).sum(), b(i) * volume, 1e-14 * std::abs(b(i) * volume));
  }
}
