// Property tests of the parametric edge curves: arcs, segments, reversal, arc_through, length.
#include "hpcontact/geometry/curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"

using hpcontact::InputError;
using hpcontact::Vec2;
using namespace hpcontact::geometry;

namespace {

constexpr double pi = std::numbers::pi;

/// Parameters in [0, 1] at which curves are sampled (interior, so central differences fit).
std::vector<double> sample_parameters() { return {0.01, 0.137, 0.25, 0.5, 0.618, 0.75, 0.99}; }

/// Arcs of various radii, centres, openings and both directions.
std::vector<CircularArc> sample_arcs() {
  return {CircularArc(Vec2(0, 0), 1.0, 0.0, pi / 2), CircularArc(Vec2(3, -2), 10.0, 1.0, -0.5),
          CircularArc(Vec2(-1, 4), 0.25, -pi, pi / 3), CircularArc(Vec2(0, 10), 10.0, -pi / 2, -pi)};
}

void expect_near(const Vec2& a, const Vec2& b, double tol, const std::string& what) {
  EXPECT_LE((a - b).norm(), tol) << what << ": (" << a.transpose() << ") vs (" << b.transpose()
                                 << ")";
}

}  // namespace

// A circular arc's tangent and second derivative shall be the derivatives of its points: central
// differences with h = 1e-5 agree to 1e-7 relative (truncation ~h²|x'''|/6 ~ 1e-10·r·dθ³,
// round-off ~1e-16·|x|/h ~ 1e-11·|x|).
TEST(CircularArc, DerivativesMatchFiniteDifferences) {
  const double h = 1e-5;
  for (const auto& arc : sample_arcs()) {
    const double dtheta = std::abs(arc.theta1() - arc.theta0());
    const double scale = arc.radius() * (1 + dtheta * dtheta) + arc.center().norm();
    for (double s : sample_parameters()) {
      const Vec2 fd1 = (arc.point(s + h) - arc.point(s - h)) / (2 * h);
      const Vec2 fd2 = (arc.tangent(s + h) - arc.tangent(s - h)) / (2 * h);
      expect_near(arc.tangent(s), fd1, 1e-7 * scale, arc.describe() + " tangent");
      expect_near(arc.second_derivative(s), fd2, 1e-7 * scale, arc.describe() + " x''");
    }
  }
}

// Every point of a circular arc shall lie on its circle, start at theta0 and end at theta1.
TEST(CircularArc, PointsLieOnTheCircleBetweenItsEndAngles) {
  for (const auto& arc : sample_arcs()) {
    const Vec2 c = arc.center();
    const double r = arc.radius();
    for (double s : sample_parameters())
      EXPECT_NEAR((arc.point(s) - c).norm(), r, 1e-14 * (r + c.norm())) << arc.describe();
    expect_near(arc.point(0), c + r * Vec2(std::cos(arc.theta0()), std::sin(arc.theta0())),
                1e-14 * (r + c.norm()), "start");
    expect_near(arc.point(1), c + r * Vec2(std::cos(arc.theta1()), std::sin(arc.theta1())),
                1e-14 * (r + c.norm()), "end");
  }
}

// The length of a quarter circle shall be pi r / 2 to 1e-12 relative.
TEST(CircularArc, QuarterCircleLength) {
  for (double r : {0.5, 1.0, 10.0, 1234.5}) {
    const auto arc = std::make_shared<CircularArc>(Vec2(1, -2), r, 0.3, 0.3 + pi / 2);
    EXPECT_NEAR(arc->length(), pi * r / 2, 1e-12 * pi * r / 2) << "r = " << r;
    // Clockwise traversal has the same length.
    EXPECT_NEAR(arc->reversed()->length(), pi * r / 2, 1e-12 * pi * r / 2) << "r = " << r;
  }
}

// The length of a segment and of a parabola (closed form) shall be computed to 1e-12 relative.
TEST(Curve, LengthOfSegmentAndParabola) {
  const LineSegment seg(Vec2(1, 2), Vec2(4, 6));
  EXPECT_NEAR(seg.length(), 5.0, 5e-12);
  // y = x², x in [0, 1]: L = (2 sqrt 5 + asinh 2) / 4.
  const FunctionCurve parabola([](double s) { return Vec2(s, s * s); },
                               [](double s) { return Vec2(1, 2 * s); }, "parabola");
  const double L = (2 * std::sqrt(5.0) + std::asinh(2.0)) / 4;
  EXPECT_NEAR(parabola.length(), L, 1e-12 * L);
}

// reversed() shall traverse the same points backwards: point(s) = original(1-s), the tangent
// flips sign and the second derivative is unchanged; reversing twice gives the original.
TEST(Curve, ReversedTraversesBackwards) {
  std::vector<CurvePtr> curves = {
      std::make_shared<CircularArc>(Vec2(3, -2), 10.0, 1.0, -0.5),
      std::make_shared<LineSegment>(Vec2(1, 2), Vec2(-3, 7)),
      std::make_shared<FunctionCurve>([](double s) { return Vec2(s, std::sin(3 * s)); },
                                      [](double s) { return Vec2(1, 3 * std::cos(3 * s)); },
                                      "sine")};
  for (const auto& c : curves) {
    const CurvePtr r = c->reversed();
    const CurvePtr rr = r->reversed();
    for (double s : {0.0, 0.1, 0.5, 0.77, 1.0}) {
      expect_near(r->point(s), c->point(1 - s), 1e-14 * (1 + c->point(1 - s).norm()),
                  c->describe() + " point");
      expect_near(r->tangent(s), -c->tangent(1 - s), 1e-13 * (1 + c->tangent(1 - s).norm()),
                  c->describe() + " tangent");
      // FunctionCurve's second derivative is a finite difference, hence the looser bound.
      expect_near(r->second_derivative(s), c->second_derivative(1 - s),
                  1e-6 * (1 + c->second_derivative(1 - s).norm()), c->describe() + " x''");
      expect_near(rr->point(s), c->point(s), 1e-14 * (1 + c->point(s).norm()),
                  c->describe() + " twice reversed");
    }
  }
}

// arc_through with ccw = 0 shall pick the shorter arc, in either direction, also when it crosses
// the branch cut of atan2 (the negative x axis), and shall end exactly at the given points.
TEST(ArcThrough, PicksTheShorterArc) {
  const Vec2 c(1, 1);
  const double r = 2;
  auto on = [&](double t) { return Vec2(c + r * Vec2(std::cos(t), std::sin(t))); };
  struct Case {
    double ta, tb, expected_sweep;
  };
  const std::vector<Case> cases = {{0.0, pi / 2, pi / 2},      {pi / 2, 0.0, -pi / 2},
                                   {0.2, 0.2 + 3.0, 3.0},       {0.2, 0.2 - 3.0, -3.0},
                                   {pi - 0.1, -pi + 0.2, 0.3}, {-pi + 0.2, pi - 0.1, -0.3}};
  for (const auto& k : cases) {
    const auto arc = arc_through(on(k.ta), on(k.tb), c, r, 0, "test");
    EXPECT_NEAR(arc->theta1() - arc->theta0(), k.expected_sweep, 1e-12)
        << "from " << k.ta << " to " << k.tb;
    expect_near(arc->point(0), on(k.ta), 1e-14 * 4, "start");
    expect_near(arc->point(1), on(k.tb), 1e-14 * 4, "end");
    EXPECT_NEAR(arc->length(), r * std::abs(k.expected_sweep), 1e-12 * r * 2 * pi);
  }
}

// arc_through shall honour ccw = +1 (counter-clockwise) and -1 (clockwise) even when that is the
// longer way round.
TEST(ArcThrough, HonoursExplicitDirection) {
  const Vec2 c(0, 0);
  const double r = 1;
  const Vec2 a(1, 0), b(0, 1);
  const auto ccw_short = arc_through(a, b, c, r, +1, "test");
  EXPECT_NEAR(ccw_short->theta1() - ccw_short->theta0(), pi / 2, 1e-12);
  const auto cw_long = arc_through(a, b, c, r, -1, "test");
  EXPECT_NEAR(cw_long->theta1() - cw_long->theta0(), -3 * pi / 2, 1e-12);
  // The clockwise arc from (1,0) to (0,1) passes through (0,-1) and (-1,0).
  expect_near(cw_long->point(1.0 / 3), Vec2(0, -1), 1e-14, "cw 1/3");
  expect_near(cw_long->point(2.0 / 3), Vec2(-1, 0), 1e-14, "cw 2/3");
  const auto ccw_long = arc_through(b, a, c, r, +1, "test");
  EXPECT_NEAR(ccw_long->theta1() - ccw_long->theta0(), 3 * pi / 2, 1e-12);
  expect_near(ccw_long->point(0.5), Vec2(-std::sqrt(0.5), -std::sqrt(0.5)), 1e-14, "ccw mid");
  // The tangent points in the direction of travel: ccw turns left around the centre.
  const Vec2 t = ccw_short->tangent(0.0);
  EXPECT_GT(a.x() * t.y() - a.y() * t.x(), 0.0);
  const Vec2 tc = cw_long->tangent(0.0);
  EXPECT_LT(a.x() * tc.y() - a.y() * tc.x(), 0.0);
}

// Diametrically opposite end points shall need a direction: InputError naming the key for
// ccw = 0, and the two half circles for ccw = +1 / -1.
TEST(ArcThrough, OppositePointsNeedADirection) {
  const Vec2 c(2, 3), a(5, 3), b(-1, 3);
  try {
    arc_through(a, b, c, 3.0, 0, "bodies[0].curves[2]");
    ADD_FAILURE() << "no InputError for diametrically opposite points without direction";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bodies[0].curves[2]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("opposite"), std::string::npos) << e.what();
  }
  const auto upper = arc_through(a, b, c, 3.0, +1, "test");
  expect_near(upper->point(0.5), Vec2(2, 6), 1e-14 * 6, "upper half");
  const auto lower = arc_through(a, b, c, 3.0, -1, "test");
  expect_near(lower->point(0.5), Vec2(2, 0), 1e-14 * 6, "lower half");
}

// End points off the circle (beyond tol·radius) shall be rejected with an InputError that names
// the key; points within the tolerance are accepted.
TEST(ArcThrough, RejectsPointsOffTheCircle) {
  const Vec2 c(0, 0);
  const double r = 10;
  for (int which = 0; which < 2; ++which) {
    Vec2 a(10, 0), b(0, 10);
    (which == 0 ? a : b) *= 1.001;
    try {
      arc_through(a, b, c, r, 0, "bodies[1].arc");
      ADD_FAILURE() << "no InputError for end point " << which << " off the circle";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bodies[1].arc"), std::string::npos) << e.what();
    }
  }
  EXPECT_NO_THROW(arc_through(Vec2(10 * (1 + 1e-8), 0), Vec2(0, 10), c, r, 0, "ok"));
  EXPECT_THROW(arc_through(Vec2(1, 0), Vec2(0, 1), c, -1.0, 0, "negative radius"), InputError);
  EXPECT_THROW(arc_through(Vec2(10, 0), Vec2(10, 0), c, r, 0, "zero length"), InputError);
}
