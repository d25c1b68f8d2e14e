// Property tests of the Gordon–Hall blending map: bilinear limit, exact curved edges, sector
// area, Jacobian.
#include "hpcontact/geometry/blending.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

using hpcontact::Mat2;
using hpcontact::Vec2;
using namespace hpcontact::geometry;

namespace {

constexpr double pi = std::numbers::pi;

/// n-point Gauss–Legendre rule on [-1, 1] by Newton's method on L_n (this test links only the
/// geometry module, so it does not use basis/quadrature.hpp). Nodes accurate to ~1e-15.
void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(pi * (i + 0.75) / (n + 0.5)), dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

/// The annular sector 1 <= r <= 2, 0 <= theta <= pi/3 as one blending element: E1 and E3 are
/// straight radial edges, E2 the outer arc (X2 -> X3), E4 the inner arc (X1 -> X4).
BlendingQuad annular_sector(double r1 = 1, double r2 = 2, double theta = pi / 3) {
  BlendingQuad q;
  q.vertices = {Vec2(r1, 0), Vec2(r2, 0), Vec2(r2 * std::cos(theta), r2 * std::sin(theta)),
                Vec2(r1 * std::cos(theta), r1 * std::sin(theta))};
  q.edges[1] = std::make_shared<CircularArc>(Vec2(0, 0), r2, 0.0, theta);
  q.edges[3] = std::make_shared<CircularArc>(Vec2(0, 0), r1, 0.0, theta);
  return q;
}

/// An element with four curved edges of different kinds, some given reversed.
BlendingQuad four_curved_edges() {
  BlendingQuad q;
  q.vertices = {Vec2(0, 0), Vec2(2, 0.2), Vec2(2.2, 1.8), Vec2(-0.1, 1.5)};
  // E1: X1 -> X2 with a bulge downwards (outwards).
  q.edges[0] = std::make_shared<FunctionCurve>(
      [](double s) { return Vec2(2 * s, 0.2 * s - 0.3 * std::sin(pi * s)); },
      [](double s) { return Vec2(2, 0.2 - 0.3 * pi * std::cos(pi * s)); }, "E1");
  // E2: X2 -> X3 as the reversal of an arc from X3 to X2 bulging to the right.
  const Vec2 a(2.2, 1.8), b(2, 0.2), m = 0.5 * (a + b);
  const Vec2 chord_normal = Vec2((b - a).y(), -(b - a).x()).normalized();  // right of a->b: inward
  const Vec2 centre = m + 3.0 * chord_normal;
  q.edges[1] = arc_through(a, b, centre, (a - centre).norm(), 0, "E2")->reversed();
  // E3: X4 -> X3, a segment given as a curve (zero deviation from the chord).
  q.edges[2] = std::make_shared<LineSegment>(Vec2(-0.1, 1.5), Vec2(2.2, 1.8));
  // E4: X1 -> X4, a gentle S-curve.
  q.edges[3] = std::make_shared<FunctionCurve>(
      [](double s) { return Vec2(-0.1 * s + 0.15 * std::sin(2 * pi * s), 1.5 * s); },
      [](double s) { return Vec2(-0.1 + 0.3 * pi * std::cos(2 * pi * s), 1.5); }, "E4");
  return q;
}

std::vector<std::array<double, 2>> random_points(int n, unsigned seed = 7) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::array<double, 2>> p(n);
  for (auto& x : p) x = {u(rng), u(rng)};
  return p;
}

}  // namespace

// With four straight edges (null or given as segments) the blending map shall be the bilinear
// map of its vertices, with the bilinear Jacobian, to round-off.
TEST(BlendingQuad, StraightEdgesGiveTheBilinearMap) {
  BlendingQuad q;
  q.vertices = {Vec2(0.1, -0.2), Vec2(3, 0.4), Vec2(2.5, 2.2), Vec2(-0.3, 1.7)};
  BlendingQuad s = q;
  for (int e = 0; e < 4; ++e) {
    static constexpr int ev[4][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}};
    s.edges[e] = std::make_shared<LineSegment>(q.vertices[ev[e][0]], q.vertices[ev[e][1]]);
  }
  const auto& X = q.vertices;
  for (auto [xi, eta] : random_points(50)) {
    const Vec2 bil = 0.25 * ((1 - xi) * (1 - eta) * X[0] + (1 + xi) * (1 - eta) * X[1] +
                             (1 + xi) * (1 + eta) * X[2] + (1 - xi) * (1 + eta) * X[3]);
    Mat2 Jb;
    Jb.col(0) = 0.25 * (-(1 - eta) * X[0] + (1 - eta) * X[1] + (1 + eta) * X[2] - (1 + eta) * X[3]);
    Jb.col(1) = 0.25 * (-(1 - xi) * X[0] - (1 + xi) * X[1] + (1 + xi) * X[2] + (1 - xi) * X[3]);
    for (const BlendingQuad* b : {&q, &s}) {
      Mat2 J;
      const Vec2 x = b->map(xi, eta, &J);
      EXPECT_LE((x - bil).norm(), 1e-14 * 4);
      EXPECT_LE((J - Jb).norm(), 1e-14 * 4);
    }
  }
  for (int k = 0; k < 4; ++k) {
    const double xi = (k == 1 || k == 2) ? 1 : -1, eta = k >= 2 ? 1 : -1;
    EXPECT_LE((q.map(xi, eta) - X[k]).norm(), 1e-15 * 4) << "vertex " << k;
  }
}

// The edges of an annular-sector element shall map exactly onto its arcs (every point at its
// radius from the centre, to 1e-14) and onto the straight radial sides.
TEST(BlendingQuad, AnnularSectorEdgesLieOnTheArcs) {
  const BlendingQuad q = annular_sector();
  for (int i = 0; i <= 40; ++i) {
    const double t = -1 + i / 20.0;
    EXPECT_NEAR(q.map(-1, t).norm(), 1.0, 1e-14) << "inner arc at eta = " << t;
    EXPECT_NEAR(q.map(1, t).norm(), 2.0, 1e-14) << "outer arc at eta = " << t;
    // Radial sides: angle 0 and pi/3.
    const Vec2 bottom = q.map(t, -1), top = q.map(t, 1);
    EXPECT_NEAR(bottom.y(), 0.0, 1e-14);
    EXPECT_NEAR(std::atan2(top.y(), top.x()), pi / 3, 1e-14);
    // For this element the blending map is the polar map r = 1.5 + xi/2, theta = (eta+1) pi/6.
    const Vec2 x = q.map(0.3, t);
    const double theta = (t + 1) * pi / 6;
    EXPECT_LE((x - 1.65 * Vec2(std::cos(theta), std::sin(theta))).norm(), 1e-14);
  }
}

// The area of the annular sector, ∫ det J over the reference square (Gauss 20×20), shall equal
// (theta/2)(r2² − r1²) to 1e-13 relative.
TEST(BlendingQuad, AnnularSectorAreaIsExact) {
  std::vector<double> x, w;
  gauss_legendre(20, x, w);
  for (auto [r1, r2, theta] : std::vector<std::array<double, 3>>{
           {1, 2, pi / 3}, {9, 10, pi / 2}, {0.5, 3, 2 * pi / 3}, {1, 1.001, 0.1}}) {
    const BlendingQuad q = annular_sector(r1, r2, theta);
    double area = 0;
    for (int i = 0; i < 20; ++i)
      for (int j = 0; j < 20; ++j) {
        Mat2 J;
        q.map(x[i], x[j], &J);
        area += w[i] * w[j] * J.determinant();
      }
    const double exact = 0.5 * theta * (r2 * r2 - r1 * r1);
    EXPECT_NEAR(area, exact, 1e-13 * exact) << "r in [" << r1 << ", " << r2 << "], theta " << theta;
  }
}

// Every curved edge shall be reproduced exactly by the map, whatever the other edges are:
// map on local edge e at parameter t is the curve's point at s = (t + 1)/2.
TEST(BlendingQuad, CurvedEdgesAreReproducedExactly) {
  const BlendingQuad q = four_curved_edges();
  for (int i = 0; i <= 20; ++i) {
    const double t = -1 + i / 10.0, s = 0.5 * (t + 1);
    EXPECT_LE((q.map(t, -1) - q.edges[0]->point(s)).norm(), 1e-14 * 4) << "E1 t = " << t;
    EXPECT_LE((q.map(1, t) - q.edges[1]->point(s)).norm(), 1e-14 * 4) << "E2 t = " << t;
    EXPECT_LE((q.map(t, 1) - q.edges[2]->point(s)).norm(), 1e-14 * 4) << "E3 t = " << t;
    EXPECT_LE((q.map(-1, t) - q.edges[3]->point(s)).norm(), 1e-14 * 4) << "E4 t = " << t;
  }
}

// The Jacobian returned by map() shall be the derivative of map(): central differences with
// h = 1e-6 agree to 1e-8 (truncation ~h²|x'''| ~ 1e-11, round-off ~1e-16·|x|/h ~ 1e-10).
TEST(BlendingQuad, JacobianMatchesFiniteDifferences) {
  const double h = 1e-6;
  for (const BlendingQuad& q : {annular_sector(), annular_sector(9, 10, pi / 2), four_curved_edges()}) {
    for (auto [xi, eta] : random_points(40, 11)) {
      Mat2 J;
      q.map(xi, eta, &J);
      Mat2 fd;
      fd.col(0) = (q.map(xi + h, eta) - q.map(xi - h, eta)) / (2 * h);
      fd.col(1) = (q.map(xi, eta + h) - q.map(xi, eta - h)) / (2 * h);
      EXPECT_LE((J - fd).norm(), 1e-8 * (1 + J.norm())) << "at (" << xi << ", " << eta << ")";
      EXPECT_GT(J.determinant(), 0.0);
    }
  }
}
