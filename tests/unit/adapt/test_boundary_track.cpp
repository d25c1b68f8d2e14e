// Boundary tracks and node moves of the rp-version: the node stays on the exact curve, the
// neighbours bound it, corners and parametric curves refuse, elements stay valid.
#include <gtest/gtest.h>

#include <cmath>

#include "hpcontact/adapt/boundary_track.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/model/discretization.hpp"

using namespace hpcontact;

namespace {

/// The 2×2 quarter cylinder of the Hertz examples (R = 10, centre (0, 10)): nodes 1–9, arcs
/// 1-2-3-6-9 on the circle, node 2 (A) at x = 2.48.
model::ProblemSpec quarter_cylinder() {
  model::ProblemSpec spec;
  spec.file = "test.yaml";
  model::BodySpec b;
  b.name = "cylinder";
  b.material.youngs_modulus = 210000;
  b.material.poisson_ratio = 0.3;
  b.node_ids = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  const double ya = 10 - std::sqrt(100 - 2.48 * 2.48);
  b.nodes = {{0, 0}, {2.48, ya}, {6.42787609686539, 2.33955556881022}, {0, 4}, {3.6, 4.6},
             {9.0630778703665, 5.77381738259301}, {0, 10}, {5, 10}, {10, 10}};
  b.element_ids = {1, 2, 3, 4};
  b.elements = {{1, 2, 5, 4}, {2, 3, 6, 5}, {4, 5, 8, 7}, {5, 6, 9, 8}};
  for (auto [a, c] : {std::pair{1, 2}, {2, 3}, {3, 6}, {6, 9}}) {
    model::CurveSpec cs;
    cs.node_a = a;
    cs.node_b = c;
    cs.center = {0, 10};
    cs.radius = 10;
    b.curves.push_back(cs);
  }
  spec.bodies.push_back(b);
  spec.discretization.degree = {4, 4};
  return spec;
}

Vec2 node(const model::ProblemSpec& spec, int id) {
  const auto& b = spec.bodies[0];
  for (size_t i = 0; i < b.node_ids.size(); ++i)
    if (b.node_ids[i] == id) return Vec2(b.nodes[i][0], b.nodes[i][1]);
  return Vec2::Constant(NAN);
}

}  // namespace

TEST(BoundaryTrack, NodeOnTheArcMovesAlongTheCircle) {
  const auto spec = quarter_cylinder();
  const adapt::BoundaryTrack track(spec, 0, 2);
  EXPECT_NEAR(track.node(), 0.0, 1e-14);
  EXPECT_LT(track.lower(), 0.0);
  EXPECT_GT(track.upper(), 0.0);
  // parameter and point are inverse on the circle; every point lies on it.
  for (double s : {track.lower(), -0.05, 0.0, 0.1, track.upper()}) {
    const Vec2 X = track.point(s);
    EXPECT_NEAR((X - Vec2(0, 10)).norm(), 10.0, 1e-12);
    EXPECT_NEAR(track.parameter(X), s, 1e-13);
  }
  // The neighbours are the ends: nodes 1 and 3.
  EXPECT_NEAR((track.point(track.lower()) - node(spec, 1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((track.point(track.upper()) - node(spec, 3)).norm(), 0.0, 1e-9);
}

TEST(BoundaryTrack, MovedNodeStaysOnTheCircleAndTheMeshStaysValid) {
  const auto spec = quarter_cylinder();
  const adapt::BoundaryTrack track(spec, 0, 2);
  const Vec2 target(1.94, 10 - std::sqrt(100 - 1.94 * 1.94));
  const auto moved = adapt::with_node_moved(spec, track, track.parameter(target));
  EXPECT_NEAR((node(moved, 2) - target).norm(), 0.0, 1e-12);
  EXPECT_EQ(node(moved, 5), node(spec, 5));  // no need for the interior node to follow
  const auto d = model::discretize(moved);
  // The arc from node 1 to node 2 is still exact: its midpoint lies on the circle.
  const auto& m = d.bodies[0].mesh;
  const int e = m.find_edge(m.node_index(1), m.node_index(2));
  ASSERT_GE(e, 0);
  EXPECT_NEAR((m.edge_point(e, 0.0) - Vec2(0, 10)).norm(), 10.0, 1e-12);
}

TEST(BoundaryTrack, CornersAndInteriorNodesCannotSlide) {
  const auto spec = quarter_cylinder();
  EXPECT_THROW(adapt::BoundaryTrack(spec, 0, 1), AdaptError);  // arc meets the symmetry line
  EXPECT_THROW(adapt::BoundaryTrack(spec, 0, 5), AdaptError);  // interior
  EXPECT_THROW(adapt::BoundaryTrack(spec, 0, 9), AdaptError);  // arc meets the centre plane
  // Node 8 lies between two collinear straight edges of the centre plane: it slides.
  const adapt::BoundaryTrack line(spec, 0, 8);
  EXPECT_NEAR((line.point(line.parameter(Vec2(7, 10))) - Vec2(7, 10)).norm(), 0.0, 1e-14);
}

TEST(BoundaryTrack, ParametricCurveIsRefused) {
  auto spec = quarter_cylinder();
  auto& c = spec.bodies[0].curves[0];
  c.kind = model::CurveKind::parametric;
  c.x_expr = "2.48*s";
  c.y_expr = "10 - sqrt(100 - (2.48*s)^2)";
  try {
    adapt::BoundaryTrack(spec, 0, 2);
    FAIL() << "no error";
  } catch (const AdaptError& e) {
    EXPECT_NE(std::string(e.what()).find("parametric"), std::string::npos) << e.what();
  }
}

TEST(BoundaryTrack, MoveBeyondANeighbourIsRefused) {
  const auto spec = quarter_cylinder();
  const adapt::BoundaryTrack track(spec, 0, 2);
  EXPECT_THROW(adapt::with_node_moved(spec, track, track.lower() - 0.01), AdaptError);
  EXPECT_THROW(adapt::with_node_moved(spec, track, track.upper()), AdaptError);
}

TEST(BoundaryTrack, InteriorNeighbourFollowsWhenAnElementWouldInvert) {
  // Node 8 slides along the centre plane y = 10 towards node 9, past the interior node 5's
  // x = 3.6 by far: element 3 (4, 5, 8, 7) would fold unless node 5 follows.
  auto spec = quarter_cylinder();
  spec.bodies[0].nodes[4] = {3.6, 9.0};  // node 5 close below the centre plane
  const adapt::BoundaryTrack track(spec, 0, 8);
  const double s = track.parameter(Vec2(9.6, 10));
  auto unfollowed = spec;
  unfollowed.bodies[0].nodes[7] = {9.6, 10};
  EXPECT_THROW((void)model::discretize(unfollowed), MeshError);
  const auto moved = adapt::with_node_moved(spec, track, s);
  EXPECT_NEAR((node(moved, 8) - Vec2(9.6, 10)).norm(), 0.0, 1e-12);
  EXPECT_GT(node(moved, 5).x(), 3.6);  // it followed
  EXPECT_NO_THROW((void)model::discretize(moved));
}
