// Distributed edge loads: every profile shape integrates to its resultant with the right centroid.
#include <gtest/gtest.h>

#include <cmath>

#include "hpcontact/model/discretization.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {

/// Total vertical force and its first moment about x = 0 of the consistent load vector: the
/// vertex modes carry the partition of unity (sum of N = 1, sum of N x = x on straight edges),
/// so their load entries sum to ∫ q ds and ∫ q x ds.
std::pair<double, double> force_and_moment(const model::Discretization& d) {
  const auto& b = d.bodies[0];
  double F = 0, M = 0;
  for (int v = 0; v < b.mesh.n_nodes(); ++v) {
    const double fy = d.load(b.dof_offset + 2 * b.dofs.vertex_mode(v) + 1);
    F += fy;
    M += fy * b.mesh.node(v).x();
  }
  return {F, M};
}

}  // namespace

// A load given by its resultant R over part of the top edge (from x = 0 to x = 1.5, ending
// inside an element edge) sums to R for every shape, and its centroid is the shape's
// ∫ t f(t) dt / ∫ f(t) dt, computed independently by a fine midpoint rule of the profile.
TEST(EdgeLoads, ShapesIntegrateToResultantWithTheirCentroid) {
  auto centroid = [](model::LoadShape s) {
    // reference by a 2000-interval midpoint rule of the same formulas
    auto f = [s](double t) {
      switch (s) {
        case model::LoadShape::constant: return 1.0;
        case model::LoadShape::linear: return 1 - t;
        case model::LoadShape::bspline1: return (1 - t) * (1 - t);
        case model::LoadShape::bspline2: {
          // eq. 4.9: the uniform quadratic B-spline on [0, 3] from its peak x = 1.5 to x = 3
          const double x = 1.5 + 1.5 * t;
          return (x < 2 ? -x * x + 3 * x - 1.5 : 0.5 * (3 - x) * (3 - x)) / 0.75;
        }
        default: return 1 - 3 * t * t + 2 * t * t * t;
      }
    };
    double a = 0, m = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) / n;
      a += f(t);
      m += t * f(t);
    }
    return m / a;
  };
  for (auto shape : {model::LoadShape::constant, model::LoadShape::linear, model::LoadShape::bspline1,
                     model::LoadShape::bspline2, model::LoadShape::hermite}) {
    auto spec = test_problems::distorted_patch(4);
    model::EdgeLoadSpec l;
    l.edge_sets = {"top"};
    l.kind = model::LoadKind::traction;
    l.value = {0.0, -1.0};
    l.resultant = 1000.0;
    l.shape = shape;
    l.along = 'x';
    l.interval = std::array<double, 2>{0.0, 1.5};
    spec.bodies[0].edge_loads = {l};
    model::ConstraintSpec c;
    c.edge_sets = {"bottom"};
    c.ux = "0";
    c.uy = "0";
    spec.bodies[0].constraints = {c};
    const auto d = model::discretize(spec);
    const auto [F, M] = force_and_moment(d);
    EXPECT_NEAR(F, -1000.0, 1e-9) << static_cast<int>(shape);
    EXPECT_NEAR(M / F, 1.5 * centroid(shape), 1e-6) << static_cast<int>(shape);
  }
}

// The Hermite profile of eq. 4.10, 2 - 3t + t³ on [-1, 1], is the shape used, rescaled: its
// centroid on [0, 1] is 3/10 (a closed form independent of the midpoint rule above).
TEST(EdgeLoads, HermiteCentroidClosedForm) {
  auto spec = test_problems::distorted_patch(3);
  model::EdgeLoadSpec l;
  l.edge_sets = {"top"};
  l.kind = model::LoadKind::traction;
  l.value = {0.0, -5.0};
  l.shape = model::LoadShape::hermite;
  l.interval = std::array<double, 2>{0.0, 2.0};
  spec.bodies[0].edge_loads = {l};
  const auto d = model::discretize(spec);
  const auto [F, M] = force_and_moment(d);
  EXPECT_NEAR(F, -5.0 * 2.0 * 0.5, 1e-12);  // ∫_0^1 (1 - 3t² + 2t³) dt = 1/2, length 2
  EXPECT_NEAR(M / F, 2.0 * 0.3, 1e-12);
}

// A load ending exactly in the middle of an element edge (a point of the break-point scan) is
// integrated piecewise: its resultant and centroid are exact even at high p, where one Gauss
// rule across the jump would miss them.
TEST(EdgeLoads, LoadEndingOnAScanPointIsSplitThere) {
  for (int p : {4, 16}) {
    auto spec = test_problems::distorted_patch(p);
    model::EdgeLoadSpec l;
    l.edge_sets = {"top"};
    l.kind = model::LoadKind::traction;
    l.value = {0.0, -1.0};
    l.resultant = 1000.0;
    l.along = 'x';
    l.interval = std::array<double, 2>{0.0, 0.65};  // the top-left edge runs from x = 0 to 1.3
    spec.bodies[0].edge_loads = {l};
    const auto d = model::discretize(spec);
    const auto [F, M] = force_and_moment(d);
    EXPECT_NEAR(F, -1000.0, 1e-9) << "p " << p;
    EXPECT_NEAR(M / F, 0.325, 1e-12) << "p " << p;
  }
}
