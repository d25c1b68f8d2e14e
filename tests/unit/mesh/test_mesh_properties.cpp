// Property tests of the mesh topology, its checks, and the blending / isoparametric element maps.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"
#include "hpcontact/geometry/curve.hpp"
#include "hpcontact/mesh/element_map.hpp"
#include "hpcontact/mesh/mesh.hpp"

using hpcontact::Mat2;
using hpcontact::MeshError;
using hpcontact::Vec2;
using namespace hpcontact::mesh;
namespace geo = hpcontact::geometry;

namespace {

constexpr double pi = std::numbers::pi;

/// The square [0,2]² as 2×2 unit elements; node ids 1..9 row by row from (0,0), element ids
/// 11..14. Elements list their vertices counter-clockwise from the lower left corner, except
/// element 14 which starts at its lower right corner (so some local edges run against the
/// global direction).
Mesh mesh_2x2(std::vector<EdgeCurve> curves = {}) {
  std::vector<Vec2> nodes;
  std::vector<int> ids;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      nodes.emplace_back(i, j);
      ids.push_back(1 + 3 * j + i);
    }
  std::vector<std::array<int, 4>> quads;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const int a = 3 * j + i;
      if (i == 1 && j == 1)
        quads.push_back({a + 1, a + 4, a + 3, a});
      else
        quads.push_back({a, a + 1, a + 4, a + 3});
    }
  return Mesh(nodes, ids, quads, {11, 12, 13, 14}, curves, "test.yaml: bodies[0]");
}

/// Annular sector 1 <= r <= 2, 0 <= theta <= pi/2, split into 2 elements along theta = pi/4.
/// Nodes: 0 (1,0), 1 (2,0), 2 outer at pi/4, 3 inner at pi/4, 4 outer at pi/2, 5 inner at pi/2.
/// Element 21 is (0,1,2,3); element 22 is numbered from a different corner, (5,3,2,4), so that
/// its local edge directions differ from the global ones. The arcs are given in mixed directions.
Mesh annulus_2() {
  auto polar = [](double r, double t) { return Vec2(r * std::cos(t), r * std::sin(t)); };
  std::vector<Vec2> nodes = {polar(1, 0),      polar(2, 0),      polar(2, pi / 4),
                             polar(1, pi / 4), polar(2, pi / 2), polar(1, pi / 2)};
  const Vec2 c(0, 0);
  std::vector<EdgeCurve> curves = {
      {1, 2, geo::arc_through(nodes[1], nodes[2], c, 2, 0, "outer a")},
      {4, 2, geo::arc_through(nodes[4], nodes[2], c, 2, 0, "outer b")},  // given clockwise
      {3, 0, geo::arc_through(nodes[3], nodes[0], c, 1, 0, "inner a")},  // given clockwise
      {3, 5, geo::arc_through(nodes[3], nodes[5], c, 1, 0, "inner b")}};
  // Element 22: corners (5,3,2,4): inner pi/2 -> inner pi/4 -> outer pi/4 -> outer pi/2 is
  // counter-clockwise (theta decreasing while r is the second direction).
  return Mesh(nodes, {1, 2, 3, 4, 5, 6}, {{0, 1, 2, 3}, {5, 3, 2, 4}}, {21, 22}, curves,
              "annulus");
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const MeshError& e) {
    return e.what();
  }
  return "<no MeshError>";
}

}  // namespace

// A 2×2 mesh shall have 9 nodes, 12 edges of which 8 on the boundary, and each of the 4 interior
// edges shall list two elements whose local edge maps back to it.
TEST(MeshTopology, TwoByTwoCounts) {
  const Mesh m = mesh_2x2();
  EXPECT_EQ(m.n_nodes(), 9);
  EXPECT_EQ(m.n_quads(), 4);
  ASSERT_EQ(m.n_edges(), 12);
  int boundary = 0, interior = 0;
  for (int e = 0; e < m.n_edges(); ++e) {
    const Edge& edge = m.edge(e);
    if (edge.on_boundary()) {
      ++boundary;
      EXPECT_GE(edge.quads[0], 0);
      EXPECT_EQ(m.quad_edge(edge.quads[0], edge.local_edge[0]), e);
      // A boundary edge lies on the outline of [0,2]².
      const Vec2 mid = 0.5 * (m.node(edge.v0) + m.node(edge.v1));
      EXPECT_TRUE(mid.x() == 0 || mid.x() == 2 || mid.y() == 0 || mid.y() == 2) << "edge " << e;
      continue;
    }
    ++interior;
    EXPECT_NE(edge.quads[0], edge.quads[1]);
    for (int s = 0; s < 2; ++s) {
      const int q = edge.quads[s], le = edge.local_edge[s];
      ASSERT_GE(q, 0);
      ASSERT_GE(le, 0);
      ASSERT_LT(le, 4);
      EXPECT_EQ(m.quad_edge(q, le), e) << "edge " << e << " side " << s;
      const int a = m.quad(q)[kEdgeVertices[le][0]], b = m.quad(q)[kEdgeVertices[le][1]];
      EXPECT_EQ(std::set<int>({a, b}), std::set<int>({edge.v0, edge.v1}));
    }
  }
  EXPECT_EQ(boundary, 8);
  EXPECT_EQ(interior, 4);
  // Every local edge of every element is one of the 12, and every edge is used 1 or 2 times.
  std::vector<int> uses(m.n_edges(), 0);
  for (int q = 0; q < m.n_quads(); ++q)
    for (int le = 0; le < 4; ++le) ++uses[m.quad_edge(q, le)];
  for (int e = 0; e < m.n_edges(); ++e) EXPECT_EQ(uses[e], m.edge(e).on_boundary() ? 1 : 2);
  // Look-ups by id and by node pair.
  EXPECT_EQ(m.node_index(5), 4);
  EXPECT_EQ(m.quad_index(13), 2);
  EXPECT_EQ(m.node_index(99), -1);
  EXPECT_EQ(m.find_edge(0, 4), -1);  // a diagonal
  EXPECT_EQ(m.find_edge(4, 1), m.find_edge(1, 4));
  EXPECT_GE(m.find_edge(1, 4), 0);
}

// Every edge shall be oriented v0 < v1, and quad_edge_reversed shall be true exactly when the
// local edge (kEdgeVertices order) runs from the higher to the lower node index.
TEST(MeshTopology, EdgeOrientationIsConsistent) {
  for (const Mesh& m : {mesh_2x2(), annulus_2()}) {
    for (int e = 0; e < m.n_edges(); ++e) EXPECT_LT(m.edge(e).v0, m.edge(e).v1);
    int n_reversed = 0;
    for (int q = 0; q < m.n_quads(); ++q)
      for (int le = 0; le < 4; ++le) {
        const int a = m.quad(q)[kEdgeVertices[le][0]], b = m.quad(q)[kEdgeVertices[le][1]];
        const Edge& edge = m.edge(m.quad_edge(q, le));
        const bool rev = m.quad_edge_reversed(q, le);
        EXPECT_EQ(rev, a > b) << "element " << q << " local edge " << le;
        EXPECT_EQ(rev ? b : a, edge.v0);
        EXPECT_EQ(rev ? a : b, edge.v1);
        n_reversed += rev;
      }
    EXPECT_GT(n_reversed, 0);  // the meshes do exercise reversed edges
  }
}

// edge_point shall run from v0 (t = -1) to v1 (t = +1), on the exact curve where one is given,
// whatever the direction in which the curve was given.
TEST(MeshTopology, EdgePointFollowsTheGlobalDirection) {
  const Mesh m = annulus_2();
  for (int e = 0; e < m.n_edges(); ++e) {
    const Edge& edge = m.edge(e);
    EXPECT_LE((m.edge_point(e, -1) - m.node(edge.v0)).norm(), 1e-14) << "edge " << e;
    EXPECT_LE((m.edge_point(e, 1) - m.node(edge.v1)).norm(), 1e-14) << "edge " << e;
    if (!edge.curve) continue;
    const double r = m.node(edge.v0).norm();
    for (double t : {-0.7, 0.0, 0.4}) EXPECT_NEAR(m.edge_point(e, t).norm(), r, 1e-14);
  }
}

// A clockwise element shall be rejected with a MeshError naming its element id.
TEST(MeshChecks, ClockwiseElementIsRejected) {
  const std::vector<Vec2> nodes = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1), Vec2(2, 0),
                                   Vec2(2, 1)};
  const std::string msg = message_of([&] {
    Mesh(nodes, {1, 2, 3, 4, 5, 6}, {{0, 1, 2, 3}, {1, 2, 5, 4}}, {7, 42}, {}, "ctx");
  });
  EXPECT_NE(msg.find("element 42"), std::string::npos) << msg;
  EXPECT_NE(msg.find("ctx"), std::string::npos) << msg;
  // A degenerate (repeated corner) and a non-convex element are rejected too.
  EXPECT_THROW(Mesh(nodes, {1, 2, 3, 4, 5, 6}, {{0, 1, 1, 3}}, {1}, {}, "ctx"), MeshError);
  const std::vector<Vec2> dart = {Vec2(0, 0), Vec2(2, 0), Vec2(0.5, 0.5), Vec2(0, 2)};
  EXPECT_THROW(Mesh(dart, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {1}, {}, "ctx"), MeshError);
}

// Two corners at one point up to round-off of the element's size (distinct node ids) make a
// triangle; they shall be rejected naming the element and the nodes, at any scale of the mesh.
TEST(MeshChecks, CornersAtOnePointAreRejectedAtAnyScale) {
  for (double h : {1e-9, 1.0, 1e9}) {
    const std::vector<Vec2> nodes = {Vec2(0, 0), h * Vec2(1e-9, 0), h * Vec2(1, 1), h * Vec2(0, 1)};
    const std::string msg = message_of([&] { Mesh(nodes, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {8}, {}, "ctx"); });
    EXPECT_NE(msg.find("element 8 is degenerate: its corners 1 and 2 are at one point"),
              std::string::npos)
        << msg;
    // A short edge that is not round-off (1e-6 of the element) is an element, if a poor one.
    const std::vector<Vec2> short_edge = {Vec2(0, 0), h * Vec2(1e-6, 0), h * Vec2(1, 1), h * Vec2(0, 1)};
    EXPECT_NO_THROW(Mesh(short_edge, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {8}, {}, "ctx")) << h;
  }
}

// The same element under two ids (its edges then have two elements each, and pass the topology
// check) shall be rejected.
TEST(MeshChecks, ElementGivenTwiceIsRejected) {
  const std::vector<Vec2> nodes = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  const std::string msg =
      message_of([&] { Mesh(nodes, {1, 2, 3, 4}, {{0, 1, 2, 3}, {1, 2, 3, 0}}, {5, 6}, {}, "ctx"); });
  EXPECT_NE(msg.find("elements 5 and 6 have the same corners"), std::string::npos) << msg;
}

// A duplicate node id shall be rejected with a MeshError naming the id.
TEST(MeshChecks, DuplicateNodeIdIsRejected) {
  const std::vector<Vec2> nodes = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  const std::string msg = message_of(
      [&] { Mesh(nodes, {1, 2, 77, 77}, {{0, 1, 2, 3}}, {1}, {}, "ctx"); });
  EXPECT_NE(msg.find("duplicate node id 77"), std::string::npos) << msg;
  EXPECT_THROW(Mesh(nodes, {1, 2, 3, 4}, {{0, 1, 2, 3}, {0, 1, 2, 3}}, {5, 5}, {}, "ctx"),
               MeshError);
}

// A curve between two nodes that are not joined by an element edge shall be a MeshError naming
// the node ids; a curve that does not end at its nodes too.
TEST(MeshChecks, CurveOnANonEdgeIsRejected) {
  const Vec2 a(0, 0), c(2, 2);
  const auto diagonal = std::make_shared<geo::LineSegment>(a, c);
  const std::string msg = message_of([&] { mesh_2x2({{0, 4, diagonal}}); });
  EXPECT_NE(msg.find("not joined"), std::string::npos) << msg;
  EXPECT_NE(msg.find("1 and 5"), std::string::npos) << msg;  // node ids of indices 0 and 4
  // Curve on an edge (0-1) that ends elsewhere.
  const auto wrong = std::make_shared<geo::LineSegment>(Vec2(0, 0), Vec2(1, 0.5));
  EXPECT_THROW(mesh_2x2({{0, 1, wrong}}), MeshError);
  // Two curves for one edge.
  const auto ok = std::make_shared<geo::LineSegment>(Vec2(0, 0), Vec2(1, 0));
  EXPECT_THROW(mesh_2x2({{0, 1, ok}, {1, 0, ok->reversed()}}), MeshError);
}

// check_jacobian shall reject an element whose curved edge crosses the opposite edge with a
// MeshError naming the element id, and accept the same element with a mild curve.
TEST(MeshChecks, SelfCrossingCurvedElementIsRejected) {
  const std::vector<Vec2> nodes = {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  auto bulge = [](double height) {
    return std::make_shared<geo::FunctionCurve>(
        [height](double s) { return Vec2(s, height * std::sin(pi * s)); },
        [height](double s) { return Vec2(1, height * pi * std::cos(pi * s)); }, "bulge");
  };
  // The bottom edge bulges up to y = 3, far across the top edge y = 1.
  const Mesh bad(nodes, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {314}, {{0, 1, bulge(3.0)}}, "ctx");
  const ElementMap map = ElementMap::blending(bad, 0);
  const std::string msg = message_of([&] { check_jacobian(map, bad, 0, 6); });
  EXPECT_NE(msg.find("element 314"), std::string::npos) << msg;
  // A downward bulge (outwards) is a valid element.
  const Mesh good(nodes, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {314}, {{0, 1, bulge(-0.3)}}, "ctx");
  EXPECT_NO_THROW(check_jacobian(ElementMap::blending(good, 0), good, 0, 6));
}

// The blending map of every element shall put its edges on the exact arcs, with the arcs given
// in either direction and elements numbered from any corner, and vertices at the nodes.
TEST(ElementMapProperties, BlendingEdgesLieOnTheArcs) {
  const Mesh m = annulus_2();
  for (int q = 0; q < m.n_quads(); ++q) {
    const ElementMap map = ElementMap::blending(m, q);
    EXPECT_NO_THROW(check_jacobian(map, m, q, 8));
    const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k)
      EXPECT_LE((map.map(corner[k][0], corner[k][1]) - m.node(m.quad(q)[k])).norm(), 1e-14);
    for (int le = 0; le < 4; ++le) {
      const Edge& edge = m.edge(m.quad_edge(q, le));
      if (!edge.curve) continue;
      const double r = m.node(edge.v0).norm();
      for (int i = 0; i <= 10; ++i) {
        const double t = -1 + 0.2 * i;
        const double xi = le == 1 ? 1 : le == 3 ? -1 : t, eta = le == 0 ? -1 : le == 2 ? 1 : t;
        EXPECT_NEAR(map.map(xi, eta).norm(), r, 1e-14) << "element " << q << " edge " << le;
      }
    }
  }
}

// The isoparametric Q8 map shall put each mid-edge node on the exact arc at the angular midpoint,
// interpolate its nodes, and put the Q9 centre node at the centre of the exact sector.
TEST(ElementMapProperties, IsoparametricMidEdgeNodesOnTheArc) {
  const Mesh m = annulus_2();
  using hpcontact::basis::LagrangeType;
  const double ref[8][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (int q = 0; q < m.n_quads(); ++q) {
    const ElementMap q8 = ElementMap::isoparametric(m, q, LagrangeType::q8);
    const auto& nodes = q8.lagrange_nodes();
    ASSERT_EQ(nodes.size(), 8u);
    int on_arc = 0;
    for (int le = 0; le < 4; ++le) {
      const Vec2 a = m.node(m.quad(q)[kEdgeVertices[le][0]]),
                 b = m.node(m.quad(q)[kEdgeVertices[le][1]]);
      const Vec2& mid = nodes[4 + le];
      if (m.edge(m.quad_edge(q, le)).curve) {
        ++on_arc;
        const double r = a.norm();
        EXPECT_NEAR(mid.norm(), r, 1e-14) << "element " << q << " edge " << le;
        // Angular midpoint: the direction of a + b.
        EXPECT_LE((mid - r * (a + b).normalized()).norm(), 1e-14);
      } else {
        EXPECT_LE((mid - 0.5 * (a + b)).norm(), 1e-14);
      }
    }
    EXPECT_EQ(on_arc, 2);
    for (int k = 0; k < 8; ++k) EXPECT_LE((q8.map(ref[k][0], ref[k][1]) - nodes[k]).norm(), 1e-14);
    EXPECT_NO_THROW(check_jacobian(q8, m, q, 4));
    const ElementMap q9 = ElementMap::isoparametric(m, q, LagrangeType::q9);
    ASSERT_EQ(q9.lagrange_nodes().size(), 9u);
    // The blending map of a sector element is the polar map: its centre is at the mean radius
    // on the angular bisector (pi/8 for element 21, 3pi/8 for element 22).
    const double bisector = q == 0 ? pi / 8 : 3 * pi / 8;
    EXPECT_LE((q9.lagrange_nodes()[8] - 1.5 * Vec2(std::cos(bisector), std::sin(bisector))).norm(),
              1e-14);
  }
}

// The Jacobian of the blending and isoparametric maps shall match central differences of map()
// (h = 1e-6, agreement to 1e-8: truncation ~1e-12, round-off ~1e-10).
TEST(ElementMapProperties, JacobianMatchesFiniteDifferences) {
  const Mesh m = annulus_2();
  using hpcontact::basis::LagrangeType;
  const double h = 1e-6;
  for (int q = 0; q < m.n_quads(); ++q) {
    for (const ElementMap& map :
         {ElementMap::blending(m, q), ElementMap::isoparametric(m, q, LagrangeType::q4),
          ElementMap::isoparametric(m, q, LagrangeType::q8),
          ElementMap::isoparametric(m, q, LagrangeType::q9)}) {
      for (auto [xi, eta] : std::vector<std::array<double, 2>>{
               {0.1, 0.2}, {-0.8, 0.6}, {0.95, -0.95}, {-0.3, -0.7}}) {
        Mat2 J, fd;
        map.map(xi, eta, &J);
        fd.col(0) = (map.map(xi + h, eta) - map.map(xi - h, eta)) / (2 * h);
        fd.col(1) = (map.map(xi, eta + h) - map.map(xi, eta - h)) / (2 * h);
        EXPECT_LE((J - fd).norm(), 1e-8 * (1 + J.norm()));
      }
    }
  }
}
