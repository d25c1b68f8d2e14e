// The rigid profile obstacle against hand-computed gaps and normals on segments, fillet arcs and
// sharp convex and concave corners, against the plane and the circle it can be, and its
// derivatives against central differences.
#include "hpcontact/contact/obstacle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using hpcontact::Mat2;
using hpcontact::Vec2;
using hpcontact::geometry::ProfileSpec;
using namespace hpcontact::contact;

namespace {

/// The obstacle is the quadrant x < 0, y < 0: its top, then down its wall; the body above and
/// to the right sees a convex corner at the origin.
ProfileSpec convex_corner(double fillet = 0) {
  return {{Vec2(-4, 0), Vec2(0, 0), Vec2(0, -4)}, fillet > 0 ? std::vector<double>{fillet} : std::vector<double>{},
          false};
}

/// A groove's corner: down the wall x = 0, then along the bottom y = 0; the body in x > 0, y > 0
/// sees a concave corner at the origin.
ProfileSpec concave_corner(double fillet = 0) {
  return {{Vec2(0, 4), Vec2(0, 0), Vec2(4, 0)}, fillet > 0 ? std::vector<double>{fillet} : std::vector<double>{},
          false};
}

/// The square of side 2 r about c with every corner rounded by r: the circle of radius r.
/// Clockwise the body is outside it (a disc), counter-clockwise inside (a hole).
ProfileSpec rounded_square(Vec2 c, double r, bool clockwise) {
  std::vector<Vec2> p{c + Vec2(-r, -r), c + Vec2(r, -r), c + Vec2(r, r), c + Vec2(-r, r)};
  if (clockwise) std::swap(p[1], p[3]);
  return {p, {r, r, r, r}, true};
}

struct Expected {
  Vec2 x;
  double gap;
  Vec2 normal;
};

void expect_gaps(const RigidProfile& profile, const std::vector<Expected>& cases) {
  for (const auto& c : cases) {
    Vec2 n;
    EXPECT_NEAR(profile.gap(c.x, &n, nullptr), c.gap, 1e-14) << c.x.transpose();
    EXPECT_LT((n - c.normal).norm(), 1e-14) << c.x.transpose() << ": n = " << n.transpose();
  }
}

/// dg/dx = n and dn/dx of `profile` at x against central differences of step h.
void expect_derivatives(const RigidProfile& profile, const Vec2& x) {
  const double h = 1e-5;
  Vec2 n;
  Mat2 dn;
  profile.gap(x, &n, &dn);
  for (int j = 0; j < 2; ++j) {
    const Vec2 e = h * Vec2::Unit(j);
    Vec2 np, nm;
    const double gp = profile.gap(x + e, &np, nullptr), gm = profile.gap(x - e, &nm, nullptr);
    EXPECT_NEAR((gp - gm) / (2 * h), n(j), 1e-7) << x.transpose() << " d/dx" << j;
    EXPECT_LT(((np - nm) / (2 * h) - dn.col(j)).norm(), 1e-7) << x.transpose() << " d/dx" << j;
  }
}

}  // namespace

// On a segment the gap shall be the distance along its normal (the body's side positive), beyond
// an open profile's ends along its continuation; one segment shall be the plane through it.
TEST(RigidProfile, OneSegmentIsThePlaneThroughIt) {
  const Vec2 a(1, 2), b(4, 6);  // direction (3, 4)/5, normal (−4, 3)/5
  const RigidProfile profile({{a, b}, {}, false});
  const RigidPlane plane(a, Vec2(-4, 3));
  for (const Vec2& x : {Vec2(0, 5), Vec2(10, 1), Vec2(-30, -35), Vec2(2.5, 4), Vec2(40, 2)}) {
    Vec2 n, np;
    Mat2 dn;
    EXPECT_NEAR(profile.gap(x, &n, &dn), plane.gap(x, &np, nullptr), 1e-13) << x.transpose();
    EXPECT_LT((n - np).norm(), 1e-15);
    EXPECT_EQ(dn.norm(), 0.0);
  }
}

// At a sharp convex corner a point in its fan of normals shall have the corner as closest
// point: the gap its distance, the normal the direction from the corner; a point inside the
// obstacle the nearer of the two sides.
TEST(RigidProfile, SharpConvexCorner) {
  const RigidProfile profile(convex_corner());
  expect_gaps(profile, {{Vec2(0.3, 0.4), 0.5, Vec2(0.6, 0.8)},
                        {Vec2(-1, 0.5), 0.5, Vec2(0, 1)},
                        {Vec2(0.2, -1), 0.2, Vec2(1, 0)},
                        {Vec2(-0.1, -0.3), -0.1, Vec2(1, 0)},
                        {Vec2(-0.3, -0.1), -0.1, Vec2(0, 1)},
                        {Vec2(-7, 0.25), 0.25, Vec2(0, 1)}});  // on the continuation
  Vec2 n;
  Mat2 dn;
  profile.gap(Vec2(0.3, 0.4), &n, &dn);
  EXPECT_LT((dn - (Mat2::Identity() - n * n.transpose()) / 0.5).norm(), 1e-14);
}

// At a sharp concave corner a point outside the obstacle shall have the nearer side's gap; a
// point beyond the corner inside the obstacle the corner's distance, negative, with the normal
// towards the corner; one that projects onto one side alone that side's.
TEST(RigidProfile, SharpConcaveCorner) {
  const RigidProfile profile(concave_corner());
  expect_gaps(profile, {{Vec2(0.3, 0.1), 0.1, Vec2(0, 1)},
                        {Vec2(0.1, 0.3), 0.1, Vec2(1, 0)},
                        {Vec2(-0.3, -0.4), -0.5, Vec2(0.6, 0.8)},
                        {Vec2(0.5, -0.2), -0.2, Vec2(0, 1)},
                        {Vec2(-0.2, 0.5), -0.2, Vec2(1, 0)}});
  Vec2 n;
  Mat2 dn;
  profile.gap(Vec2(-0.3, -0.4), &n, &dn);
  EXPECT_LT((dn + (Mat2::Identity() - n * n.transpose()) / 0.5).norm(), 1e-14);
}

// A fillet of radius r shall replace the corner by the arc tangent to both sides: the gap that
// of its circle (centre r from both sides), the body inside it at a concave corner and outside
// at a convex one; the sides' gaps unchanged beyond the tangent points.
TEST(RigidProfile, FilletArcs) {
  const double s = std::sqrt(0.5);
  const RigidProfile concave(concave_corner(1));  // centre (1, 1), tangent points (0, 1), (1, 0)
  expect_gaps(concave, {{Vec2(0.5, 0.5), 1 - std::sqrt(0.5), Vec2(s, s)},
                        {Vec2(0.2, 3), 0.2, Vec2(1, 0)},
                        {Vec2(3, -0.1), -0.1, Vec2(0, 1)},
                        {Vec2(-1, -1), -(2 * std::sqrt(2.0) - 1), Vec2(s, s)}});
  const RigidProfile convex(convex_corner(1));  // centre (−1, −1)
  expect_gaps(convex, {{Vec2(0.5, 0.5), 1.5 * std::sqrt(2.0) - 1, Vec2(s, s)},
                       {Vec2(-2, 0.3), 0.3, Vec2(0, 1)},
                       {Vec2(-1 + 0.6, -1 + 0.8), 0, Vec2(0.6, 0.8)},
                       {Vec2(-0.1, -0.1), -(1 - 0.9 * std::sqrt(2.0)), Vec2(s, s)}});
}

// A closed square rounded at every corner by half its side shall be the circle: clockwise the
// disc, counter-clockwise the hole, gap, normal and dn/dx to round-off.
TEST(RigidProfile, ARoundedSquareIsTheCircle) {
  const Vec2 c(2, -1);
  const double r = 1.5;
  for (bool clockwise : {true, false}) {
    const RigidProfile profile(rounded_square(c, r, clockwise));
    const RigidCircle circle(c, r, !clockwise);
    for (const Vec2& x : {Vec2(5, 3), Vec2(2.3, -1.2), Vec2(0, -1), Vec2(-4, -9), Vec2(2, 0.2),
                          Vec2(3.2, -2.4)}) {
      Vec2 n, nc;
      Mat2 dn, dnc;
      EXPECT_NEAR(profile.gap(x, &n, &dn), circle.gap(x, &nc, &dnc), 1e-14) << x.transpose();
      EXPECT_LT((n - nc).norm(), 1e-14) << x.transpose();
      EXPECT_LT((dn - dnc).norm(), 1e-13) << x.transpose();
    }
  }
}

// dg/dx shall be the normal and dn/dx that of central differences (step 1e-5, to 1e-7) on
// segments, arcs, in a convex corner's fan and beyond a concave one.
TEST(RigidProfile, DerivativesAgreeWithCentralDifferences) {
  const RigidProfile sharp_convex(convex_corner()), sharp_concave(concave_corner());
  const RigidProfile round_convex(convex_corner(0.8)), round_concave(concave_corner(0.8));
  for (const Vec2& x : {Vec2(0.3, 0.4), Vec2(0.05, 0.9), Vec2(1.2, 0.02), Vec2(-2, 0.3), Vec2(-0.1, -0.3)})
    expect_derivatives(sharp_convex, x);
  for (const Vec2& x : {Vec2(-0.3, -0.4), Vec2(-0.01, -0.2), Vec2(0.3, 0.1), Vec2(0.5, -0.2)})
    expect_derivatives(sharp_concave, x);
  for (const Vec2& x : {Vec2(0.3, 0.4), Vec2(-0.3, 0.1), Vec2(-0.5, -0.4), Vec2(0.1, -2)})
    expect_derivatives(round_convex, x);
  for (const Vec2& x : {Vec2(0.3, 0.4), Vec2(0.1, 0.1), Vec2(-0.2, -0.3), Vec2(0.2, 2)})
    expect_derivatives(round_concave, x);
}

// The normal shall turn continuously as a point travels round a convex corner at a fixed
// distance (from the top's normal through the fan to the wall's), the gap staying that distance.
TEST(RigidProfile, TheNormalIsContinuousRoundAConvexCorner) {
  const RigidProfile profile(convex_corner());
  const double d = 0.25;
  Vec2 previous(0, 1);
  for (int i = 0; i <= 400; ++i) {
    // Along the top, round the corner on the circle of radius d, then down the wall.
    const double t = -1 + 3.0 * i / 400;
    const double angle = std::clamp(t, 0.0, 1.0) * std::acos(-1.0) / 2;
    const Vec2 x = t < 0 ? Vec2(t, d) : t > 1 ? Vec2(d, 1 - t) : Vec2(d * std::sin(angle), d * std::cos(angle));
    Vec2 n;
    EXPECT_NEAR(profile.gap(x, &n, nullptr), d, 1e-14) << t;
    EXPECT_LT((n - previous).norm(), 0.02) << t;
    previous = n;
  }
  EXPECT_LT((previous - Vec2(1, 0)).norm(), 1e-15);
}
