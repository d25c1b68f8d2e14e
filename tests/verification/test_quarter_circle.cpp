// DOF numbering against the seed's Table 5.1 and static condensation on the Hertz geometry.
#include <gtest/gtest.h>

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

// Static condensation of the internal modes gives the same displacements as the full solve
// (to 1e-10 relative), at p = 2, 5 and 8.
TEST(StaticCondensation, SameDisplacementsAsFullSolve) {
  for (int p : {2, 5, 8}) {
    const auto d = model::discretize(test_problems::quarter_circle_2x2(p));
    model::LinearSolveOptions full, cond;
    cond.condense = true;
    const auto a = model::solve_linear(d, full);
    const auto b = model::solve_linear(d, cond);
    EXPECT_EQ(a.n_system, d.n_free);
    EXPECT_EQ(b.n_system, d.n_free_external);
    EXPECT_LT(b.n_system, a.n_system);
    EXPECT_LT((a.u - b.u).norm(), 1e-10 * a.u.norm()) << "p = " << p;
  }
}

// Elements of different degree share an edge at the lower degree (minimum rule), and the
// solution stays conforming: the displacement is continuous across that edge.
TEST(DofNumbering, MinimumRuleKeepsConformity) {
  auto spec = test_problems::quarter_circle_2x2(3);
  spec.bodies[0].element_degrees[1] = {6, 4};
  spec.bodies[0].element_degrees[4] = {2, 5};
  const auto d = model::discretize(spec);
  const auto sol = model::solve_linear(d, {});
  const auto& body = d.bodies[0];
  // Element 1 (index 0) and element 2 (index 1) share edge 2-5: local E2 of element 1
  // (xi = 1) and local E4 of element 2 (xi = -1), both running from node 2 to node 5.
  for (double t : {-0.8, -0.3, 0.1, 0.55, 0.9}) {
    const auto a = post::evaluate(body, 0, 1.0, t, sol.u);
    const auto b = post::evaluate(body, 1, -1.0, t, sol.u);
    EXPECT_LT((a.x - b.x).norm(), 1e-12);
    EXPECT_LT((a.u - b.u).norm(), 1e-12 * a.u.norm());
  }
}
