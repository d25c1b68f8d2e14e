// Property tests of consistent edge loads: resultants of uniform pressure on straight and
// circular edges, outward normals, support on the loaded edge, additivity over sub-intervals.
#include "hpcontact/fem/edge_load.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fem_test_meshes.hpp"
#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/mesh/element_map.hpp"

using namespace hpcontact;

namespace {

struct LoadedElement {
  fem::DofMap dofs;
  mesh::ElementMap map;
};

LoadedElement hierarchic_setup(const mesh::Mesh& m, int p) {
  fem::SpaceOptions o;
  o.degrees = {{p, p}};
  return {fem::DofMap(m, o), mesh::ElementMap::blending(m, 0)};
}

/// The resultant force of an element load vector: its work on unit translations, i.e. the sum
/// over the vertex modes (which sum to one on the element) of each component.
Vec2 resultant(const Eigen::VectorXd& f, int n_modes, int n_partition) {
  return Vec2(f.head(n_modes).head(n_partition).sum(), f.tail(n_modes).head(n_partition).sum());
}

/// Outward unit normal of the chord of local edge le (E1, E2 run counter-clockwise around the
/// element, E3, E4 clockwise).
Vec2 chord_normal(const mesh::Mesh& m, int le) {
  const Vec2 a = m.node(m.quad(0)[mesh::kEdgeVertices[le][0]]);
  const Vec2 b = m.node(m.quad(0)[mesh::kEdgeVertices[le][1]]);
  const Vec2 c = (b - a).normalized();
  return le < 2 ? Vec2(c.y(), -c.x()) : Vec2(-c.y(), c.x());
}

double chord_length(const mesh::Mesh& m, int le) {
  return (m.node(m.quad(0)[mesh::kEdgeVertices[le][1]]) -
          m.node(m.quad(0)[mesh::kEdgeVertices[le][0]]))
      .norm();
}

}  // namespace

// A uniform pressure p on a straight edge of length L shall give the resultant −p·L·t·n (n the
// outward normal, t the thickness) to 1e-12 relative, on each of the four local edges, p = 1..8.
TEST(EdgeLoadProperties, UniformPressureOnStraightEdge) {
  const auto m = fem_test::distorted_quad();
  const double pressure = 3.5, t = 0.8;
  const fem::TractionFn traction = [&](const Vec2&, const Vec2& n) { return Vec2(-pressure * n); };
  for (int p = 1; p <= 8; ++p) {
    const LoadedElement s = hierarchic_setup(m, p);
    const auto& space = s.dofs.element(0);
    for (int le = 0; le < 4; ++le) {
      const Eigen::VectorXd f = fem::edge_load(space, s.map, le, -1, 1, p + 1, t, traction);
      const Vec2 R = resultant(f, space.n_modes(), 4);
      const Vec2 exact = -pressure * chord_length(m, le) * t * chord_normal(m, le);
      EXPECT_LE((R - exact).norm(), 1e-12 * exact.norm()) << "p = " << p << " edge " << le;
      // The outward normal points away from the element centre.
      Vec2 n;
      const Vec2 x = fem::edge_geometry(s.map, le, 0.3, &n, nullptr);
      EXPECT_GT(n.dot(x - s.map.map(0, 0)), 0.0) << "edge " << le;
      EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    }
  }
}

// The load of an edge shall only reach the modes that do not vanish on it: its two vertex modes
// and its own edge modes (all others to 1e-14 of the largest entry).
TEST(EdgeLoadProperties, LoadOnlyReachesModesOfTheEdge) {
  const auto m = fem_test::sector_quad();
  const int p = 6;
  const LoadedElement s = hierarchic_setup(m, p);
  const auto& space = s.dofs.element(0);
  const int n = space.n_modes();
  const fem::TractionFn traction = [](const Vec2& x, const Vec2& nrm) {
    return Vec2(2 * x.x() - nrm.y(), 1 + x.y() * x.y());
  };
  for (int le = 0; le < 4; ++le) {
    const Eigen::VectorXd f = fem::edge_load(space, s.map, le, -1, 1, 12, 1.0, traction);
    std::vector<bool> on_edge(n, false);
    on_edge[mesh::kEdgeVertices[le][0]] = on_edge[mesh::kEdgeVertices[le][1]] = true;
    int first = 4;
    for (int e = 0; e < le; ++e) first += space.hierarchic.n_edge_modes(e);
    for (int k = 0; k < space.hierarchic.n_edge_modes(le); ++k) on_edge[first + k] = true;
    const double scale = f.cwiseAbs().maxCoeff();
    for (int a = 0; a < n; ++a)
      for (int c = 0; c < 2; ++c)
        if (!on_edge[a]) EXPECT_LE(std::abs(f(c * n + a)), 1e-14 * scale) << "edge " << le << " mode " << a;
  }
}

// A uniform pressure on a circular arc shall give the resultant p × chord length, normal to the
// chord (outwards), to 1e-12 relative: ∫ n ds is the chord turned by 90°. Outer and inner arcs,
// several openings and radii, p = 1..8.
TEST(EdgeLoadProperties, UniformPressureOnCircularArc) {
  const double pressure = 2.0;
  const fem::TractionFn traction = [&](const Vec2&, const Vec2& n) { return Vec2(-pressure * n); };
  for (auto [r1, r2, theta] : std::vector<std::array<double, 3>>{
           {1, 2, std::numbers::pi / 3}, {9, 10, std::numbers::pi / 2}, {0.5, 3, 2.5}}) {
    const auto m = fem_test::sector_quad(r1, r2, theta);
    for (int p = 1; p <= 8; ++p) {
      const LoadedElement s = hierarchic_setup(m, p);
      const auto& space = s.dofs.element(0);
      for (int le : {1, 3}) {  // E2 outer arc, E4 inner arc
        const Eigen::VectorXd f = fem::edge_load(space, s.map, le, -1, 1, 20, 1.0, traction);
        const Vec2 R = resultant(f, space.n_modes(), 4);
        const Vec2 exact = -pressure * chord_length(m, le) * chord_normal(m, le);
        EXPECT_LE((R - exact).norm(), 1e-12 * exact.norm())
            << "r " << r1 << ".." << r2 << " theta " << theta << " p " << p << " edge " << le;
      }
    }
  }
}

// A constant traction on an arc shall give q × arc length (20 Gauss points; 1e-12 relative).
TEST(EdgeLoadProperties, ConstantTractionOnArcIntegratesArcLength) {
  const auto m = fem_test::sector_quad(1, 2, 1.2);
  const LoadedElement s = hierarchic_setup(m, 4);
  const auto& space = s.dofs.element(0);
  const Vec2 q(0.3, -1.7);
  const fem::TractionFn traction = [&](const Vec2&, const Vec2&) { return q; };
  const Eigen::VectorXd f = fem::edge_load(space, s.map, 1, -1, 1, 20, 1.0, traction);
  const Vec2 exact = q * 2 * 1.2;  // outer arc length r2 · theta
  EXPECT_LE((resultant(f, space.n_modes(), 4) - exact).norm(), 1e-12 * exact.norm());
}

// Loads over [t0, tm] and [tm, t1] shall add up to the load over [t0, t1] (1e-13 relative) for a
// load integrated exactly on each part.
TEST(EdgeLoadProperties, SubIntervalsAreAdditive) {
  const auto m = fem_test::distorted_quad();
  const LoadedElement s = hierarchic_setup(m, 5);
  const auto& space = s.dofs.element(0);
  // Linear in x on a straight edge: integrand of degree 5 + 1, exact with 4+ Gauss points.
  const fem::TractionFn traction = [](const Vec2& x, const Vec2&) {
    return Vec2(1 + x.x(), 2 - 0.5 * x.y());
  };
  for (int le = 0; le < 4; ++le) {
    const Eigen::VectorXd whole = fem::edge_load(space, s.map, le, -1, 1, 6, 1.0, traction);
    const Eigen::VectorXd parts = fem::edge_load(space, s.map, le, -1, 0.25, 6, 1.0, traction) +
                                  fem::edge_load(space, s.map, le, 0.25, 1, 6, 1.0, traction);
    EXPECT_LE((whole - parts).norm(), 1e-13 * whole.norm()) << "edge " << le;
  }
}
