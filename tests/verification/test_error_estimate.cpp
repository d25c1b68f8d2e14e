// The error estimate of the hp loop: one degree more on every element, and the difference of
// two solves' contact tractions and energies (zero for a solve against itself).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "hpcontact/adapt/error_estimate.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/io/problem_reader.hpp"

using namespace hpcontact;

namespace {

model::ProblemSpec hertz_p(int p) {
  return io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/hertz/p8.yaml",
                          {"discretization.degree=" + std::to_string(p)});
}

}  // namespace

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
