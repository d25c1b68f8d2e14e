// The rigid curve obstacle: its gap is the signed distance with the normal as gradient, its
// dn/dx that of finite differences; through points of a line or circle it is that plane or disc.
#include "hpcontact/contact/obstacle.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

using hpcontact::Mat2;
using hpcontact::Vec2;
using namespace hpcontact::contact;

namespace {

constexpr double pi = std::numbers::pi;

/// Points on the circle (centre c, radius r) from angle a0 to a1 (clockwise when a1 < a0).
std::vector<Vec2> circle_points(Vec2 c, double r, double a0, double a1, int n) {
  std::vector<Vec2> p;
  for (int i = 0; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    p.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

/// A bump between two flats: a crowned foundation.
std::vector<Vec2> bump_points() {
  std::vector<Vec2> p;
  for (int i = 0; i <= 24; ++i) {
    const double x = -3 + 0.25 * i;
    p.emplace_back(x, 0.4 * std::exp(-x * x));
  }
  return p;
}

}  // namespace

TEST(RigidCurve, TheGapIsTheSignedDistanceWithTheNormalAsGradient) {
  const RigidCurve curve(bump_points());
  const double h = 1e-6;
  for (const Vec2& x : {Vec2(0.1, 0.45), Vec2(0.5, 0.2), Vec2(-1.2, 0.05), Vec2(0.9, 0.3),
                        Vec2(-0.3, 0.3), Vec2(1.7, -0.02)}) {
    Vec2 n;
    Mat2 dn;
    const double g = curve.gap(x, &n, &dn);
    EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    // Body above the bump (to the left walking in +x): a point below the curve penetrates.
    const double below = curve.gap(x - Vec2(0, 1.0), nullptr, nullptr);
    EXPECT_LT(below, g);
    for (int j = 0; j < 2; ++j) {
      const Vec2 e = Vec2::Unit(j) * h;
      Vec2 np, nm;
      const double gp = curve.gap(x + e, &np, nullptr), gm = curve.gap(x - e, &nm, nullptr);
      EXPECT_NEAR((gp - gm) / (2 * h), n[j], 1e-7) << x.transpose() << " d/dx" << j;
      EXPECT_LT(((np - nm) / (2 * h) - dn.col(j)).norm(), 1e-5 * (1 + dn.norm()))
          << x.transpose() << " d/dx" << j << "\n" << dn;
    }
  }
}

TEST(RigidCurve, ThroughPointsOfALineItIsThatPlane) {
  const Vec2 a(0, 1), t = Vec2(2, 1).normalized(), normal(-t.y(), t.x());
  const RigidCurve curve({a - 3 * t, a, a + 0.7 * t, a + 4 * t});
  const RigidPlane plane(a, normal);
  for (const Vec2& x : {Vec2(0, 0), Vec2(1, 3), Vec2(-5, 2), Vec2(9, 1)}) {
    Vec2 nc, np;
    Mat2 dc, dp;
    EXPECT_NEAR(curve.gap(x, &nc, &dc), plane.gap(x, &np, &dp), 1e-13) << x.transpose();
    EXPECT_LT((nc - np).norm(), 1e-14);
    EXPECT_LT(dc.norm(), 1e-12);
  }
}

TEST(RigidCurve, ThroughPointsOfACircleItApproachesThatDisc) {
  // Walking clockwise keeps the outside on the left: the body outside a disc of radius 5.
  const Vec2 c(0, -5);
  const RigidCircle disc(c, 5, false);
  const RigidCurve curve(circle_points(c, 5, 0.75 * pi, 0.25 * pi, 64));
  for (const Vec2& x : {Vec2(0, 0.01), Vec2(0.4, -0.02), Vec2(-1.0, 0.2), Vec2(0.8, 0.0)}) {
    Vec2 nc, nd;
    Mat2 dc, dd;
    const double gc = curve.gap(x, &nc, &dc), gd = disc.gap(x, &nd, &dd);
    EXPECT_NEAR(gc, gd, 1e-7) << x.transpose();
    EXPECT_LT((nc - nd).norm(), 1e-6) << x.transpose();
    EXPECT_LT((dc - dd).norm(), 1e-3 * dd.norm()) << x.transpose() << "\n" << dc << "\n" << dd;
  }
}
