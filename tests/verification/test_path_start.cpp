// A frictional solve on another discretisation starts each load step from the state the
// previous solve reached at that step (StartState::path, carried by adapt::carry_over): with
// friction the load path is part of the problem, so the final state alone is no start, and
// each step had started from the last converged state of a coarser field. Verified on the
// partial-slip pair (exact Coulomb contact, pressed then sheared in steps, p = 2): on the same
// discretisation the carried path is the solution (no Newton iteration beyond the check), one
// degree higher it reaches the same solution as a cold start in fewer iterations.
#include <gtest/gtest.h>

#include <string>

#include "hpcontact/adapt/error_estimate.hpp"
#include "hpcontact/adapt/solved.hpp"
#include "hpcontact/adapt/transfer.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/post/fields.hpp"

using namespace hpcontact;

namespace {

/// Pressed in one step, sheared in three.
model::ProblemSpec partial_slip() {
  auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/tests/verification/partial-slip-coarse.yaml", {});
  spec.solver.stages.at(1).steps = 3;
  return spec;
}

model::NonlinearSolution solve_from(const model::ProblemSpec& spec, const adapt::Solved* previous) {
  const model::Discretization d = model::discretize(spec);
  model::StartState start;
  if (previous)
    start = adapt::carry_over(previous->discretization, previous->solution, d, model::make_contact_pairs(spec, d));
  return model::solve_contact(spec, d, {}, start);
}

}  // namespace

TEST(PathStart, EveryFrictionalStepIsKept) {
  const auto s = adapt::solve(partial_slip());
  ASSERT_TRUE(s->solution.converged);
  const auto& states = s->solution.step_states;
  ASSERT_EQ(static_cast<int>(states.size()), s->solution.load_steps);
  ASSERT_EQ(states.size(), 4u);  // pressed, then sheared in three steps
  // The last state is the solution; the segments (the stages) in order, each ending at s = 1.
  EXPECT_EQ((states.back().u - s->solution.u).norm(), 0.0);
  EXPECT_EQ(states.back().s, 1.0);
  for (size_t i = 1; i < states.size(); ++i)
    EXPECT_TRUE(states[i].segment > states[i - 1].segment ||
                (states[i].segment == states[i - 1].segment && states[i].s > states[i - 1].s));
}

TEST(PathStart, TheSameDiscretisationRetracesItsPath) {
  const auto s = adapt::solve(partial_slip());
  const auto again = solve_from(s->spec, s.get());
  ASSERT_TRUE(again.converged) << again.message;
  EXPECT_EQ(again.load_steps, s->solution.load_steps);
  // each step's guess is its answer: Newton checks it and stops (at most one correction)
  EXPECT_LE(again.newton_iterations, again.load_steps);
  EXPECT_GT(s->solution.newton_iterations, again.newton_iterations);
  EXPECT_LT((again.u - s->solution.u).norm(), 1e-9 * s->solution.u.norm());
  EXPECT_LT((again.multipliers[0] - s->solution.multipliers[0]).norm(), 1e-9 * s->solution.multipliers[0].norm());
}

TEST(PathStart, OneDegreeMoreReachesTheColdStartsSolutionInFewerIterations) {
  const auto s = adapt::solve(partial_slip());
  const model::ProblemSpec higher = adapt::with_degrees_raised(s->spec);
  const auto cold = solve_from(higher, nullptr);
  const auto warm = solve_from(higher, s.get());
  ASSERT_TRUE(cold.converged && warm.converged) << cold.message << warm.message;
  EXPECT_EQ(warm.load_steps, cold.load_steps);
  EXPECT_LT(warm.newton_iterations, cold.newton_iterations);
  EXPECT_LT((warm.u - cold.u).norm(), 1e-7 * cold.u.norm());
  EXPECT_LT((warm.multipliers[0] - cold.multipliers[0]).norm(), 1e-7 * cold.multipliers[0].norm());
  std::printf("p+1 from the p solve's path: %d Newton iterations in %d steps (cold start: %d)\n",
              warm.newton_iterations, warm.load_steps, cold.newton_iterations);
}

// One degree more on the same mesh, every step's multipliers are carried as the same traction
// field: the new Lobatto nodes' quadrature of the normal and of the tangential multiplier (each
// a polynomial of the edge's degree) gives the old nodes' forces, step by step.
TEST(PathStart, OneDegreeMoreCarriesEachStepsTractions) {
  const auto s = adapt::solve(partial_slip());
  const model::ProblemSpec higher = adapt::with_degrees_raised(s->spec);
  const model::Discretization d = model::discretize(higher);
  const auto pairs = model::make_contact_pairs(higher, d);
  const auto start = adapt::carry_over(s->discretization, s->solution, d, pairs);
  ASSERT_EQ(start.path.size(), s->solution.step_states.size());
  const auto& old_nodes = s->solution.pairs[0].constraints->nodes;
  const auto& new_nodes = pairs[0].constraints->nodes;
  auto forces = [](const contact::MultiplierNodes& nodes, const Eigen::VectorXd& l) {
    double normal = 0, tangential = 0;
    for (int j = 0; j < nodes.size(); ++j) {
      normal += nodes.nodes[j].weight * l(j);
      tangential += nodes.nodes[j].weight * l(nodes.size() + j);
    }
    return std::make_pair(normal, tangential);
  };
  for (size_t k = 0; k < start.path.size(); ++k) {
    const auto before = forces(old_nodes, s->solution.step_states[k].multipliers[0]);
    ASSERT_EQ(start.path[k].multipliers[0].size(), 2 * new_nodes.size());
    const auto after = forces(new_nodes, start.path[k].multipliers[0]);
    EXPECT_GT(std::abs(before.first), 1.0) << k;  // a pressed pair
    EXPECT_NEAR(after.first, before.first, 1e-9 * std::abs(before.first)) << k;
    EXPECT_NEAR(after.second, before.second, 1e-9 * std::abs(before.first)) << k;
  }
  EXPECT_GT(std::abs(forces(old_nodes, s->solution.step_states.back().multipliers[0]).second), 1.0);
}
