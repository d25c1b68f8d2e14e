// The sum-factorised hexahedron kernel against the reference (the six M_kl products of
// hex_elasticity.hpp): the same stiffness and body force for every space, degree, orientation
// and map.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/fem/hex_elasticity.hpp"
#include "hpcontact/fem/hex_element.hpp"
#include "hpcontact/fem/hex_factored_stiffness.hpp"
#include "hpcontact/fem/hex_values.hpp"
#include "hpcontact/mesh/hex_map.hpp"
#include "hpcontact/mesh/shell_octant.hpp"

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
  const double moves[8][3] = {{0.05, -0.1, 0.0}, {0.1, 0.05, -0.08}, {0.2, 0.15, 0.1},
                              {-0.1, 0.1, 0.05}, {0.0, -0.05, 0.1},  {-0.1, 0.0, 0.2},
                              {0.25, 0.2, 0.3},  {-0.05, 0.1, -0.1}};
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = Vec3(0.5 * (c[0] + 1) + moves[i][0], 0.5 * (c[1] + 1) + moves[i][1],
                0.5 * (c[2] + 1) + moves[i][2]);
  }
  return mesh::HexMap::trilinear(v);
}

/// A blending hexahedron with two spherical faces (the thick sphere's octant, radii 1 and 2).
mesh::HexMap blending_hex() { return mesh::shell_octant_mesh(1.0, 2.0, 1).maps[0]; }

/// Degrees (4, 6, 5) with lower edge and face degrees (the minimum rule) and reversed edges
/// and turned faces: every sign and every subset of the tensor products in use.
basis::HierarchicHex anisotropic(basis::Space space) {
  auto hex = basis::hierarchic_hex({4, 6, 5}, space);
  hex.edge_degree = {3, 6, 4, 2, 4, 5, 1, 6, 5, 3, 5, 4};
  hex.edge_reversed = {true, false, false, true,  false, true,
                       true, false, false, false, true,  true};
  hex.face_degree = {{{6, 4}, {3, 5}, {4, 5}, {2, 3}, {4, 6}, {3, 6}}};
  hex.face_orientation = {{{false, false, false},
                           {true, false, true},
                           {false, true, true},
                           {true, true, false},
                           {true, true, true},
                           {false, false, true}}};
  return hex;
}

/// max |A − B| / max |B|.
double max_relative(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  return (A - B).cwiseAbs().maxCoeff() / B.cwiseAbs().maxCoeff();
}

}  // namespace

// The factored stiffness and body force shall equal the reference kernel's to 1e-12 relative in
// the largest entry, and the stiffness be exactly symmetric, for p = 1..8 in the tensor and trunk
// spaces, anisotropic degrees (1, 3, 2), (5, 2, 7) and an element with minimum-rule edge and face
// degrees, reversed edges and turned faces, on a distorted trilinear hex and a blending hex with
// spherical faces (measured: ≤ 3e-15).
TEST(HexFactoredStiffness, EqualsTheReferenceKernel) {
  const material::LinearElastic m = steel();
  const Vec3 body_force(1.5, -2, 0.5);
  for (const bool blending : {false, true}) {
    const mesh::HexMap map = blending ? blending_hex() : distorted_hex();
    for (const auto space : {basis::Space::tensor_product, basis::Space::trunk}) {
      std::vector<basis::HierarchicHex> elements;
      for (int p = 1; p <= 8; ++p) elements.push_back(basis::hierarchic_hex({p, p, p}, space));
      elements.push_back(basis::hierarchic_hex({1, 3, 2}, space));
      elements.push_back(basis::hierarchic_hex({5, 2, 7}, space));
      elements.push_back(anisotropic(space));
      for (const basis::HierarchicHex& h : elements) {
        const std::string where = "p (" + std::to_string(h.p[0]) + ", " + std::to_string(h.p[1]) +
                                  ", " + std::to_string(h.p[2]) + ")" +
                                  (space == basis::Space::trunk ? " trunk" : " tensor") +
                                  (blending ? " blending" : " trilinear");
        const std::array<int, 3> n_points = fem::hex_gauss_points(h, map);
        const fem::HexValues v = fem::hex_values(h, map, n_points);
        const fem::HexGridGeometry g = fem::hex_grid_geometry(map, n_points);
        const Eigen::MatrixXd K = fem::hex_stiffness_factored(h, g, m);
        const Eigen::MatrixXd reference = fem::hex_stiffness(v, m);
        ASSERT_EQ(K.rows(), reference.rows()) << where;
        EXPECT_LE(max_relative(K, reference), 1e-12) << where;
        EXPECT_EQ((K - K.transpose()).cwiseAbs().maxCoeff(), 0.0) << where;
        EXPECT_LE(max_relative(fem::hex_body_force_factored(h, g, body_force),
                               fem::hex_body_force(v, body_force)),
                  1e-12)
            << where;
      }
    }
  }
}

// `automatic` shall pick sum factorisation where it was measured faster (BENCHMARKS.md, 3D
// element stiffness): on the trilinear hex the tensor space from p = 3 on, not at p = 1, 2, and
// not the trunk space up to p = 8 (whose few modes keep the products small); on the blending hex
// (p + 3 points per direction) the tensor space from p = 3 on. (Where the two were measured
// within 5 % of each other, the blending hex's tensor p = 2 and trunk p = 7, 8, either will do.)
TEST(HexFactoredStiffness, ChosenWhereItIsFaster) {
  for (const bool blending : {false, true}) {
    const mesh::HexMap map = blending ? blending_hex() : distorted_hex();
    for (int p = 1; p <= 8; ++p) {
      const auto tensor = basis::hierarchic_hex({p, p, p}, basis::Space::tensor_product);
      const auto trunk = basis::hierarchic_hex({p, p, p}, basis::Space::trunk);
      const auto tensor_kernel =
          fem::hex_stiffness_kernel(tensor, fem::hex_gauss_points(tensor, map));
      const auto trunk_kernel = fem::hex_stiffness_kernel(trunk, fem::hex_gauss_points(trunk, map));
      if (p >= 3)
        EXPECT_EQ(tensor_kernel, fem::HexStiffnessKernel::factored)
            << "tensor p " << p << " blending " << blending;
      if (!blending) {
        if (p <= 2) EXPECT_EQ(tensor_kernel, fem::HexStiffnessKernel::blocks) << "tensor p " << p;
        EXPECT_EQ(trunk_kernel, fem::HexStiffnessKernel::blocks) << "trunk p " << p;
      }
    }
  }
}
