// The results of a contact state (model::evaluate_contact, model::BoundaryPressureProbe) for a
// displacement field known in closed form: the zone ends where its gap vanishes, the pressure
// from the stresses −n·σ·n, the penalty pressure ε_N ⟨−g⟩.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "hpcontact/model/boundary_pressure.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"

using namespace hpcontact;

namespace {

constexpr double kE = 1000, kNu = 0.3, kPenalty = 1e5;

/// The elastic field u = A + B + linear (zero body force, E = 1000, ν = 0.3, plane strain,
/// k = ν/(1 − ν), E' = E/(1 − ν²)), written out so that each term's stress is known by hand:
///  - A: ux = a x y, uy = −(a/2)(x² + k y²): ε = (a y, −a k y, 0), σyy = 0, σxx = E' a y;
///  - B: ux = −(b/2)(y² + k x²), uy = b x y: ε = (−b k x, b x, 0), σxx = 0, σyy = E' b x;
///  - uy += β x + γ₀: a shear γxy = β (σxy = μβ) and a translation.
/// On y = 0: uy = −(a/2) x² + β x + γ₀ = c (x − x₁)(x − x₂) for a = −2c, β = −c (x₁ + x₂),
/// γ₀ = c x₁ x₂ — the gap against the plane y = 0, negative (contact) between x₁ and x₂ — and
/// −n·σ·n = −σyy = −E' b x with n = (0, −1).
struct Field {
  double c, x1, x2, b;
  double a() const { return -2 * c; }
  double beta() const { return -c * (x1 + x2); }
  double gamma0() const { return c * x1 * x2; }
  static double k() { return kNu / (1 - kNu); }
  static double E_plane() { return kE / (1 - kNu * kNu); }
  double gap(double x) const { return c * (x - x1) * (x - x2); }
  double ux_bottom(double x) const { return -0.5 * b * k() * x * x; }
  double stress_pressure(double x) const { return -E_plane() * b * x; }
  /// ux, uy as formulas in the body's frame coordinates, given as formulas `xs`, `ys`.
  std::string ux(const std::string& xs, const std::string& ys) const {
    char s[400];
    std::snprintf(s, sizeof s, "%.17g*(%s)*(%s) - %.17g*((%s)^2 + %.17g*(%s)^2)", a(), xs.c_str(),
                  ys.c_str(), b / 2, ys.c_str(), k(), xs.c_str());
    return s;
  }
  std::string uy(const std::string& xs, const std::string& ys) const {
    char s[500];
    std::snprintf(s, sizeof s, "%.17g*(%s)*(%s) - %.17g*((%s)^2 + %.17g*(%s)^2) + %.17g*(%s) + %.17g",
                  b, xs.c_str(), ys.c_str(), a() / 2, xs.c_str(), k(), ys.c_str(), beta(), xs.c_str(),
                  gamma0());
    return s;
  }
};

/// [0, 3] × [0, 1] in three elements (nodes 1–4 along the bottom, 5–8 along the top), p = 3,
/// turned by `angle` about the origin (the field turned with it: u' = R u(Rᵀ x')), the field
/// prescribed on the whole boundary (the solution is the field: it is quadratic), the bottom in
/// contact with the plane through the origin along the turned x axis. Gaps, coordinates along
/// the plane and −n·σ·n do not change with the angle; positions turn.
model::ProblemSpec block(const Field& f, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  model::ProblemSpec spec;
  spec.file = spec.case_name = "contact-result";
  model::BodySpec b;
  b.name = "block";
  b.material.youngs_modulus = kE;
  b.material.poisson_ratio = kNu;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 2; ++j) {
      b.node_ids.push_back(1 + i + 4 * j);
      b.nodes.push_back({c * i - s * j, s * i + c * j});
    }
  for (int e = 0; e < 3; ++e) {
    b.element_ids.push_back(e + 1);
    b.elements.push_back({1 + e, 2 + e, 6 + e, 5 + e});
  }
  model::EdgeSetSpec bottom{"bottom", {{1, 2}, {2, 3}, {3, 4}}, {}};
  model::EdgeSetSpec rest{"rest", {{4, 8}, {8, 7}, {7, 6}, {6, 5}, {5, 1}}, {}};
  b.edge_sets = {bottom, rest};
  char xs[96], ys[96];  // the body-frame coordinates Rᵀ x'
  std::snprintf(xs, sizeof xs, "%.17g*x + %.17g*y", c, s);
  std::snprintf(ys, sizeof ys, "%.17g*x + %.17g*y", -s, c);
  const std::string ux = f.ux(xs, ys), uy = f.uy(xs, ys);
  model::ConstraintSpec all;
  all.edge_sets = {"bottom", "rest"};
  char cs[32], ss[32];
  std::snprintf(cs, sizeof cs, "%.17g", c);
  std::snprintf(ss, sizeof ss, "%.17g", s);
  all.ux = std::string(cs) + "*(" + ux + ") - " + ss + "*(" + uy + ")";
  all.uy = std::string(ss) + "*(" + ux + ") + " + cs + "*(" + uy + ")";
  b.constraints = {all};
  spec.bodies.push_back(b);
  model::ContactPairSpec cp;
  cp.enforcement = model::Enforcement::penalty;
  cp.body = "block";
  cp.edge_sets = {"bottom"};
  cp.obstacle.kind = model::ObstacleKind::plane;
  cp.obstacle.normal = {-s, c};
  cp.penalty = kPenalty;
  cp.quadrature = 10;
  spec.contact = {cp};
  spec.discretization.degree = {3, 3};
  return spec;
}

/// The body-frame coordinates of a point of the turned block.
Vec2 body_frame(const Vec2& x, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * x.x() + s * x.y(), -s * x.x() + c * x.y()};
}

}  // namespace

// The zone ends of a state shall be the roots x₁, x₂ of its gap on the undeformed boundary (to
// the root finder's tolerance on the gap, 1e-14 (1 + |x|): 2e-11 in position here), moved by the
// displacement there on the deformed one; both are the outer ends, and the zone's extent along
// the plane runs between them (no half width: the zone is not symmetric about the plane's
// point); a root on the node between two edges (x₁ = 1) is found as well. The pressure from
// the stresses at each contact point shall be −E' b X, the closed form, and the penalty pressure
// ε_N ⟨−g⟩. On the block as given and turned by 0.4 rad (where −n·σ·n takes all three stresses).
TEST(ContactResult, ZoneEndsAndStressPressureOfAKnownField) {
  for (const double angle : {0.0, 0.4})
    for (const Field f : {Field{1e-3, 0.6, 2.3, -5e-4}, Field{1e-3, 1.0, 2.45, -5e-4}}) {
      const auto spec = block(f, angle);
      const auto d = model::discretize(spec);
      const Eigen::VectorXd u = model::solve_linear(d, {}).u;
      const auto pairs = model::make_contact_pairs(spec, d);
      const auto r = model::evaluate_contact(d, pairs.front(), u);
      ASSERT_EQ(r.gamma_star.size(), 2u) << f.x1;
      ASSERT_EQ(r.outer_ends.size(), 2u);
      const double roots[] = {f.x1, f.x2};
      for (int k = 0; k < 2; ++k) {
        // The root finder stops at |g| <= 1e-14 (1 + |x|): the closed-form gap there is as
        // small (factor 2 for the round-off of the discrete field), the position off by that / |g'|.
        const Vec2 X = body_frame(r.gamma_star[k], angle), x = body_frame(r.gamma_star_deformed[k], angle);
        const double slope = std::abs(f.c * (roots[k] - roots[1 - k]));
        const double g_tol = 2e-14 * (1 + x.norm());
        EXPECT_LE(std::abs(f.gap(X.x())), g_tol) << "root " << roots[k];
        EXPECT_NEAR(X.x(), roots[k], g_tol / slope) << "root " << roots[k];
        EXPECT_NEAR(X.y(), 0, 1e-14);
        EXPECT_NEAR(x.x(), X.x() + f.ux_bottom(X.x()), 1e-14) << "root " << roots[k];
        EXPECT_NEAR(x.y(), f.gap(X.x()), 1e-14);
      }
      EXPECT_FALSE(r.half_width) << "an asymmetric zone has no half width";
      ASSERT_TRUE(r.zone);
      const double a = body_frame(r.gamma_star[0], angle).x(), b = body_frame(r.gamma_star[1], angle).x();
      EXPECT_NEAR(r.zone->first, std::min(a, b), 1e-14);
      EXPECT_NEAR(r.zone->second, std::max(a, b), 1e-14);
      EXPECT_NEAR(r.contact_length, std::abs(b - a), 1e-14);
      const auto& points = pairs.front().points;
      ASSERT_EQ(r.minus_sigma_nn.size(), points.size());
      ASSERT_EQ(r.pressure.size(), points.size());
      for (size_t i = 0; i < points.size(); ++i) {
        const double X = body_frame(points[i].X, angle).x();
        EXPECT_NEAR(r.minus_sigma_nn[i], f.stress_pressure(X), 1e-9 * kE * 1e-3) << "X " << X;
        // A flat boundary on the plane: along the obstacle is along the boundary (dS/ds = 1).
        EXPECT_NEAR(r.pressure_from_stress[i], f.stress_pressure(X), 1e-9 * kE * 1e-3) << "X " << X;
        EXPECT_NEAR(r.pressure[i], r.states[i].pressure, 1e-9) << "X " << X;
        EXPECT_NEAR(r.states[i].gap, f.gap(X), 1e-13) << "X " << X;
        EXPECT_NEAR(r.states[i].pressure, kPenalty * std::max(0.0, -f.gap(X)), 1e-9) << "X " << X;
      }
    }
}

// The pressure probe at s (the coordinate along the plane) shall find the boundary point at s,
// the pressure from the stresses −E' b s and the penalty pressure
// ε_N ⟨−g(s)⟩ (to 1e-9 of their scale), on nodes and inside edges, and nothing beyond the
// contact boundary; on the block as given and turned.
TEST(ContactResult, PressureProbeOfAKnownField) {
  const Field f{1e-3, 0.6, 2.3, -5e-4};
  for (const double angle : {0.0, 0.4}) {
    const auto spec = block(f, angle);
    const auto d = model::discretize(spec);
    const Eigen::VectorXd u = model::solve_linear(d, {}).u;
    const auto pairs = model::make_contact_pairs(spec, d);
    const model::BoundaryPressureProbe probe(d, pairs.front(), u);
    for (double s : {0.0, 0.37, 1.0, 1.5, 2.0, 2.29, 2.31, 3.0}) {
      const auto bp = probe(s);
      ASSERT_TRUE(bp.has_value()) << s;
      const Vec2 X = body_frame(bp->X, angle);
      EXPECT_NEAR(X.x(), s, 1e-12);
      EXPECT_NEAR(X.y(), 0, 1e-14);
      EXPECT_NEAR(bp->minus_sigma_nn, f.stress_pressure(s), 1e-9 * kE * 1e-3) << s;
      EXPECT_NEAR(bp->pressure_from_stress, f.stress_pressure(s), 1e-9 * kE * 1e-3) << s;
      EXPECT_NEAR(bp->traction, kPenalty * std::max(0.0, -f.gap(s)), 1e-9 * kPenalty * 1e-3) << s;
      EXPECT_NEAR(bp->pressure, bp->traction, 1e-9 * kPenalty * 1e-3) << s;
    }
    EXPECT_FALSE(probe(-0.01).has_value());
    EXPECT_FALSE(probe(3.01).has_value());
  }
}
