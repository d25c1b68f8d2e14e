// DOF numbering against the seed's Table 5.1 and static condensation on the Hertz geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/model/linear_solve.hpp"
#include "hpcontact/post/fields.hpp"
#include "problems.hpp"

using namespace hpcontact;

// The 2×2 quarter circle with ux fixed on the symmetry edge and uy on the centre plane has
// 2·(6 + 10(p−1) + 4(p−1)²) free unknowns in the tensor-product space: 220, 544, 1860 at
// p = 5, 8, 15 (the seed's Table 5.1).
TEST(DofNumbering, SeedTable51Counts) {
  for (auto [p, expected] : {std::pair{5, 220}, std::pair{8, 544}, std::pair{15, 1860}}) {
    const auto d = model::discretize(test_problems::quarter_circle_2x2(p));
    EXPECT_EQ(d.n_free, expected) << "p = " << p;
    EXPECT_EQ(d.n_free, 2 * (6 + 10 * (p - 1) + 4 * (p - 1) * (p - 1)));
  }
}

// The trunk space drops the internal modes with i + j > p: 2·(6 + 10(p−1) + 4·(p−2)(p−3)/2).
TEST(DofNumbering, TrunkSpaceCounts) {
  for (int p : {1, 2, 3, 4, 8}) {
    auto spec = test_problems::quarter_circle_2x2(p);
    spec.discretization.space = model::ShapeSpace::trunk;
    const auto d = model::discretize(spec);
    const int internal = p >= 4 ? (p - 2) * (p - 3) / 2 : 0;
    EXPECT_EQ(d.n_free, 2 * (6 + 10 * (p - 1) + 4 * internal)) << "p = " << p;
  }
}

namespace {

/// max over the interior edges and points along them of the jump of u between the two
/// elements, and the number of interior edges traversed in opposite directions by them.
double max_jump(const model::Body& body, const Eigen::VectorXd& u, int* opposite) {
  double jump = 0;
  *opposite = 0;
  for (int e = 0; e < body.mesh.n_edges(); ++e) {
    const auto& edge = body.mesh.edge(e);
    if (edge.on_boundary()) continue;
    const int qa = edge.quads[0], la = edge.local_edge[0], qb = edge.quads[1], lb = edge.local_edge[1];
    const bool same = body.mesh.quad_edge_reversed(qa, la) == body.mesh.quad_edge_reversed(qb, lb);
    *opposite += !same;
    for (double t : {-0.8, -0.3, 0.1, 0.55, 0.9}) {
      const double tb = same ? t : -t;  // the same point seen from the other element
      const Vec2 xa = fem::edge_geometry(body.maps[qa], la, t, nullptr, nullptr);
      const Vec2 xb = fem::edge_geometry(body.maps[qb], lb, tb, nullptr, nullptr);
      EXPECT_LT((xa - xb).norm(), 1e-12) << "edge " << e;
      jump = std::max(jump, (test_problems::edge_displacement(body, qa, la, t, u) -
                             test_problems::edge_displacement(body, qb, lb, tb, u)).norm());
    }
  }
  return jump;
}

}  // namespace

// Static condensation of the internal modes gives the same displacements as the full solve
// (to 1e-10 relative), at p = 2, 5 and 8, on the stressed quarter circle with a body force (its
// internal modes carry both K_ii⁻¹ K_ie u_e and K_ii⁻¹ f_i; energy printed).
TEST(StaticCondensation, SameDisplacementsAsFullSolve) {
  for (int p : {2, 5, 8}) {
    const auto d = model::discretize(test_problems::quarter_circle_2x2_loaded(p));
    model::LinearSolveOptions full, cond;
    cond.condense = true;
    const auto a = model::solve_linear(d, full);
    const auto b = model::solve_linear(d, cond);
    EXPECT_EQ(a.n_system, d.n_free);
    EXPECT_EQ(b.n_system, d.n_free_external);
    EXPECT_LT(b.n_system, a.n_system);
    // Not a rigid motion: the internal modes are far from zero.
    const double U = post::strain_energy(d, a.u);
    double internal = 0;
    const auto& body = d.bodies[0];
    for (int q = 0; q < body.mesh.n_quads(); ++q) {
      const auto& es = body.dofs.element(q);
      for (int k = es.n_modes() - es.n_internal; k < es.n_modes(); ++k)
        internal = std::max(internal, std::abs(a.u(body.dof_offset + 2 * es.modes[k] + 1)));
    }
    std::printf("p = %d: strain energy %.6g, max |internal mode| %.3g of max |u| %.3g\n", p, U,
                internal, a.u.cwiseAbs().maxCoeff());
    EXPECT_GT(U, 1.0);
    EXPECT_GT(internal, 1e-4 * a.u.cwiseAbs().maxCoeff());
    EXPECT_LT((a.u - b.u).norm(), 1e-10 * a.u.norm()) << "p = " << p;
  }
}

// The nonlinear solver's condensation (model::solve_contact, which recovers the internal modes
// with the loads' factor) gives the full solve's displacements (1e-10 relative) on the
// stressed quarter circle at p = 5, stopped at loads factor 0.4 with the displacements at 1;
// and both are the linear superposition u(1, 0) + 0.4 (u(1, 1) − u(1, 0)) of linear solves.
TEST(StaticCondensation, NewtonRecoversInternalModesUnderTheLoadFactor) {
  auto spec = test_problems::quarter_circle_2x2_loaded(5);
  spec.solver.stages = {{1, 0.4, 2}};
  const auto d = model::discretize(spec);
  std::vector<Eigen::VectorXd> u;
  for (bool condense : {false, true}) {
    spec.discretization.condense = condense;
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    EXPECT_DOUBLE_EQ(sol.loads_factor, 0.4);
    u.push_back(sol.u);
  }
  EXPECT_LT((u[0] - u[1]).norm(), 1e-10 * u[0].norm());
  auto unloaded = test_problems::quarter_circle_2x2_loaded(5);
  unloaded.bodies[0].edge_loads.clear();
  unloaded.bodies[0].body_force = {0, 0};
  const auto u_loaded = model::solve_linear(d, {}).u;
  const auto u_unloaded = model::solve_linear(model::discretize(unloaded), {}).u;
  const Eigen::VectorXd expected = u_unloaded + 0.4 * (u_loaded - u_unloaded);
  EXPECT_LT((u[1] - expected).norm(), 1e-10 * expected.norm());
}

// Elements of different degree share an edge at the lower degree (minimum rule), and the
// solution stays conforming: on the stressed quarter circle, with edges shared in opposite
// directions (where odd edge modes change sign), the displacement is continuous across every
// interior edge to 1e-12 of its size.
TEST(DofNumbering, MinimumRuleKeepsConformity) {
  auto spec = test_problems::quarter_circle_2x2_loaded(3);
  spec.bodies[0].element_degrees[1] = {6, 4};
  spec.bodies[0].element_degrees[4] = {2, 5};
  const auto d = model::discretize(spec);
  const auto sol = model::solve_linear(d, {});
  const auto& body = d.bodies[0];
  EXPECT_GT(post::strain_energy(d, sol.u), 1.0);
  int opposite = 0;
  const double jump = max_jump(body, sol.u, &opposite);
  EXPECT_EQ(opposite, 2);  // 5–6 and 5–8
  EXPECT_LT(jump, 1e-12 * sol.u.cwiseAbs().maxCoeff());
}

// Node 3 of the 2×2 quarter circle joins two edges on one circle: a corner of 180°, where the
// blending map's Jacobian vanishes and the discrete gradient grows like 1/distance. The stresses
// sampled there (VTU, PNG) shall be those of the field inside, not round-off over round-off
// (2e7 for a peak of 1.4e4 before): von Mises at that corner no larger than 1.5 times the
// largest over the element's other samples on a 0.2 grid.
TEST(Fields, SingularCornerIsSampledInside) {
  const int p = 8;
  const auto d = model::discretize(test_problems::quarter_circle_2x2_loaded(p));
  const auto u = model::solve_linear(d, {}).u;
  const auto& body = d.bodies[0];
  int singular = 0;
  for (int q = 0; q < body.mesh.n_quads(); ++q) {
    const double centre = fem::point_values(body.dofs.element(q), body.maps[q], 0, 0).det_J;
    double largest = 0;
    for (int i = 0; i <= 10; ++i)
      for (int j = 0; j <= 10; ++j)
        if ((i % 10 != 0) || (j % 10 != 0))
          largest = std::max(largest, post::evaluate(body, q, -1 + 0.2 * i, -1 + 0.2 * j, u).von_mises);
    for (double xi : {-1.0, 1.0})
      for (double eta : {-1.0, 1.0}) {
        const double det = fem::point_values(body.dofs.element(q), body.maps[q], xi, eta).det_J;
        if (std::abs(det) > 1e-6 * std::abs(centre)) continue;
        ++singular;
        const double at = post::evaluate(body, q, xi, eta, u).von_mises;
        EXPECT_TRUE(std::isfinite(at)) << "element " << q;
        EXPECT_LT(at, 1.5 * largest) << "element " << q;
      }
  }
  EXPECT_GE(singular, 1);  // the premise: the mesh has a 180° corner
}
