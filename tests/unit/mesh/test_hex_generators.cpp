// Property tests of the structured hexahedral meshes (box, cylinder sector, shell octant): counts,
// face sets that cover the boundary and lie on their planes and cylinders, exact volumes, the
// polar map of the sector, the refusal of bad arguments; and the checks every HexMesh passes.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "hpcontact/basis/hex_modes.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/mesh/cylinder_sector.hpp"
#include "hpcontact/mesh/hex_box.hpp"
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

/// Largest |distance(x)| over a 5 × 5 grid of points (corners included) of every face of the set.
double farthest(const mesh::HexMesh& m, const std::string& set,
                const std::function<double(const Vec3&)>& distance) {
  double worst = 0;
  for (const auto& [h, f] : m.face_sets.at(set))
    for (double s : {-1.0, -0.6, 0.0, 0.35, 1.0})
      for (double t : {-1.0, -0.4, 0.1, 0.8, 1.0}) {
        const Vec3 r = face_point(f, s, t);
        worst = std::max(worst, std::abs(distance(m.maps[h].map(r(0), r(1), r(2)))));
      }
  return worst;
}

/// Each boundary face of the topology in exactly one of the mesh's face sets.
void expect_sets_partition_the_boundary(const mesh::HexMesh& m) {
  std::map<int, int> count;
  for (const auto& [name, faces] : m.face_sets)
    for (const auto& [h, f] : faces) ++count[m.topology.hex_face(h, f)];
  const std::vector<int> boundary = m.topology.boundary_faces();
  EXPECT_EQ(count.size(), boundary.size());
  for (int f : boundary) EXPECT_EQ(count[f], 1) << "boundary face " << f;
}

/// ∫ 1 dV by n Gauss points per direction on every element.
double volume(const mesh::HexMesh& m, int n) {
  const auto& g = basis::gauss_legendre(n);
  double sum = 0;
  for (const auto& map : m.maps)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        for (int k = 0; k < n; ++k) {
          Mat3 J;
          map.map(g.points[i], g.points[j], g.points[k], &J);
          sum += g.weights[i] * g.weights[j] * g.weights[k] * J.determinant();
        }
  return sum;
}

template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

// The box [-1, 2] × [0.5, 1.5] × [-3, -2.25] in 3 × 2 × 4 elements shall have 24 elements and
// 4 · 3 · 5 nodes; its face sets "x0" .. "z1" hold ny·nz, nx·nz, nx·ny faces each, together every
// boundary face once; each face of a set lies on its plane to round-off (1e-15 of the box's size),
// and the elements fill the box's volume to 1e-12 (trilinear, 2 Gauss points).
TEST(HexBox, CountsFaceSetsAndVolume) {
  const Vec3 lower(-1, 0.5, -3), upper(2, 1.5, -2.25);
  const std::array<int, 3> n{3, 2, 4};
  const mesh::HexMesh m = mesh::hex_box_mesh(lower, upper, n);
  EXPECT_EQ(m.topology.n_hexes(), 24);
  EXPECT_EQ(m.topology.n_nodes(), 60);
  EXPECT_EQ(m.maps.size(), 24u);
  EXPECT_EQ(m.face_sets.size(), 6u);
  const char* names[6] = {"x0", "x1", "y0", "y1", "z0", "z1"};
  for (int d = 0; d < 3; ++d)
    for (int side = 0; side < 2; ++side) {
      const std::string name = names[2 * d + side];
      ASSERT_TRUE(m.face_sets.count(name)) << name;
      EXPECT_EQ(static_cast<int>(m.face_sets.at(name).size()), n[0] * n[1] * n[2] / n[d]) << name;
      const double plane = side ? upper(d) : lower(d);
      EXPECT_LE(farthest(m, name, [&](const Vec3& x) { return x(d) - plane; }), 1e-15 * 3) << name;
    }
  expect_sets_partition_the_boundary(m);
  EXPECT_NEAR(volume(m, 2) / (upper - lower).prod(), 1, 1e-12);
}

// The box cut at given planes (x = 0, 0.1, 0.4, 1.5; y = -1, 2; z = 0, 0.3, 0.5) shall have its
// nodes on those planes, 6 elements, face sets as the equal box's, and its volume to 1e-12.
TEST(HexBox, GivenPlanes) {
  const std::array<std::vector<double>, 3> planes{std::vector<double>{0, 0.1, 0.4, 1.5},
                                                  std::vector<double>{-1, 2},
                                                  std::vector<double>{0, 0.3, 0.5}};
  const mesh::HexMesh m = mesh::hex_box_mesh(planes);
  EXPECT_EQ(m.topology.n_hexes(), 6);
  ASSERT_EQ(m.topology.n_nodes(), 4 * 2 * 3);
  for (int k = 0, a = 0; k < 3; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 4; ++i, ++a)
        EXPECT_EQ(m.nodes[a], Vec3(planes[0][i], planes[1][j], planes[2][k])) << "node " << a;
  const std::map<std::string, int> sizes{{"x0", 2}, {"x1", 2}, {"y0", 6},
                                         {"y1", 6}, {"z0", 3}, {"z1", 3}};
  for (const auto& [name, size] : sizes)
    EXPECT_EQ(static_cast<int>(m.face_sets.at(name).size()), size) << name;
  EXPECT_LE(farthest(m, "x1", [](const Vec3& x) { return x.x() - 1.5; }), 1e-15);
  expect_sets_partition_the_boundary(m);
  EXPECT_NEAR(volume(m, 2) / (1.5 * 3 * 0.5), 1, 1e-12);
}

// The cylinder sector a = 0.5 <= r <= b = 1.25, 0.2 <= θ <= 2.4, 0 <= z <= 1.5 in 2 × 3 × 2
// elements shall have 12 elements and 3 · 4 · 3 nodes; its sets "inner", "outer" hold n_θ·n_z
// faces, "theta0", "theta1" n_r·n_z, "z0", "z1" n_r·n_θ, together every boundary face once; the
// faces of "inner" and "outer" lie on their cylinders, the others on their planes, to 1e-14; the
// map is the polar map r(xi), θ(eta) linear (so the circular edges are uniform in angle) to 1e-14,
// and the volume (θ1 − θ0)(b² − a²) L / 2 is recovered to 1e-14 (det J = r r' θ' z' is linear in
// xi: 2 Gauss points are exact).
TEST(CylinderSector, CountsFaceSetsPolarMapAndVolume) {
  mesh::CylinderSector c;
  c.inner_radius = 0.5;
  c.outer_radius = 1.25;
  c.angle0 = 0.2;
  c.angle1 = 2.4;
  c.length = 1.5;
  const std::array<int, 3> n{2, 3, 2};
  const mesh::HexMesh m = mesh::cylinder_sector_mesh(c, n);
  EXPECT_EQ(m.topology.n_hexes(), 12);
  EXPECT_EQ(m.topology.n_nodes(), 36);
  const std::map<std::string, int> sizes{{"inner", 6}, {"outer", 6}, {"theta0", 4},
                                         {"theta1", 4}, {"z0", 6},    {"z1", 6}};
  EXPECT_EQ(m.face_sets.size(), sizes.size());
  for (const auto& [name, size] : sizes) {
    ASSERT_TRUE(m.face_sets.count(name)) << name;
    EXPECT_EQ(static_cast<int>(m.face_sets.at(name).size()), size) << name;
  }
  expect_sets_partition_the_boundary(m);
  auto radius = [](const Vec3& x) { return x.head<2>().norm(); };
  auto meridian = [](double angle) { return Vec3(-std::sin(angle), std::cos(angle), 0); };
  EXPECT_LE(farthest(m, "inner", [&](const Vec3& x) { return radius(x) - c.inner_radius; }), 1e-14);
  EXPECT_LE(farthest(m, "outer", [&](const Vec3& x) { return radius(x) - c.outer_radius; }), 1e-14);
  EXPECT_LE(farthest(m, "theta0", [&](const Vec3& x) { return x.dot(meridian(c.angle0)); }), 1e-14);
  EXPECT_LE(farthest(m, "theta1", [&](const Vec3& x) { return x.dot(meridian(c.angle1)); }), 1e-14);
  // ... and on the right side of the axis: the meridian plane holds two half-planes.
  for (const auto& [name, angle] : {std::pair{"theta0", c.angle0}, std::pair{"theta1", c.angle1}})
    EXPECT_LE(farthest(m, name, [&](const Vec3& x) {
                return x.head<2>().normalized().dot(Vec3(std::cos(angle), std::sin(angle), 0).head<2>()) - 1;
              }),
              1e-14)
        << name;
  EXPECT_LE(farthest(m, "z0", [](const Vec3& x) { return x.z(); }), 1e-15);
  EXPECT_LE(farthest(m, "z1", [&](const Vec3& x) { return x.z() - c.length; }), 1e-15);

  // Element (i, j, k) is index i + n_r (j + n_θ k); its map the polar one.
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        const mesh::HexMap& map = m.maps[i + n[0] * (j + n[1] * k)];
        for (double xi : {-1.0, -0.3, 0.7})
          for (double eta : {-0.9, 0.2, 1.0})
            for (double zeta : {-1.0, 0.4}) {
              auto lerp = [](double a, double b, double t) { return a + (b - a) * (t + 1) / 2; };
              const double dr = (c.outer_radius - c.inner_radius) / n[0];
              const double da = (c.angle1 - c.angle0) / n[1], dz = c.length / n[2];
              const double r = lerp(c.inner_radius + i * dr, c.inner_radius + (i + 1) * dr, xi);
              const double a = lerp(c.angle0 + j * da, c.angle0 + (j + 1) * da, eta);
              const double z = lerp(k * dz, (k + 1) * dz, zeta);
              EXPECT_LE((map.map(xi, eta, zeta) - Vec3(r * std::cos(a), r * std::sin(a), z)).norm(), 1e-14);
            }
      }
  const double exact = (c.angle1 - c.angle0) *
                       (c.outer_radius * c.outer_radius - c.inner_radius * c.inner_radius) * c.length / 2;
  EXPECT_NEAR(volume(m, 2) / exact, 1, 1e-14);
}

// The shell octant's five face sets ("inner", "outer", "x0", "y0", "z0") shall hold every boundary
// face once, for one and for three layers (their surfaces: BlendingHex.ShellOctantFacesLieOnTheirSurfaces).
TEST(ShellOctant, FaceSetsPartitionTheBoundary) {
  for (int n_layers : {1, 3}) {
    const mesh::HexMesh m = mesh::shell_octant_mesh(1, 2, n_layers);
    EXPECT_EQ(m.topology.n_hexes(), 3 * n_layers);
    EXPECT_EQ(m.face_sets.size(), 5u);
    expect_sets_partition_the_boundary(m);
  }
}

// Bad arguments shall be refused with an InputError that names the bad value.
TEST(HexGenerators, BadArgumentsAreRefused) {
  EXPECT_NE(input_error([] { mesh::hex_box_mesh(Vec3(0, 0, 0), Vec3(1, 0, 1), {1, 1, 1}); })
                .find("y0 < y1 required (got 0, 0)"),
            std::string::npos);
  EXPECT_NE(input_error([] { mesh::hex_box_mesh(Vec3(0, 0, 0), Vec3(1, 1, 1), {1, 1, 0}); })
                .find("along z must be >= 1 (got 0)"),
            std::string::npos);
  EXPECT_NE(input_error([] { mesh::hex_box_mesh({std::vector<double>{0, 1}, {0, 1}, {0}}); })
                .find("the planes along z must be two or more (got 1)"),
            std::string::npos);
  EXPECT_NE(input_error([] { mesh::hex_box_mesh({std::vector<double>{0, 1, 1}, {0, 1}, {0, 1}}); })
                .find("the planes along x must increase strictly (got 1 before 1 at 2)"),
            std::string::npos);
  auto sector = [](double a, double b, double t0, double t1, double length, std::array<int, 3> n) {
    return input_error([=] { mesh::cylinder_sector_mesh({a, b, t0, t1, length}, n); });
  };
  EXPECT_EQ(sector(1, 2, 0, 1, 1, {1, 1, 1}), "");
  EXPECT_NE(sector(0, 2, 0, 1, 1, {1, 1, 1}).find("0 < inner_radius < outer_radius (got 0, 2)"),
            std::string::npos);
  EXPECT_NE(sector(2, 2, 0, 1, 1, {1, 1, 1}).find("(got 2, 2)"), std::string::npos);
  EXPECT_NE(sector(1, 2, 1, 1, 1, {1, 1, 1}).find("angle0 < angle1"), std::string::npos);
  EXPECT_NE(sector(1, 2, 0, 2 * pi, 1, {1, 4, 1}).find("angle1 < angle0 + 2π"), std::string::npos);
  EXPECT_NE(sector(1, 2, 0, 1, -1, {1, 1, 1}).find("length must be > 0 (got -1)"), std::string::npos);
  EXPECT_NE(sector(1, 2, 0, 1, 1, {1, 0, 1}).find("along the angle must be >= 1 (got 0)"),
            std::string::npos);
  EXPECT_NE(sector(1, 2, 0, 3.5, 1, {1, 1, 1}).find("must be < π (got 3.5 with 1 elements)"),
            std::string::npos);
  EXPECT_EQ(sector(1, 2, 0, 3.5, 1, {1, 2, 1}), "");
}

// check_hex_mesh shall refuse a face set holding an interior face, a face twice, or a face of no
// element, naming the mesh, the set and the face; and a mesh with a map missing.
TEST(HexMeshCheck, RefusesBadFaceSetsAndMissingMaps) {
  const mesh::HexMesh good = mesh::hex_box_mesh(Vec3::Zero(), Vec3::Ones(), {2, 1, 1});
  EXPECT_NO_THROW(mesh::check_hex_mesh(good));
  auto refusal = [&](const std::function<void(mesh::HexMesh&)>& change) -> std::string {
    mesh::HexMesh m = good;
    change(m);
    try {
      mesh::check_hex_mesh(m);
    } catch (const MeshError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(refusal([](mesh::HexMesh& m) { m.face_sets["x0"].push_back({0, 1}); })
                .find("hexahedral box: face set 'x0' holds (element 0, face 1), which is not on the boundary"),
            std::string::npos);
  EXPECT_NE(refusal([](mesh::HexMesh& m) { m.face_sets["y0"].push_back(m.face_sets["y0"][0]); })
                .find("face set 'y0' holds (element 0, face 2) twice"),
            std::string::npos);
  EXPECT_NE(refusal([](mesh::HexMesh& m) { m.face_sets["load"] = {{2, 0}}; })
                .find("face set 'load' holds (element 2, face 0), outside"),
            std::string::npos);
  EXPECT_NE(refusal([](mesh::HexMesh& m) { m.maps.pop_back(); }).find("1 maps for 2 elements"),
            std::string::npos);
}
