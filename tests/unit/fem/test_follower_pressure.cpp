// Property tests of the follower pressure on a curved edge: its resultant is the pressure times
// the deformed chord (the deformed ring's projected area when axisymmetric), and its load
// stiffness is the derivative of its force.
#include "hpcontact/fem/follower_pressure.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "fem_test_meshes.hpp"
#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/mesh/element_map.hpp"

using namespace hpcontact;

namespace {

struct SectorElement {
  fem::DofMap dofs;
  mesh::ElementMap map;
};

/// The annular sector 1 <= r <= 2 (exact arcs: local edge 1 outer, 3 inner) at degree p.
SectorElement sector(int p) {
  const auto m = fem_test::sector_quad();
  fem::SpaceOptions o;
  o.degrees = {{p, p}};
  return {fem::DofMap(m, o), mesh::ElementMap::blending(m, 0)};
}

/// A smooth, not small displacement of every mode (component-blocked): the edge is moved and
/// turned by some 10 % of its length.
Eigen::VectorXd displacement(int n) {
  Eigen::VectorXd u(2 * n);
  for (int i = 0; i < 2 * n; ++i) u(i) = 0.15 * std::sin(1.7 * i + 0.4) / (1 + i % n);
  return u;
}

/// The deformed position of local edge le at t.
Vec2 deformed(const SectorElement& s, int le, double t, const Eigen::VectorXd& u) {
  const auto& space = s.dofs.element(0);
  const int n = space.n_modes();
  const auto r = fem::edge_reference_point(le, t);
  Eigen::VectorXd N(n);
  space.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
  return s.map.map(r[0], r[1]) + Vec2(N.dot(u.head(n)), N.dot(u.tail(n)));
}

Vec2 resultant(const Eigen::VectorXd& f, int n) {
  // the vertex modes sum to one on the element: the work on a unit translation
  return Vec2(f.head(n).head(4).sum(), f.tail(n).head(4).sum());
}

const fem::PressureFn kUniform = [](const Vec2&) { return 2.5; };

}  // namespace

// A uniform follower pressure p on a deformed curved edge shall have the resultant
// −p t R (x(1) − x(−1)) (plane, thickness t: ∫ n ds is the turned chord of the deformed edge)
// and along the axis p π (r(1)² − r(−1)²) (axisymmetric: ∫ 2π r n_z ds over the deformed
// ring), to 1e-12 relative: exact integrals of the quadrature (the arc's map is integrated by
// 13+ Gauss points, to round-off), on the inner and the outer arc, p = 3 … 6.
TEST(FollowerPressure, ResultantIsThatOfTheDeformedEdge) {
  const double p = 2.5, thickness = 0.7;
  for (int deg = 3; deg <= 6; ++deg) {
    const SectorElement s = sector(deg);
    const int n = s.dofs.element(0).n_modes();
    const Eigen::VectorXd u = displacement(n);
    for (int le : {1, 3}) {
      const Vec2 a = deformed(s, le, -1, u), b = deformed(s, le, 1, u);
      // the outward rotation of the edge's tangent (clockwise on edges 0, 1)
      const Vec2 chord = b - a;
      const Vec2 turned = le < 2 ? Vec2(chord.y(), -chord.x()) : Vec2(-chord.y(), chord.x());
      const auto plane = fem::follower_pressure(s.dofs.element(0), s.map, le, -1, 1, deg + 9,
                                                fem::OutOfPlane(thickness), u, kUniform, false);
      const Vec2 exact_plane = -p * thickness * turned;
      EXPECT_LE((resultant(plane.f, n) - exact_plane).norm(), 1e-12 * exact_plane.norm())
          << "p = " << deg << ", edge " << le;
      const auto axi = fem::follower_pressure(s.dofs.element(0), s.map, le, -1, 1, deg + 9,
                                              fem::OutOfPlane(1.0, true), u, kUniform, false);
      // n_z ds = (R x_t)_y dt = ∓ dr/dt: −p ∫ 2π r (∓ dr) = ±p π (r_b² − r_a²)
      const double sign = le < 2 ? 1.0 : -1.0;
      const double exact_axial = sign * p * std::numbers::pi * (b.x() * b.x() - a.x() * a.x());
      EXPECT_NEAR(resultant(axi.f, n).y(), exact_axial, 1e-12 * std::abs(exact_axial))
          << "axisymmetric, p = " << deg << ", edge " << le;
    }
  }
}

// The load stiffness K = ∂f/∂u of the follower pressure shall be the central differences of its
// force to 1e-9 relative (of K's largest entry), plane and axisymmetric, on a curved edge, p = 3
// and 5, on a part [−0.4, 0.7] of the edge as penetration integrates. f is linear (plane) or
// quadratic (axisymmetric: the ring 2π x times the turned tangent) in u, so central differences
// have no truncation error: what is left is round-off, ~1e-16 |f| / h with h = 1e-5.
TEST(FollowerPressure, LoadStiffnessIsTheDerivativeOfTheForce) {
  for (int deg : {3, 5})
    for (bool axisymmetric : {false, true}) {
      const SectorElement s = sector(deg);
      const auto& space = s.dofs.element(0);
      const int n = space.n_modes();
      const fem::OutOfPlane measure(0.7, axisymmetric);
      const fem::PressureFn pressure = [](const Vec2& X) { return 1.5 + X.y() * X.x(); };
      const Eigen::VectorXd u = displacement(n);
      for (int le : {1, 3}) {
        const auto F = fem::follower_pressure(space, s.map, le, -0.4, 0.7, deg + 9, measure, u, pressure, true);
        Eigen::MatrixXd K_fd(2 * n, 2 * n);
        const double h = 1e-5;
        for (int b = 0; b < 2 * n; ++b) {
          Eigen::VectorXd up = u, um = u;
          up(b) += h;
          um(b) -= h;
          K_fd.col(b) = (fem::follower_pressure(space, s.map, le, -0.4, 0.7, deg + 9, measure, up, pressure, false).f -
                         fem::follower_pressure(space, s.map, le, -0.4, 0.7, deg + 9, measure, um, pressure, false).f) /
                        (2 * h);
        }
        const double scale = F.K.cwiseAbs().maxCoeff();
        EXPECT_GT(scale, 0.0);
        EXPECT_LE((F.K - K_fd).cwiseAbs().maxCoeff(), 1e-9 * scale)
            << (axisymmetric ? "axisymmetric" : "plane") << ", p = " << deg << ", edge " << le;
        // not symmetric: a follower pressure is not conservative on an open edge
        EXPECT_GT((F.K - F.K.transpose()).cwiseAbs().maxCoeff(), 1e-3 * scale);
      }
    }
}
