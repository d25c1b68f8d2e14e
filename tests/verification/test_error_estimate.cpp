// The error estimate of the hp loop: one degree more on every element, and the difference of
// two solves' contact tractions and energies (zero for a solve against itself).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>

#include "hpcontact/adapt/error_estimate.hpp"
#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/boundary_pressure.hpp"

using namespace hpcontact;

namespace {

model::ProblemSpec hertz_p(int p) {
  return io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/hertz/p8.yaml",
                          {"discretization.degree=" + std::to_string(p)});
}

/// The integrals of the traction estimate over every pair's contact edges by brute force:
/// ∫ (t − t⁺)², ∫ t⁺², and the same of the shear, with 16 pieces of 24 Gauss points on each
/// edge (exact for polynomials of degree 47 on each piece), of the same fields the estimate
/// integrates (the multipliers interpolated along the edges, ds/dt of the undeformed edge).
struct TractionIntegrals {
  double diff2 = 0, norm2 = 0, shear_diff2 = 0, shear_norm2 = 0, capacity2 = 0;
};
TractionIntegrals brute_force(const adapt::Solved& coarse, const adapt::Solved& enriched) {
  const auto& a = coarse.solution;
  const auto& b = enriched.solution;
  const auto& rule = basis::gauss_legendre(24);
  const int pieces = 16;
  TractionIntegrals I;
  for (size_t k = 0; k < b.pairs.size(); ++k) {
    const model::BoundaryPressureProbe pa(coarse.discretization, a.pairs[k], a.u, a.multipliers_of(k));
    const model::BoundaryPressureProbe pb(enriched.discretization, b.pairs[k], b.u, b.multipliers_of(k));
    const double mu = b.pairs[k].constraints ? b.pairs[k].constraints->friction.mu : 0.0;
    const auto& body = enriched.discretization.bodies[b.pairs[k].body];
    for (size_t e = 0; e < b.pairs[k].edges.size(); ++e) {
      const auto& edge = body.mesh.edge(b.pairs[k].edges[e]);
      for (int piece = 0; piece < pieces; ++piece)
        for (int i = 0; i < rule.size(); ++i) {
          const double t = -1 + (2.0 * piece + 1 + rule.points[i]) / pieces;
          const double w = rule.weights[i] / pieces;
          double ds_dt = 0;
          fem::edge_geometry(body.maps[edge.quads[0]], edge.local_edge[0], t, nullptr, &ds_dt);
          const int ke = static_cast<int>(e);
          const double ta = pa.traction(ke, t), tb = pb.traction(ke, t);
          I.diff2 += w * ds_dt * (ta - tb) * (ta - tb);
          I.norm2 += w * ds_dt * tb * tb;
          const double sa = pa.tangential_traction(ke, t), sb = pb.tangential_traction(ke, t);
          I.shear_diff2 += w * ds_dt * (sa - sb) * (sa - sb);
          I.shear_norm2 += w * ds_dt * sb * sb;
          I.capacity2 += w * ds_dt * mu * mu * tb * tb;
        }
    }
  }
  return I;
}

}  // namespace

// The estimate's integrals are exact: on the partial-slip pair (exact contact, Coulomb
// friction, arcs) solved at p = 2 and one degree higher, its relative L2 differences of the
// pressure and the shear equal those of a brute-force quadrature of the same fields to 1e-12.
// The multipliers are polynomials of the edges' trace degree in the edge parameter and ds/dt of
// an arc is constant, so that one Gauss point too few (degree p⁺ = 3: (t − t⁺)² of degree 6
// wants 4) is seen as a relative 1e-3 or more.
TEST(ErrorEstimate, TractionIntegralsAreExact) {
  const auto coarse = adapt::solve(io::read_problem(
      std::string(HPC_SOURCE_DIR) + "/tests/verification/partial-slip-coarse.yaml", {}));
  const auto enriched = adapt::solve(adapt::with_degrees_raised(coarse->spec), {}, coarse.get());
  const auto e = adapt::estimate_error(*coarse, *enriched);
  const TractionIntegrals I = brute_force(*coarse, *enriched);
  // the shear is the contact's own (not incidental): it is measured against its own size
  ASSERT_GT(I.shear_norm2, 1e-4 * I.capacity2);
  const double pressure = std::sqrt(I.diff2 / I.norm2), shear = std::sqrt(I.shear_diff2 / I.shear_norm2);
  EXPECT_GT(pressure, 1e-4);  // a difference to measure, not round-off
  EXPECT_GT(shear, 1e-4);
  EXPECT_NEAR(e.pressure, pressure, 1e-12 * pressure);
  EXPECT_NEAR(e.shear, shear, 1e-12 * shear);
}

// Every element of every body gets one degree more in both directions, whether its degree came
// from discretization.degree or its own entry; the largest degree has no "more" and says so.
TEST(ErrorEstimate, RaisesEveryElementByOneDegree) {
  model::ProblemSpec spec = hertz_p(8);
  spec.bodies[0].element_degrees[3] = {5, 6};
  const model::ProblemSpec raised = adapt::with_degrees_raised(spec);
  for (const int id : spec.bodies[0].element_ids) {
    const auto p = raised.bodies[0].element_degrees.at(id);
    if (id == 3) {
      EXPECT_EQ(p[0], 6);
      EXPECT_EQ(p[1], 7);
    } else {
      EXPECT_EQ(p[0], 9);
      EXPECT_EQ(p[1], 9);
    }
  }
  spec.bodies[0].element_degrees[2] = {30, 30};
  EXPECT_THROW(adapt::with_degrees_raised(spec), AdaptError);
}

// The Hertz p8 solve against itself: no difference; against p9 on the same mesh: the
// difference of the two pressures, a few percent (the zone end lies inside an element, so p
// converges slowly), and the energy difference far smaller than the pressure's.
TEST(ErrorEstimate, DifferenceOfTwoSolvesOfOneMesh) {
  const auto p8 = adapt::solve(hertz_p(8));
  const auto self = adapt::estimate_error(*p8, *p8);
  EXPECT_EQ(self.pressure, 0.0);
  EXPECT_EQ(self.energy, 0.0);
  const auto p9 = adapt::solve(adapt::with_degrees_raised(p8->spec), {}, p8.get());
  const auto e = adapt::estimate_error(*p8, *p9);
  EXPECT_GT(e.pressure, 5e-3);
  EXPECT_LT(e.pressure, 0.1);
  EXPECT_GT(e.energy, 0.0);
  EXPECT_EQ(e.dofs, p9->discretization.n_free);
  EXPECT_GT(e.dofs, p8->discretization.n_free);
}

// With exact Coulomb friction the estimate measures the tangential multipliers as it measures
// the normal ones: a solve against a copy of itself whose tangential multipliers are scaled by
// 1 + ε (and nothing else changed) has the shear error ε / (1 + ε) and no pressure error; one
// whose normal multipliers are scaled instead, the reverse. traction() is the larger; without
// friction the shear is not a number and traction() is the pressure's. The goal-oriented
// indicators' functional weighs both parts alike (traction_error_gradient).
TEST(ErrorEstimate, ShearOfTheTangentialMultipliers) {
  const auto s = adapt::solve(io::read_problem(
      std::string(HPC_SOURCE_DIR) + "/tests/verification/partial-slip-coarse.yaml", {}));
  ASSERT_TRUE(s->solution.pairs[0].constraints && s->solution.pairs[0].constraints->has_friction());
  const int n = s->solution.pairs[0].constraints->size();
  const double eps = 0.03;
  auto scaled = [&](int first) {
    auto t = std::make_shared<adapt::Solved>(*s);
    t->solution.multipliers[0].segment(first, n) *= 1 + eps;
    return t;
  };
  const auto self = adapt::estimate_error(*s, *s);
  EXPECT_EQ(self.shear, 0.0);
  const auto tangential = adapt::estimate_error(*s, *scaled(n));
  EXPECT_NEAR(tangential.shear, eps / (1 + eps), 1e-12);
  EXPECT_EQ(tangential.pressure, 0.0);
  EXPECT_EQ(tangential.traction(), tangential.shear);
  const auto normal = adapt::estimate_error(*s, *scaled(0));
  EXPECT_NEAR(normal.pressure, eps / (1 + eps), 1e-12);
  EXPECT_EQ(normal.shear, 0.0);
  EXPECT_EQ(normal.traction(), normal.pressure);
  // The goal's gradient: J(λ⁺) − J(λ) = Σ_j ∂J/∂λ_j (λ⁺_j − λ_j) is the sum of the squared
  // relative errors at the nodes, here (ε / (1 + ε))² from the scaled part alone.
  for (const int first : {0, n}) {
    const auto plus = scaled(first);
    const auto g = adapt::traction_error_gradient(*s, *plus);
    ASSERT_EQ(g[0].size(), 2 * n);
    const Eigen::VectorXd change = plus->solution.multipliers[0] - s->solution.multipliers[0];
    EXPECT_NEAR(g[0].dot(change), std::pow(eps / (1 + eps), 2), 1e-14) << first;
    EXPECT_EQ(g[0].segment(n - first, n).norm(), 0.0) << first;  // the part not scaled
  }
  const auto p8 = adapt::solve(hertz_p(8));
  const auto frictionless = adapt::estimate_error(*p8, *p8);
  EXPECT_TRUE(std::isnan(frictionless.shear));
  EXPECT_EQ(frictionless.traction(), 0.0);
}
