// The error estimate of the hp loop: one degree more on every element, and the difference of
// two solves' contact tractions and energies (zero for a solve against itself).
#include <gtest/gtest.h>

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
