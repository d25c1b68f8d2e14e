// Property tests of the exact surfaces: each maps onto itself, fixes its own points, and has the
// derivative its finite differences give.
#include "hpcontact/geometry/surface.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <tuple>
#include <vector>

#include "hpcontact/core/error.hpp"

using namespace hpcontact;
using namespace hpcontact::geometry;

namespace {

std::vector<SurfacePtr> surfaces() {
  return {std::make_shared<Sphere>(Vec3(0.3, -0.2, 1.1), 2.5),
          std::make_shared<Cylinder>(Vec3(1, 2, 3), Vec3(1, 1, 0.5), 1.5),
          std::make_shared<Plane>(Vec3(0.5, 0, 0), Vec3(1, -2, 0.3))};
}

/// The surface's implicit distance: 0 exactly on it.
double level(const Surface& s, const Vec3& x) {
  if (auto* sp = dynamic_cast<const Sphere*>(&s)) return (x - sp->centre()).norm() - sp->radius();
  if (auto* pl = dynamic_cast<const Plane*>(&s)) return (x - Vec3(0.5, 0, 0)).dot(pl->normal());
  const Vec3 a = Vec3(1, 1, 0.5).normalized(), d = x - Vec3(1, 2, 3);
  return (d - a.dot(d) * a).norm() - 1.5;
}

}  // namespace

// Each surface shall map points around it onto itself and fix its own points (P(P(y)) = P(y)) to
// 5e-14.
TEST(Surface, MapsOntoItselfAndFixesItsPoints) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-3, 3);
  for (const auto& s : surfaces())
    for (int k = 0; k < 50; ++k) {
      const Vec3 y(u(rng), u(rng), u(rng));
      const Vec3 x = s->onto(y);
      EXPECT_LE(std::abs(level(*s, x)), 1e-14 * 5) << s->describe();
      EXPECT_LE((s->onto(x) - x).norm(), 1e-14 * 5) << s->describe();
    }
}

// dP/dy shall agree with central differences to 1e-8 relative to |dP| (h = 1e-6).
TEST(Surface, DerivativeMatchesFiniteDifferences) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  const double h = 1e-6;
  for (const auto& s : surfaces())
    for (int k = 0; k < 20; ++k) {
      const Vec3 y(u(rng), u(rng), u(rng));
      Mat3 dP, fd;
      s->onto(y, &dP);
      for (int j = 0; j < 3; ++j)
        fd.col(j) = (s->onto(y + h * Vec3::Unit(j)) - s->onto(y - h * Vec3::Unit(j))) / (2 * h);
      EXPECT_LE((dP - fd).norm(), 1e-8 * dP.norm()) << s->describe();
    }
}

// The sphere's central projection shall keep planes through its centre, and the cylinder's
// projection planes containing its axis and planes normal to it (what lets an edge on both a
// curved face and a symmetry plane lie on both), to 1e-14.
TEST(Surface, CurvedProjectionsKeepTheirSymmetryPlanes) {
  const Sphere sphere(Vec3(1, 2, 3), 2);
  const Vec3 on_plane = Vec3(1, 2, 3) + Vec3(0.4, -1.3, 0);  // in the plane z = 3
  EXPECT_NEAR(sphere.onto(on_plane).z(), 3.0, 1e-14);
  const Cylinder cylinder(Vec3(0, 0, 0), Vec3(0, 0, 1), 1.5);
  const Vec3 y(0.7, 0.0, 2.5);  // in the plane y = 0 (contains the axis)
  EXPECT_NEAR(cylinder.onto(y).y(), 0.0, 1e-14);
  EXPECT_NEAR(cylinder.onto(y).z(), 2.5, 1e-14);  // and in the plane z = 2.5 (normal to it)
  EXPECT_NEAR(cylinder.onto(y).x(), 1.5, 1e-14);
}

// Bad surfaces and points without an image shall be refused with InputError naming the surface.
TEST(Surface, RefusesDegenerateInput) {
  EXPECT_THROW(Sphere(Vec3::Zero(), 0), InputError);
  EXPECT_THROW(Cylinder(Vec3::Zero(), Vec3::Zero(), 1), InputError);
  EXPECT_THROW(Plane(Vec3::Zero(), Vec3::Zero()), InputError);
  const Sphere sphere(Vec3(1, 0, 0), 1);
  try {
    sphere.onto(Vec3(1, 0, 0));
    FAIL() << "the centre has no central projection";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sphere(centre=(1,0,0), R=1)"), std::string::npos)
        << e.what();
  }
}

// The curves of edges on a surface (Surface::edge) shall be uniform in angle: a circle of a
// cylinder's normal plane is the 2D CircularArc's parametrisation c + R (cos θ, sin θ), θ linear
// in t; a generator is the straight chord; a sphere's edge is the great-circle arc (slerp), and
// each has the derivative its finite differences give (to 1e-8) and lies on its surface.
TEST(Surface, EdgesAreUniformInAngle) {
  const double R = 1.5, t0 = 0.2, t1 = 1.3, z = 0.7;
  const Cylinder cylinder(Vec3(0, 0, -2), Vec3(0, 0, 3), R);
  const Vec3 A(R * std::cos(t0), R * std::sin(t0), z), B(R * std::cos(t1), R * std::sin(t1), z);
  for (double t : {-1.0, -0.6, 0.0, 0.35, 1.0}) {
    const double th = t0 + 0.5 * (t + 1) * (t1 - t0);
    EXPECT_LT((cylinder.edge(A, B, t) - Vec3(R * std::cos(th), R * std::sin(th), z)).norm(), 1e-15);
    const Vec3 G = A + Vec3(0, 0, 2.5);  // a generator from A
    EXPECT_LT((cylinder.edge(A, G, t) - (0.5 * (1 - t) * A + 0.5 * (1 + t) * G)).norm(), 1e-15);
  }
  const Sphere sphere(Vec3(0.3, -0.2, 1.1), 2.5);
  const Vec3 P = sphere.onto(Vec3(2, 1, 0)), Q = sphere.onto(Vec3(-1, 2, 3));
  const Vec3 p = (P - sphere.centre()).normalized(), q = (Q - sphere.centre()).normalized();
  const double angle = std::acos(p.dot(q));
  for (double t : {-1.0, -0.6, 0.0, 0.35, 1.0}) {
    const Vec3 x = sphere.edge(P, Q, t);
    const Vec3 n = (x - sphere.centre()).normalized();
    EXPECT_NEAR((x - sphere.centre()).norm(), 2.5, 1e-14);
    EXPECT_NEAR(std::acos(std::min(1.0, n.dot(p))), 0.5 * (t + 1) * angle, 1e-7);
    EXPECT_NEAR(n.dot(p.cross(q)), 0, 1e-14);  // on the great circle through P and Q
  }
  const Cylinder tilted(Vec3(1, 2, 3), Vec3(1, 1, 0.5), 1.5);
  const Vec3 C = tilted.onto(Vec3(3, 0, 1)), D = tilted.onto(Vec3(0, 4, 5));
  const double h = 1e-6;
  for (const auto& [s, a, b] : {std::tuple<const Surface*, Vec3, Vec3>{&sphere, P, Q},
                                std::tuple<const Surface*, Vec3, Vec3>{&tilted, C, D},
                                std::tuple<const Surface*, Vec3, Vec3>{&cylinder, A, B}})
    for (double t : {-0.9, 0.1, 0.8}) {
      Vec3 dE;
      const Vec3 x = s->edge(a, b, t, &dE);
      if (s != &cylinder) EXPECT_LT(std::abs(level(*s, x)), 1e-13);  // level(): the tilted one
      const Vec3 fd = (s->edge(a, b, t + h) - s->edge(a, b, t - h)) / (2 * h);
      EXPECT_LT((dE - fd).norm(), 1e-8 * (1 + dE.norm())) << s->describe() << " t = " << t;
    }
  EXPECT_THROW(sphere.edge(P, 2 * sphere.centre() - P, 0.0), InputError);
}
