// The closed forms' inputs of a compare section: E* and R* of the pair, the force from the load.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hpcontact/core/error.hpp"
#include "hpcontact/driver/hertz_inputs.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_pairs.hpp"

using namespace hpcontact;

namespace {

driver::HertzInputs inputs_of(const std::string& example, const std::vector<std::string>& sets) {
  const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/hertz/" + example, sets);
  const auto d = model::discretize(spec);
  const auto pairs = model::make_contact_pairs(spec, d);
  return driver::hertz_inputs(spec, d, pairs, 0);
}

}  // namespace

// Two elastic bodies of different E, ν and R (the bilateral Hertz cylinders, the lower one made
// aluminium, its radius derived from its arcs): compare shall use E* and R* of the pair,
// computed here by hand, in plane strain and in plane stress, and F = 2 × the target.
TEST(HertzInputs, TwoElasticBodiesUseThePairsModulusAndRadius) {
  const std::vector<std::string> aluminium = {"bodies[1].material.E=70000", "bodies[1].material.nu=0.33",
                                              "contact[0].compare.radius=10"};
  const auto in = inputs_of("bilateral.yaml", aluminium);
  const double E1 = 210000 / (1 - 0.3 * 0.3), E2 = 70000 / (1 - 0.33 * 0.33);
  EXPECT_NEAR(in.effective_modulus, 1 / (1 / E1 + 1 / E2), 1e-9 * E1);
  EXPECT_NEAR(in.effective_radius, 1 / (1 / 10.0 + 1 / 10.0), 1e-12);
  EXPECT_NEAR(in.other_radius, 10, 1e-12);
  ASSERT_TRUE(in.force.has_value());
  EXPECT_NEAR(*in.force, 70000, 1e-9);
  EXPECT_EQ(in.models_of_whole, 2);

  auto stress = aluminium;
  stress.push_back("bodies[0].material.plane=stress");
  stress.push_back("bodies[1].material.plane=stress");
  const auto ps = inputs_of("bilateral.yaml", stress);
  EXPECT_NEAR(ps.effective_modulus, 1 / (1 / 210000.0 + 1 / 70000.0), 1e-6);
}

// A rigid plane: E* = E', R* = R; an other_radius that contradicts the plane, and a force that
// contradicts the target, shall be refused before the solve, naming the key.
TEST(HertzInputs, ContradictionsAreRefusedBeforeTheSolve) {
  const auto in = inputs_of("p8.yaml", {});
  EXPECT_NEAR(in.effective_modulus, 210000 / (1 - 0.09), 1e-6);
  EXPECT_TRUE(std::isinf(in.other_radius));
  EXPECT_NEAR(in.effective_radius, 10, 1e-12);
  try {
    inputs_of("p8.yaml", {"contact[0].compare.other_radius=30"});
    FAIL() << "other_radius of a plane accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compare.other_radius: 30 contradicts the obstacle"), std::string::npos) << e.what();
  }
  try {
    inputs_of("p8.yaml", {"solver.target_resultant.value=5000"});
    FAIL() << "compare.force 70000 accepted against a target of 5000";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("compare.force: 70000 contradicts solver.target_resultant"), std::string::npos) << e.what();
  }
  // Left out, the force is derived from the target.
  const auto derived = inputs_of("p8.yaml", {"solver.target_resultant.value=5000", "contact[0].compare.force=10000"});
  EXPECT_NEAR(*derived.force, 10000, 1e-9);
}
