// The natural cubic spline through points: interpolation, smoothness, exactness on lines,
// fourth-order approximation of a circle, and the closest-point search against brute force.
#include "hpcontact/geometry/cubic_spline.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hpcontact/core/error.hpp"

using hpcontact::InputError;
using hpcontact::Vec2;
using hpcontact::geometry::CubicSpline;

namespace {

constexpr double pi = std::numbers::pi;

/// n + 1 points on the circle (centre c, radius r) from angle a0 to a1.
std::vector<Vec2> circle_points(Vec2 c, double r, double a0, double a1, int n) {
  std::vector<Vec2> p;
  for (int i = 0; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    p.push_back(c + r * Vec2(std::cos(a), std::sin(a)));
  }
  return p;
}

/// A wavy, unevenly spaced open curve.
std::vector<Vec2> wavy_points() {
  return {{0, 0}, {0.7, 0.3}, {1.5, 0.1}, {2.0, -0.4}, {3.1, -0.2}, {3.5, 0.5}, {4.8, 0.6}};
}

double knot(const CubicSpline& s, int i) {
  double t = 0;
  for (int k = 0; k < i; ++k) t += (s.points()[k + 1] - s.points()[k]).norm();
  return t;
}

}  // namespace

TEST(CubicSpline, PassesThroughItsPointsAtTheChordLengthKnots) {
  const CubicSpline s(wavy_points());
  for (int i = 0; i < 7; ++i) EXPECT_LT((s.point(knot(s, i)) - wavy_points()[i]).norm(), 1e-13) << i;
  EXPECT_NEAR(s.end(), knot(s, 6), 1e-14);
}

TEST(CubicSpline, IsTwiceContinuouslyDifferentiableAndNaturalAtItsEnds) {
  const CubicSpline s(wavy_points());
  const double e = 1e-7;
  for (int i = 1; i < 6; ++i) {
    const double t = knot(s, i);
    EXPECT_LT((s.point(t - e) - s.point(t + e)).norm(), 1e-6) << i;
    EXPECT_LT((s.derivative(t - e) - s.derivative(t + e)).norm(), 1e-5) << i;
    EXPECT_LT((s.second_derivative(t - e) - s.second_derivative(t + e)).norm(), 1e-5) << i;
  }
  EXPECT_LT(s.second_derivative(0).norm(), 1e-13);
  EXPECT_LT(s.second_derivative(s.end()).norm(), 1e-13);
  // The derivatives are those of the position (central differences inside the segments).
  for (double t : {0.3, 1.1, 2.6, 4.0, 5.5}) {
    const double h = 1e-5;
    EXPECT_LT((s.derivative(t) - (s.point(t + h) - s.point(t - h)) / (2 * h)).norm(), 1e-8) << t;
    EXPECT_LT((s.second_derivative(t) - (s.derivative(t + h) - s.derivative(t - h)) / (2 * h)).norm(),
              1e-7) << t;
  }
}

TEST(CubicSpline, ContinuesStraightBeyondItsEnds) {
  const CubicSpline s(wavy_points());
  const Vec2 d0 = s.derivative(0), d1 = s.derivative(s.end());
  EXPECT_LT((s.point(-2.0) - (wavy_points().front() - 2.0 * d0)).norm(), 1e-13);
  EXPECT_LT((s.point(s.end() + 3.0) - (wavy_points().back() + 3.0 * d1)).norm(), 1e-12);
  EXPECT_EQ(s.second_derivative(-1.0), Vec2::Zero());
}

TEST(CubicSpline, ReproducesAStraightLineExactly) {
  const Vec2 a(1, 2), dir = Vec2(3, -1).normalized();
  const CubicSpline s({a, a + 0.5 * dir, a + 2.0 * dir, a + 2.2 * dir, a + 5.0 * dir});
  for (double t : {-1.0, 0.0, 0.3, 1.7, 2.1, 4.9, 6.0}) {
    EXPECT_LT((s.point(t) - (a + t * dir)).norm(), 1e-13) << t;
    EXPECT_LT((s.derivative(t) - dir).norm(), 1e-13) << t;
    EXPECT_LT(s.second_derivative(t).norm(), 1e-12) << t;
  }
}

TEST(CubicSpline, ApproximatesACircleToFourthOrderAwayFromItsEnds) {
  // The natural end condition (x'' = 0) is wrong for a circle, so only the middle half is
  // measured; there the radial error must fall like h^4 (ratio 16 per halving; asserted > 12).
  const Vec2 c(0.5, -1);
  const double r = 2;
  double previous = 0;
  for (int n : {8, 16, 32, 64}) {
    const CubicSpline s(circle_points(c, r, 0, pi, n));
    double worst = 0;
    for (int k = 0; k <= 400; ++k) {
      const double t = s.end() * (0.25 + 0.5 * k / 400.0);
      worst = std::max(worst, std::abs((s.point(t) - c).norm() - r));
    }
    if (previous > 0) EXPECT_GT(previous / worst, 12) << "n = " << n << ": " << worst;
    previous = worst;
  }
  EXPECT_LT(previous, 1e-7 * r);
}

TEST(CubicSpline, FindsTheClosestPointLikeABruteForceSearch) {
  const CubicSpline s(wavy_points());
  std::vector<double> dense;
  for (int k = -20000; k <= 60000; ++k) dense.push_back(s.end() * k / 40000.0);
  for (const Vec2& x : {Vec2(0.9, 0.8), Vec2(2.0, -1.0), Vec2(2.2, 0.0), Vec2(-1.0, 0.5),
                        Vec2(6.0, 0.0), Vec2(3.3, 0.2), Vec2(1.5, 0.11), Vec2(4.0, 3.0)}) {
    const double t = s.closest_parameter(x);
    double best = 1e300;
    for (double u : dense) best = std::min(best, (s.point(u) - x).norm());
    const double d = (s.point(t) - x).norm();
    EXPECT_LE(d, best + 1e-12) << x.transpose();
    EXPECT_GT(d, best - 1e-4) << x.transpose();  // the dense grid's spacing is 1.3e-4
    if (d > 1e-12)  // the foot of the perpendicular
      EXPECT_LT(std::abs((s.point(t) - x).normalized().dot(s.derivative(t).normalized())), 1e-10)
          << x.transpose();
  }
}

TEST(CubicSpline, RefusesTooFewOrRepeatedPoints) {
  EXPECT_THROW(CubicSpline({Vec2(1, 1)}), InputError);
  EXPECT_THROW(CubicSpline({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(2, 0)}), InputError);
  EXPECT_NO_THROW(CubicSpline({Vec2(0, 0), Vec2(1, 0)}));
}
