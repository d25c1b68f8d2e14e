// Property tests of the blending (Gordon–Hall) hexahedron: the trilinear limit, exact faces and
// edges on their surfaces, shared faces, the Jacobian, volumes and areas of a shell octant, and
// the refusal of inconsistent surfaces.
#include "hpcontact/geometry/blending_hex.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/geometry/blending.hpp"
#include "hpcontact/mesh/hex_map.hpp"
#include "hpcontact/mesh/shell_octant.hpp"

using namespace hpcontact;
using mesh::Mat3;
using mesh::Vec3;

namespace {

constexpr double pi = std::numbers::pi;

/// Reference point of local face f at its local coordinates (s, t).
Vec3 face_point(int f, double s, double t) {
  Vec3 r;
  r(basis::kHexFaceNormalAxis[f]) = f % 2 ? 1 : -1;
  r(basis::kHexFaceAxes[f][0]) = s;
  r(basis::kHexFaceAxes[f][1]) = t;
  return r;
}

/// ∫ f over the reference cube's image, n points per direction.
template <class F>
double integrate(const mesh::HexMap& map, int n, F&& f) {
  const auto& g = basis::gauss_legendre(n);
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        Mat3 J;
        const Vec3 x = map.map(g.points[i], g.points[j], g.points[k], &J);
        sum += g.weights[i] * g.weights[j] * g.weights[k] * J.determinant() * f(x);
      }
  return sum;
}

}  // namespace

// Without surfaces the blending map shall be the trilinear map of its vertices (the Boolean sum
// reproduces it), with the same Jacobian, to 1e-14.
TEST(BlendingHex, WithoutSurfacesIsTrilinear) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 0.2), r(-1, 1);
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) {
    const auto* c = basis::kHexVertexCoordinates[i];
    v[i] = Vec3(c[0] + u(rng), 0.7 * c[1] + u(rng), 1.3 * c[2] + u(rng));
  }
  const mesh::HexMap blend = mesh::HexMap::blending(geometry::blending_hex(v, {}));
  const mesh::HexMap tri = mesh::HexMap::trilinear(v);
  EXPECT_EQ(blend.kind(), mesh::HexMapKind::blending);
  for (int k = 0; k < 30; ++k) {
    const double xi = r(rng), eta = r(rng), zeta = r(rng);
    Mat3 Jb, Jt;
    EXPECT_LE((blend.map(xi, eta, zeta, &Jb) - tri.map(xi, eta, zeta, &Jt)).norm(), 1e-14);
    EXPECT_LE((Jb - Jt).norm(), 1e-14);
  }
}

// Every face of the shell octant's elements shall lie on its sphere or plane (inner, outer,
// symmetry planes), and every point of an edge on all its faces' surfaces, to 1e-14 (relative).
TEST(BlendingHex, ShellOctantFacesLieOnTheirSurfaces) {
  const double a = 1, b = 2;
  const auto m = mesh::shell_octant_mesh(a, b, 2);
  ASSERT_EQ(m.topology.n_hexes(), 6);
  const char* plane[3] = {"x0", "y0", "z0"};
  EXPECT_EQ(m.face_sets.size(), 5u);
  EXPECT_EQ(m.face_sets.at("inner").size(), 3u);
  EXPECT_EQ(m.face_sets.at("outer").size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(m.face_sets.at(plane[i]).size(), 4u);  // 2 patches × 2 layers
  const std::vector<double> grid{-1, -0.6, -0.1, 0.35, 0.8, 1};
  for (const auto& [h, f] : m.face_sets.at("inner"))
    for (double s : grid)
      for (double t : grid) {
        const Vec3 r = face_point(f, s, t);
        EXPECT_NEAR(m.maps[h].map(r(0), r(1), r(2)).norm(), a, 1e-14);
      }
  for (const auto& [h, f] : m.face_sets.at("outer"))
    for (double s : grid)
      for (double t : grid) {
        const Vec3 r = face_point(f, s, t);
        EXPECT_NEAR(m.maps[h].map(r(0), r(1), r(2)).norm(), b, 2e-14);
      }
  for (int i = 0; i < 3; ++i)
    for (const auto& [h, f] : m.face_sets.at(plane[i]))
      for (double s : grid)
        for (double t : grid) {
          const Vec3 r = face_point(f, s, t);
          EXPECT_LE(std::abs(m.maps[h].map(r(0), r(1), r(2))(i)), 1e-15);
        }
  // The middle sphere (between the two layers) from the elements on either side.
  for (int h = 0; h < 6; ++h)
    for (double s : grid)
      for (double t : grid) {
        const int f = h % 2 == 0 ? 5 : 4;
        const Vec3 r = face_point(f, s, t);
        EXPECT_NEAR(m.maps[h].map(r(0), r(1), r(2)).norm(), 1.5, 1e-14);
      }
}

// Two elements that share a face shall map it onto the same point set: each image point of one
// side is found among the other side's images on a grid symmetric under the square's symmetries,
// to 1e-14.
TEST(BlendingHex, NeighboursShareTheirFaces) {
  const auto m = mesh::shell_octant_mesh(1, 2, 2);
  const std::vector<double> grid{-1, -0.7, -0.2, 0.2, 0.7, 1};
  int shared = 0;
  for (int face = 0; face < m.topology.n_faces(); ++face) {
    const mesh::HexFace& F = m.topology.face(face);
    if (F.on_boundary()) continue;
    ++shared;
    std::vector<Vec3> side[2];
    for (int k = 0; k < 2; ++k)
      for (double s : grid)
        for (double t : grid) {
          const Vec3 r = face_point(F.local_face[k], s, t);
          side[k].push_back(m.maps[F.hexes[k]].map(r(0), r(1), r(2)));
        }
    for (const Vec3& x : side[0]) {
      double nearest = 1e300;
      for (const Vec3& y : side[1]) nearest = std::min(nearest, (x - y).norm());
      EXPECT_LE(nearest, 1e-14) << "face " << face;
    }
  }
  EXPECT_EQ(shared, 3 + 3 * 1 + 3);  // patch interfaces in 2 layers (3 each), the middle sphere
}

// The analytic Jacobian shall agree with central differences of the map to 1e-8 relative
// (h = 1e-6), on every element of the shell octant, and pass check_hex_jacobian.
TEST(BlendingHex, JacobianMatchesFiniteDifferences) {
  const auto m = mesh::shell_octant_mesh(1, 2, 1);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> r(-1, 1);
  const double h = 1e-6;
  for (int e = 0; e < m.topology.n_hexes(); ++e) {
    EXPECT_NO_THROW(mesh::check_hex_jacobian(m.maps[e], "shell octant", e, 6));
    for (int k = 0; k < 20; ++k) {
      const Vec3 x(r(rng), r(rng), r(rng));
      Mat3 J, fd;
      m.maps[e].map(x(0), x(1), x(2), &J);
      for (int j = 0; j < 3; ++j) {
        const Vec3 p = x + h * Vec3::Unit(j), q = x - h * Vec3::Unit(j);
        fd.col(j) = (m.maps[e].map(p(0), p(1), p(2)) - m.maps[e].map(q(0), q(1), q(2))) / (2 * h);
      }
      EXPECT_LE((J - fd).norm(), 1e-8 * J.norm()) << "element " << e;
    }
  }
}

// The octant's volume π(b³ − a³)/6 and its first moments ∫x dV = π(b⁴ − a⁴)/16 per axis shall be
// recovered by Gauss quadrature of det J, converging exponentially: 1e-12 relative with 14 points.
TEST(BlendingHex, ShellOctantVolumeAndMoments) {
  const double a = 1, b = 2;
  const auto m = mesh::shell_octant_mesh(a, b, 1);
  double volume = 0;
  Vec3 moment = Vec3::Zero();
  for (const auto& map : m.maps) {
    volume += integrate(map, 14, [](const Vec3&) { return 1.0; });
    for (int i = 0; i < 3; ++i) moment(i) += integrate(map, 14, [i](const Vec3& x) { return x(i); });
  }
  EXPECT_NEAR(volume / (pi * (b * b * b - a * a * a) / 6), 1, 1e-12);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(moment(i) / (pi * (b * b * b * b - a * a * a * a) / 16), 1, 1e-12);
}

// A blending hexahedron turned inside out (top and bottom exchanged) shall be refused by
// check_hex_jacobian with a MeshError naming the element.
TEST(BlendingHex, InvertedElementIsRefused) {
  const auto m = mesh::shell_octant_mesh(1, 2, 1);
  std::array<Vec3, 8> v;
  for (int i = 0; i < 8; ++i) v[i] = m.maps[0].nodes()[(i + 4) % 8];
  const auto inner = std::make_shared<geometry::Sphere>(Vec3::Zero(), 1.0);
  const auto outer = std::make_shared<geometry::Sphere>(Vec3::Zero(), 2.0);
  const mesh::HexMap inverted =
      mesh::HexMap::blending(geometry::blending_hex(v, {nullptr, nullptr, nullptr, nullptr, outer, inner}));
  try {
    mesh::check_hex_jacobian(inverted, "shell", 4, 4);
    FAIL() << "an inverted element passed";
  } catch (const MeshError& e) {
    EXPECT_NE(std::string(e.what()).find("element 4 has a negative Jacobian"), std::string::npos)
        << e.what();
  }
}

// Inconsistent surfaces shall be refused with InputError naming the element: a vertex off its
// face's sphere; an edge on two different curved surfaces; a sphere's arc that leaves the plane of
// its other face (a plane not through the sphere's centre).
TEST(BlendingHex, RefusesInconsistentSurfaces) {
  // A hexahedron whose bottom corners V0..V3 lie on the cylinders and sphere below, built on
  // V0 = (0, 0, 0), V3 = (0, 1, 0) and V1 = (sin 0.5, 0, cos 0.5 − 1) (on the circle of radius 1
  // about (0, ·, −1)); V4 = (cos 0.5 − 1, 0, sin 0.5) (on the circle about (−1, ·, 0)).
  const Vec3 V1(std::sin(0.5), 0, std::cos(0.5) - 1), V4(std::cos(0.5) - 1, 0, std::sin(0.5));
  const Vec3 Y(0, 1, 0);
  const std::array<Vec3, 8> v{Vec3::Zero(), V1,     V1 + Y,      Y,
                              V4,           V1 + V4, V1 + V4 + Y, V4 + Y};
  auto message = [&](const std::array<geometry::SurfacePtr, 6>& faces) -> std::string {
    try {
      geometry::blending_hex(v, faces, "test hex");
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  const auto below = std::make_shared<geometry::Cylinder>(Vec3(0, 0, -1), Y, 1.0);
  const auto behind = std::make_shared<geometry::Cylinder>(Vec3(-1, 0, 0), Y, 1.0);
  const auto sphere = std::make_shared<geometry::Sphere>(Vec3(0, 0.5, -1), std::sqrt(1.25));
  const auto plane = std::make_shared<geometry::Plane>(Vec3::Zero(), Y);
  EXPECT_EQ(message({nullptr, nullptr, plane, nullptr, below, nullptr}), "");
  EXPECT_EQ(message({behind, nullptr, nullptr, nullptr, nullptr, nullptr}), "");
  EXPECT_EQ(message({nullptr, nullptr, nullptr, nullptr, sphere, nullptr}), "");
  EXPECT_NE(message({nullptr, nullptr, nullptr, nullptr, nullptr, below}).find(
                "test hex: vertex V4 is not on cylinder"),
            std::string::npos);
  EXPECT_NE(message({behind, nullptr, nullptr, nullptr, below, nullptr}).find(
                "test hex: edge E3 lies on two curved surfaces"),
            std::string::npos);
  EXPECT_NE(message({nullptr, nullptr, plane, nullptr, sphere, nullptr}).find(
                "test hex: edge E0 leaves plane"),
            std::string::npos);
}

// A hexahedron extruded from a plane blending quadrilateral (an annulus sector with exact arcs
// and straight radial edges; the cylinders on its curved faces, planes z = z0, z1 on the others)
// shall have the 2D map in every section: x(xi, eta, zeta) = (X_2D(xi, eta), z(zeta)), to 1e-14,
// and the Jacobian [J_2D 0; 0 (z1 − z0)/2]; its cylinder faces lie on the cylinders, uniform in
// angle (the 2D CircularArc's parametrisation).
TEST(BlendingHex, ExtrudedQuadHasThePlaneMapInEverySection) {
  const double r0 = 1.0, r1 = 1.7, a0 = 0.3, a1 = 1.2, z0 = -0.4, z1 = 0.5;
  auto polar = [](double r, double a) { return hpcontact::Vec2(r * std::cos(a), r * std::sin(a)); };
  geometry::BlendingQuad q;
  q.vertices = {polar(r0, a0), polar(r1, a0), polar(r1, a1), polar(r0, a1)};
  q.edges = {nullptr, std::make_shared<geometry::CircularArc>(hpcontact::Vec2::Zero(), r1, a0, a1),
             nullptr, std::make_shared<geometry::CircularArc>(hpcontact::Vec2::Zero(), r0, a0, a1)};
  std::array<Vec3, 8> v;
  for (int i = 0; i < 4; ++i) {
    v[i] = Vec3(q.vertices[i].x(), q.vertices[i].y(), z0);
    v[i + 4] = Vec3(q.vertices[i].x(), q.vertices[i].y(), z1);
  }
  const auto inner = std::make_shared<geometry::Cylinder>(Vec3::Zero(), Vec3::UnitZ(), r0);
  const auto outer = std::make_shared<geometry::Cylinder>(Vec3(0, 0, 3), Vec3(0, 0, -2), r1);
  const std::array<geometry::SurfacePtr, 6> faces{
      inner, outer, nullptr, nullptr,
      std::make_shared<geometry::Plane>(Vec3(0, 0, z0), Vec3::UnitZ()),
      std::make_shared<geometry::Plane>(Vec3(0, 0, z1), Vec3(0, 0, -1))};
  const auto h = geometry::blending_hex(v, faces, "extruded");
  for (double xi : {-1.0, -0.77, 0.1, 0.6, 1.0})
    for (double eta : {-1.0, -0.3, 0.45, 1.0})
      for (double zeta : {-1.0, -0.2, 0.9, 1.0}) {
        Mat3 J;
        const Vec3 x = h.map(xi, eta, zeta, &J);
        hpcontact::Mat2 J2;
        const hpcontact::Vec2 x2 = q.map(xi, eta, &J2);
        EXPECT_LT((x - Vec3(x2.x(), x2.y(), 0.5 * (1 - zeta) * z0 + 0.5 * (1 + zeta) * z1)).norm(),
                  1e-14);
        Mat3 expected = Mat3::Zero();
        expected.topLeftCorner<2, 2>() = J2;
        expected(2, 2) = 0.5 * (z1 - z0);
        EXPECT_LT((J - expected).norm(), 1e-13);
        if (xi == -1.0) {  // on the inner cylinder, at the angle a0 + (eta + 1)/2 (a1 − a0)
          const double a = a0 + 0.5 * (eta + 1) * (a1 - a0);
          EXPECT_LT((x.head<2>() - polar(r0, a)).norm(), 1e-15);
        }
      }
}
