// Element shape measures against closed forms: rectangles, a parallelogram, a trapezoid, an arc
// edge; and the warnings they give.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "hpcontact/geometry/curve.hpp"
#include "hpcontact/mesh/element_map.hpp"
#include "hpcontact/mesh/element_shape.hpp"
#include "hpcontact/mesh/mesh.hpp"

using hpcontact::Vec2;
using namespace hpcontact::mesh;

namespace {

/// One element with the corners a, b, c, d (counter-clockwise).
Mesh one_element(Vec2 a, Vec2 b, Vec2 c, Vec2 d, std::vector<EdgeCurve> curves = {}) {
  return Mesh({a, b, c, d}, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {7}, curves, "test");
}

ElementShape shape_of(const Mesh& m) { return element_shape(ElementMap::blending(m, 0), 4); }

}  // namespace

// An a × b rectangle: J = diag(a/2, b/2) everywhere, so the aspect ratio is max(a, b)/min(a, b),
// the Jacobian ratio 1, the area a b, and its edges a and b long.
TEST(ElementShape, RectangleHasItsSideRatio) {
  for (const auto [a, b] : {std::pair{1.0, 1.0}, std::pair{5.0, 0.02}, std::pair{0.3, 2.4}}) {
    const Mesh m = one_element({0, 0}, {a, 0}, {a, b}, {0, b});
    const ElementShape s = shape_of(m);
    EXPECT_NEAR(s.aspect_ratio, std::max(a, b) / std::min(a, b), 1e-12 * std::max(a, b) / std::min(a, b));
    EXPECT_NEAR(s.jacobian_ratio, 1.0, 1e-12);
    EXPECT_NEAR(s.area, a * b, 1e-13 * a * b);
    const ElementMap map = ElementMap::blending(m, 0);
    EXPECT_NEAR(edge_length(map, 0, 4), a, 1e-13 * a);  // E1, along ξ
    EXPECT_NEAR(edge_length(map, 1, 4), b, 1e-13 * b);  // E2, along η
  }
}

// A parallelogram (0,0), (2,0), (3,1), (1,1): J constant, det 1 (ratio 1), singular values of
// [[1, 0.5], [0, 0.5]]: σ² = (1.5 ± √(1.5² − 4·0.25))/2, ratio √((1.5 + √1.25)/(1.5 − √1.25)).
TEST(ElementShape, ParallelogramIsStretchedNotDistorted) {
  const ElementShape s = shape_of(one_element({0, 0}, {2, 0}, {3, 1}, {1, 1}));
  const double r = std::sqrt((1.5 + std::sqrt(1.25)) / (1.5 - std::sqrt(1.25)));
  EXPECT_NEAR(s.aspect_ratio, r, 1e-12 * r);
  EXPECT_NEAR(s.jacobian_ratio, 1.0, 1e-12);
  EXPECT_NEAR(s.area, 2.0, 1e-13);
}

// A trapezoid (0,0), (4,0), (3,1), (1,1): det J = (3 − η)/4, linear in η, so over a Gauss grid
// of 4 points the ratio is (3 − η_min)/(3 − η_max) = (3 + η₄)/(3 − η₄), η₄ the largest point.
TEST(ElementShape, TrapezoidJacobianRatioIsItsDeterminantsRatio) {
  const ElementShape s = shape_of(one_element({0, 0}, {4, 0}, {3, 1}, {1, 1}));
  const double eta = std::sqrt(3.0 / 7 + 2.0 / 7 * std::sqrt(6.0 / 5));
  EXPECT_NEAR(s.jacobian_ratio, (3 + eta) / (3 - eta), 1e-12);
  EXPECT_NEAR(s.area, 3.0, 1e-13);
}

// A quarter of an annulus, r from 1 to 2: its outer arc edge is π long, to quadrature accuracy
// (blending is exact: the arc itself).
TEST(ElementShape, ArcEdgeLengthIsTheArcs) {
  const double pi = std::numbers::pi;
  auto inner = std::make_shared<hpcontact::geometry::CircularArc>(Vec2(0, 0), 1.0, pi / 2, 0.0);
  auto outer = std::make_shared<hpcontact::geometry::CircularArc>(Vec2(0, 0), 2.0, 0.0, pi / 2);
  const Mesh m = one_element({1, 0}, {2, 0}, {0, 2}, {0, 1}, {{1, 2, outer}, {3, 0, inner}});
  const ElementMap map = ElementMap::blending(m, 0);
  EXPECT_NEAR(edge_length(map, 1, 12), pi, 1e-12);
  EXPECT_NEAR(element_shape(map, 12).area, 0.75 * pi, 1e-12);
}

// The warnings: a needle along a contact edge (5 × 0.02: ratio 250) is named with its value;
// the same element with the short side on the contact edge, or with no contact edge, is not
// (its aspect ratio 250 is below the general limit).
TEST(ElementShape, NeedleAlongAContactEdgeIsWarned) {
  const Mesh m = one_element({0, 0}, {5, 0}, {5, 0.02}, {0, 0.02});
  const std::vector<ElementMap> maps{ElementMap::blending(m, 0)};
  const int bottom = m.quad_edge(0, 0), side = m.quad_edge(0, 1);
  const auto w = shape_warnings(m, maps, {bottom}, "f.yaml: bodies[0] (b)");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("f.yaml: bodies[0] (b): 1 element(s) on a contact edge"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("element 7, has 250"), std::string::npos) << w[0];
  EXPECT_TRUE(shape_warnings(m, maps, {side}, "f").empty());
  EXPECT_TRUE(shape_warnings(m, maps, {}, "f").empty());
  // beyond the general limit: an aspect ratio of 400 anywhere
  const Mesh n = one_element({0, 0}, {8, 0}, {8, 0.02}, {0, 0.02});
  const auto v = shape_warnings(n, {ElementMap::blending(n, 0)}, {}, "f");
  ASSERT_EQ(v.size(), 1u);
  EXPECT_NE(v[0].find("with an aspect ratio above 300; the worst, element 7, has 400"), std::string::npos) << v[0];
}
