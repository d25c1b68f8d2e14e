// Gaps of the rigid obstacles and of a deformed boundary against closed forms: the signed
// distance to the surface, positive outside, with the surface's outward normal.
#include "hpcontact/contact/obstacle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "hpcontact/contact/deformable_boundary.hpp"

using hpcontact::Mat2;
using hpcontact::Vec2;
using namespace hpcontact;
using namespace hpcontact::contact;

// A plane through p with normal n (given unnormalised) shall have the gap (x − p)·n/|n|, that
// normal everywhere and no curvature; displaced by λ d it shall be the plane through p + λ d.
TEST(RigidObstacle, PlaneAndDisplacedPlaneGaps) {
  const Vec2 p(1, 2), n(3, 4);  // |n| = 5
  auto plane = std::make_shared<RigidPlane>(p, n);
  DisplacedObstacle moved(plane, Vec2(0.5, -1));
  for (const Vec2 x : {Vec2(4, 6), Vec2(-2, 1), Vec2(1, 2)}) {
    Vec2 normal;
    Mat2 dn;
    EXPECT_NEAR(plane->gap(x, &normal, &dn), (x - p).dot(n) / 5, 1e-14);
    EXPECT_LT((normal - n / 5).norm(), 1e-15);
    EXPECT_EQ(dn.norm(), 0.0);
    for (double lambda : {0.0, 0.4, -2.0}) {
      moved.set_load_factor(lambda);
      const Vec2 p_moved = p + lambda * Vec2(0.5, -1);
      EXPECT_NEAR(moved.gap(x, nullptr, nullptr), (x - p_moved).dot(n) / 5, 1e-14) << lambda;
      EXPECT_LT((moved.offset() - lambda * Vec2(0.5, -1)).norm(), 1e-15);
    }
  }
}

// A disc of radius r about c shall have the gap |x − c| − r with the normal (x − c)/|x − c|
// and dn/dx = (I − n nᵀ)/|x − c|; a hole (the body inside) the gap r − |x − c| with the normal
// turned inwards; displaced by λ d, the disc about c + λ d.
TEST(RigidObstacle, DiscAndHoleGaps) {
  const Vec2 c(1, -1);
  const double r = 2;
  auto disc = std::make_shared<RigidCircle>(c, r, false);
  const RigidCircle hole(c, r, true);
  DisplacedObstacle moved(disc, Vec2(-1, 3));
  moved.set_load_factor(0.25);
  for (const Vec2 x : {Vec2(4, 3), Vec2(1, 0.5), Vec2(-0.5, -2)}) {
    const double dist = (x - c).norm();
    const Vec2 e = (x - c) / dist;
    Vec2 normal;
    Mat2 dn;
    EXPECT_NEAR(disc->gap(x, &normal, &dn), dist - r, 1e-14);
    EXPECT_LT((normal - e).norm(), 1e-15);
    EXPECT_LT((dn - (Mat2::Identity() - e * e.transpose()) / dist).norm(), 1e-14);
    EXPECT_NEAR(hole.gap(x, &normal, &dn), r - dist, 1e-14);
    EXPECT_LT((normal + e).norm(), 1e-15);
    EXPECT_LT((dn + (Mat2::Identity() - e * e.transpose()) / dist).norm(), 1e-14);
    const Vec2 c_moved = c + 0.25 * Vec2(-1, 3);
    EXPECT_NEAR(moved.gap(x, nullptr, nullptr), (x - c_moved).norm() - r, 1e-14);
  }
}

// The boundary of the square [0, 2] × [0, 1] (one p = 2 element, all four edges), deformed by
// the affine u = (0.1 + 0.05 x, −0.02 + 0.1 y) into the rectangle [0.1, 2.2] × [−0.02, 1.08],
// shall give every point the signed distance to that rectangle's nearest side as its gap,
// positive outside, with that side's outward normal — on each of the four local edges; and
// each side's stretch ds/dS, 1.05 along x and 1.1 along y.
TEST(DeformableBoundary, GapToADeformedSquareIsTheSignedDistance) {
  const mesh::Mesh m({Vec2(0, 0), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)}, {1, 2, 3, 4}, {{0, 1, 2, 3}},
                     {1}, {}, "square");
  fem::SpaceOptions o;
  o.degrees = {{2, 2}};
  const fem::DofMap dofs(m, o);
  const std::vector<mesh::ElementMap> maps = {mesh::ElementMap::blending(m, 0)};
  std::vector<int> edges;
  for (int e = 0; e < m.n_edges(); ++e) edges.push_back(e);
  ASSERT_EQ(edges.size(), 4u);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(dofs.n_dofs());
  for (int v = 0; v < 4; ++v) {  // linear: the vertex modes carry it, the edge modes are zero
    const Vec2 X = m.node(v);
    const int mode = dofs.vertex_mode(v);
    u(2 * mode) = 0.1 + 0.05 * X.x();
    u(2 * mode + 1) = -0.02 + 0.1 * X.y();
  }
  const DeformableBoundary boundary(m, dofs, maps, edges);
  boundary.set_displacement(u);
  struct Probe {
    Vec2 x;
    double gap;
    Vec2 normal;
  };
  const Probe probes[] = {
      {Vec2(1.15, 1.38), 0.3, Vec2(0, 1)},     // above the top
      {Vec2(2.4, 0.5), 0.2, Vec2(1, 0)},       // right of the right side
      {Vec2(1.0, -0.12), 0.1, Vec2(0, -1)},    // below the bottom
      {Vec2(-0.15, 0.6), 0.25, Vec2(-1, 0)},   // left of the left side
      {Vec2(1.15, 1.0), -0.08, Vec2(0, 1)},    // inside, nearest the top
      {Vec2(2.15, 0.4), -0.05, Vec2(1, 0)},    // inside, nearest the right side
  };
  for (const auto& pr : probes) {
    Vec2 normal;
    EXPECT_NEAR(boundary.gap(pr.x, &normal, nullptr), pr.gap, 1e-13) << pr.x.transpose();
    EXPECT_LT((normal - pr.normal).norm(), 1e-13) << pr.x.transpose();
  }
  // ds/dS along each side: 1.05 along x (the horizontal sides), 1.1 along y, at any t
  for (int k = 0; k < boundary.n_edges(); ++k) {
    const Vec2 along = boundary.undeformed(k, 1) - boundary.undeformed(k, -1);
    const double expected = std::abs(along.x()) > 0 ? 1.05 : 1.1;
    for (double t : {-1.0, -0.3, 0.6})
      EXPECT_NEAR(boundary.stretch(k, t), expected, 1e-14) << "edge " << k << " t " << t;
  }
}
