// Property tests of pressure and traction loads on hexahedron faces: closed surfaces carry no
// resultant, a box face carries p·area against its normal (a traction t: t·area, at the face's
// centroid), a spherical octant p·πR²/4 per axis.
#include "hpcontact/fem/hex_face_load.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "hpcontact/mesh/shell_octant.hpp"

using namespace hpcontact;
using namespace hpcontact::fem;
using mesh::Vec3;

namespace {

constexpr double pi = std::numbers::pi;

/// What Gauss quadrature with n points per direction resolves of the shell octant's rational face
/// integrands: measured 1.1e-6 at n = 5, a factor 23-24 less per added point down to round-off
/// at n = 11 (5e-15); asserted with a factor 20 and a floor of 4e-15.
double quadrature_tolerance(int n) { return std::max(2e-6 * std::pow(20.0, 5 - n), 4e-15); }

/// Resultant force of an element load vector: the vertex modes sum to 1, so Σ_v f_(c, v) = ∫ t_c.
Vec3 resultant(const Eigen::VectorXd& f, int n_modes) {
  Vec3 r = Vec3::Zero();
  for (int c = 0; c < 3; ++c)
    for (int v = 0; v < 8; ++v) r(c) += f(c * n_modes + v);
  return r;
}

Vec3 face_resultant(const basis::HierarchicHex& e, const mesh::HexMap& map, int lf, double p) {
  return resultant(hex_face_pressure_load(e, map, lf, p, hex_face_gauss_points(e, map, lf)),
                   e.n_modes());
}

}  // namespace

// A constant pressure on the six faces of a distorted trilinear hexahedron (warped faces) shall
// have no resultant to 1e-14 relative to p·area, for p = 1..4; on a blending element of the
// shell octant to quadrature accuracy (p + 4 points: quadrature_tolerance).
TEST(HexFaceLoad, ClosedSurfaceHasNoResultant) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = Vec3(c[0] + u(rng), c[1] + u(rng), c[2] + u(rng));
  }
  const mesh::HexMap warped = mesh::HexMap::trilinear(v);
  const auto shell = mesh::shell_octant_mesh(1, 2, 1);
  for (int p = 1; p <= 4; ++p) {
    const basis::HierarchicHex e = basis::hierarchic_hex({p, p, p}, basis::Space::tensor_product);
    Vec3 sum = Vec3::Zero(), blended = Vec3::Zero();
    for (int lf = 0; lf < 6; ++lf) {
      sum += face_resultant(e, warped, lf, 2.5);
      blended += face_resultant(e, shell.maps[1], lf, 2.5);
    }
    EXPECT_LE(sum.norm(), 1e-14 * 2.5 * 4) << "p = " << p;
    const int n = hex_face_gauss_points(e, shell.maps[1], 0);
    EXPECT_EQ(n, p + 4);
    EXPECT_LE(blended.norm(), quadrature_tolerance(n) * 2.5 * 2) << "p = " << p;
  }
}

// On each face of a box [0, 2] × [0, 3] × [0, 1.5] the resultant shall be −p·area·n (n the
// outward normal) to 1e-14 relative, and the modes that vanish on the face shall carry nothing.
TEST(HexFaceLoad, BoxFaceResultantIsPressureTimesArea) {
  const Vec3 size(2, 3, 1.5);
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = Vec3(c[0] > 0 ? size(0) : 0, c[1] > 0 ? size(1) : 0, c[2] > 0 ? size(2) : 0);
  }
  const mesh::HexMap box = mesh::HexMap::trilinear(v);
  const basis::HierarchicHex e = basis::hierarchic_hex({3, 4, 2}, basis::Space::tensor_product);
  const double p = 0.7;
  const auto modes = e.mode_indices();
  for (int lf = 0; lf < 6; ++lf) {
    const int axis = basis::kHexFaceNormalAxis[lf];
    const double area = size.prod() / size(axis);
    const Vec3 n = (lf % 2 ? 1.0 : -1.0) * Vec3::Unit(axis);
    const Eigen::VectorXd f = hex_face_pressure_load(e, box, lf, p, hex_face_gauss_points(e, box, lf));
    EXPECT_LE((resultant(f, e.n_modes()) + p * area * n).norm(), 1e-14 * p * area) << "face " << lf;
    // A mode vanishes on the face when its factor along the normal axis is not the linear one
    // that is 1 there (index 0 at -1, 1 at +1).
    for (int a = 0; a < e.n_modes(); ++a)
      if (modes[a][axis] != lf % 2)
        for (int c = 0; c < 3; ++c) EXPECT_EQ(f(c * e.n_modes() + a), 0.0) << "face " << lf;
  }
}

// On the outer spherical faces of the shell octant (three cubed-sphere patches, R = 2) the
// resultant shall be −p·πR²/4 along each axis, on the inner ones (a = 1, outward normal towards
// the centre) +p·πa²/4, to quadrature accuracy for p = 1..8 (p + 4 points per direction,
// quadrature_tolerance: 2e-6 at p = 1, round-off from p = 7 on).
TEST(HexFaceLoad, SphericalOctantResultant) {
  const double a = 1, b = 2, pressure = 1.3;
  const auto shell = mesh::shell_octant_mesh(a, b, 1);
  for (int p = 1; p <= 8; ++p) {
    const basis::HierarchicHex e = basis::hierarchic_hex({p, p, p}, basis::Space::tensor_product);
    Vec3 outer = Vec3::Zero(), inner = Vec3::Zero();
    for (const auto& [h, lf] : shell.face_sets.at("outer")) outer += face_resultant(e, shell.maps[h], lf, pressure);
    for (const auto& [h, lf] : shell.face_sets.at("inner")) inner += face_resultant(e, shell.maps[h], lf, pressure);
    const double exact_outer = pressure * pi * b * b / 4, exact_inner = pressure * pi * a * a / 4;
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(outer(c) / -exact_outer, 1, quadrature_tolerance(p + 4)) << "p = " << p << ", axis " << c;
      EXPECT_NEAR(inner(c) / exact_inner, 1, quadrature_tolerance(p + 4)) << "p = " << p << ", axis " << c;
    }
  }
}

// A traction t on each face of the box [0, 2] × [0, 3] × [0, 1.5] (p = (3, 4, 2)) shall have the
// resultant t·area and the moment ∫ x t dA = (t·area) ⊗ centroid (the vertex modes interpolate x
// on an affine element, so Σ_v x_v f_v = ∫ x t dA), to 1e-14 relative; with t = −p n it shall be
// the pressure load, entry by entry, to 1e-15.
TEST(HexFaceLoad, BoxFaceTractionResultantAndMoment) {
  const Vec3 size(2, 3, 1.5);
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = Vec3(c[0] > 0 ? size(0) : 0, c[1] > 0 ? size(1) : 0, c[2] > 0 ? size(2) : 0);
  }
  const mesh::HexMap box = mesh::HexMap::trilinear(v);
  const basis::HierarchicHex e = basis::hierarchic_hex({3, 4, 2}, basis::Space::tensor_product);
  const Vec3 t(0.4, -1.1, 0.25);
  const int n = e.n_modes();
  for (int lf = 0; lf < 6; ++lf) {
    const int axis = basis::kHexFaceNormalAxis[lf];
    const double area = size.prod() / size(axis);
    Vec3 centroid = 0.5 * size;
    centroid(axis) = lf % 2 ? size(axis) : 0;
    const int points = hex_face_gauss_points(e, box, lf);
    const Eigen::VectorXd f = hex_face_traction_load(e, box, lf, t, points);
    EXPECT_LE((resultant(f, n) - t * area).norm(), 1e-14 * t.norm() * area) << "face " << lf;
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();  // moment(k, c) = ∫ x_k t_c dA
    for (int c = 0; c < 3; ++c)
      for (int a = 0; a < 8; ++a) moment.col(c) += v[a] * f(c * n + a);
    EXPECT_LE((moment - area * centroid * t.transpose()).norm(), 1e-14 * t.norm() * area * size.norm())
        << "face " << lf;
    const Vec3 normal = (lf % 2 ? 1.0 : -1.0) * Vec3::Unit(axis);
    const Eigen::VectorXd pressure = hex_face_pressure_load(e, box, lf, 0.7, points);
    EXPECT_LE((hex_face_traction_load(e, box, lf, -0.7 * normal, points) - pressure).cwiseAbs().maxCoeff(),
              1e-15 * 0.7 * area)
        << "face " << lf;
  }
}

// A traction t on the shell octant's outer faces (R = 2, area πR²/2) shall have the resultant
// t·πR²/2, to quadrature accuracy for p = 1..8 (p + 4 points, quadrature_tolerance).
TEST(HexFaceLoad, SphericalOctantTractionResultant) {
  const double b = 2;
  const Vec3 t(0.3, 0.9, -0.6);
  const auto shell = mesh::shell_octant_mesh(1, b, 1);
  for (int p = 1; p <= 8; ++p) {
    const basis::HierarchicHex e = basis::hierarchic_hex({p, p, p}, basis::Space::tensor_product);
    Vec3 sum = Vec3::Zero();
    for (const auto& [h, lf] : shell.face_sets.at("outer"))
      sum += resultant(hex_face_traction_load(e, shell.maps[h], lf, t,
                                              hex_face_gauss_points(e, shell.maps[h], lf)),
                       e.n_modes());
    const Vec3 exact = t * pi * b * b / 2;
    EXPECT_LE((sum - exact).norm(), quadrature_tolerance(p + 4) * exact.norm()) << "p = " << p;
  }
}
