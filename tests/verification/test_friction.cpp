// Friction (Coulomb regularised by a tangential penalty): the analytic tangent of stick and slip
// against central differences of the residual, on two bodies and against a rigid plane.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "problems.hpp"

using namespace hpcontact;

// Friction: the analytic tangent (stick: ε_T G_T G_Tᵀ; slip: −μ s ε_N G_T G_nᵀ, not symmetric)
// equals central differences of the residual, friction histories fixed, at the converged end
// of the two-bar examples (two bodies, both sides' points anchored): < 1e-5 of max |K|.
TEST(FrictionTangent, TwoBarsAgreeWithCentralDifferences) {
  for (const char* name : {"stick.yaml", "coulomb.yaml"}) {
    const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/two-bars/" + name,
                                       {"discretization.degree=[6, 3]"});
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    double asymmetry = 0;
    const double mismatch = test_problems::tangent_mismatch(spec, d, sol, &asymmetry);
    std::printf("%s: max |K_analytic - K_differences| / max |K| = %.3g, asymmetry %.3g\n", name,
                mismatch, asymmetry);
    EXPECT_LT(mismatch, 1e-5) << name;
  }
}

// Friction against a rigid plane: the distorted patch pressed onto y = 0 (top uy = -0.002),
// then sheared by a traction on its top; Coulomb mu = 0.2 with partial slip, and full stick.
// The analytic tangent (penalty_contact's friction terms) equals central differences: < 1e-5.
TEST(FrictionTangent, PatchOnRigidPlaneAgreesWithCentralDifferences) {
  for (const char* law : {"stick", "coulomb"}) {
    auto spec = test_problems::distorted_patch(4);
    auto& b = spec.bodies[0];
    const double E = b.material.youngs_modulus;
    model::ConstraintSpec top;
    top.edge_sets = {"top"};
    top.uy = "-0.002";
    b.constraints = {top};
    model::EdgeLoadSpec shear;
    shear.edge_sets = {"top"};
    shear.kind = model::LoadKind::traction;
    shear.value = {0.00012 * E, 0.0};
    b.edge_loads = {shear};
    model::ContactPairSpec c;
    c.body = b.name;
    c.edge_sets = {"bottom"};
    c.obstacle.kind = model::ObstacleKind::plane;
    c.penalty = 1000 * E;
    c.quadrature = 20;
    c.friction.law = law;
    c.friction.mu = 0.2;
    c.friction.penalty = 1000 * E;
    spec.contact = {c};
    spec.solver.stages = {{1, 0, 2}, {1, 1, 3}};
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    int slipping = 0;
    for (const auto& s : sol.contact.front().states) slipping += s.stick_slip == contact::StickSlip::slip;
    if (std::string(law) == "coulomb") EXPECT_GT(slipping, 0);  // partial slip, not all stuck
    const double mismatch = test_problems::tangent_mismatch(spec, d, sol);
    std::printf("patch on plane, %s (%d slipping of %zu): max |K_analytic - K_differences| / max |K| = %.3g\n",
                law, slipping, sol.contact.front().states.size(), mismatch);
    EXPECT_LT(mismatch, 1e-5) << law;
  }
}
