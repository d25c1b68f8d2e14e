// Follower pressures on finite-strain bodies against closed forms: Rivlin's thick tube inflated
// by an internal pressure under load control (plane strain and axisymmetric), and the tangent of
// the whole system with a follower load against central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {

constexpr double kA = 10, kB = 20, kC10 = 0.5, kHeight = 4;

/// Rivlin's inflation of an incompressible neo-Hookean tube A <= R <= B, axial stretch 1
/// (docs/theory.md §12): λ_b² = (B² + a² − A²) / B², P = μ/2 [ln(λ_a² / λ_b²) + 1/λ_b² − 1/λ_a²].
double rivlin_pressure(double l_a) {
  const double a = l_a * kA, l_b = std::sqrt(kB * kB + a * a - kA * kA) / kB, mu = 2 * kC10;
  return mu / 2 * (std::log(l_a * l_a / (l_b * l_b)) + 1 / (l_b * l_b) - 1 / (l_a * l_a));
}

/// The bore's stretch λ_a at the inner pressure P: P(λ_a) rises monotonically (to μ/2 ln(B²/A²)),
/// so bisection on [1, 10].
double rivlin_stretch(double P) {
  double lo = 1, hi = 10;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (rivlin_pressure(mid) < P ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void set_neo_hooke(model::BodySpec& b, model::PlaneMode plane) {
  b.material.model = "neo-hooke-split";
  b.material.plane = plane;
  b.material.C10 = kC10;
  b.material.incompressible = true;
  b.material.formulation = "mixed";
}

/// The tube of test_mixed_rubber.cpp (plane strain: the quarter with exact arcs, 2 × 2 elements;
/// axisymmetric: the section [A, B] × [0, H], 2 elements, u_z = 0 on both ends) loaded by an
/// internal follower pressure P in `steps` load steps.
model::ProblemSpec pressurised_tube(bool axisymmetric, int p, double P, int steps) {
  model::ProblemSpec spec;
  if (axisymmetric) {
    spec.file = spec.case_name = "follower-tube-axisymmetric";
    auto b = test_problems::body("tube", 0, 0);
    std::vector<std::array<int, 2>> ends;
    for (int i = 0; i <= 2; ++i) {
      test_problems::add_node(b, 1 + i, kA + (kB - kA) * i / 2, 0);
      test_problems::add_node(b, 101 + i, kA + (kB - kA) * i / 2, kHeight);
    }
    for (int i = 0; i < 2; ++i) {
      test_problems::add_element(b, 1 + i, 1 + i, 2 + i, 102 + i, 101 + i);
      ends.push_back({1 + i, 2 + i});
      ends.push_back({101 + i, 102 + i});
    }
    test_problems::add_edge_set(b, "ends", ends);
    test_problems::add_edge_set(b, "inner", {{1, 101}});
    model::ConstraintSpec hold;
    hold.edge_sets = {"ends"};
    hold.uy = "0";
    b.constraints = {hold};
    spec.bodies.push_back(b);
  } else {
    spec = test_problems::lame_quarter(2, 2);
    spec.file = spec.case_name = "follower-tube-plane-strain";
    spec.exact = {};
  }
  auto& b = spec.bodies[0];
  set_neo_hooke(b, axisymmetric ? model::PlaneMode::axisymmetric : model::PlaneMode::plane_strain);
  model::EdgeLoadSpec load;
  load.edge_sets = {"inner"};
  load.value = {P, 0.0};
  load.follower = true;
  b.edge_loads = {load};
  spec.discretization.degree = {p, p};
  spec.solver.load_steps = steps;
  spec.solver.tolerance = 1e-12;
  return spec;
}

/// The bore's stretch of the FE solution: 1 + u_r / A at the inner node on r (y = 0).
double bore_stretch(const model::Discretization& d, const Eigen::VectorXd& u) {
  const auto& body = d.bodies[0];
  for (int v = 0; v < body.mesh.n_nodes(); ++v)
    if ((body.mesh.node(v) - Vec2(kA, 0)).norm() < 1e-12)
      return 1 + u(body.dof_offset + 2 * body.dofs.vertex_mode(v)) / kA;
  ADD_FAILURE() << "no node at (A, 0)";
  return 0;
}

}  // namespace

// Rivlin's thick tube (A = 10, B = 20, incompressible neo-Hooke μ = 1, the mixed element, p = 8)
// inflated under load control by an internal follower pressure P = P_Rivlin(λ) for λ = 1.2 and
// 1.5: the bore's stretch shall be the closed form's within 1e-5 relative, plane strain and
// axisymmetric. The same meshes give the pressure at a prescribed stretch within 1e-5
// (test_mixed_rubber.cpp); dλ/λ = (P/(λ dP/dλ)) dP/P with P/(λ dP/dλ) below 1 here (measured
// 0.5 to 0.8), so a dead load (on the undeformed bore, 1/λ too little force per deformed area)
// would miss by 20 % and 50 %.
TEST(FollowerPressure, ThickTubeInflationMatchesRivlin) {
  for (bool axisymmetric : {false, true})
    for (double l_exact : {1.2, 1.5}) {
      const double P = rivlin_pressure(l_exact);
      ASSERT_NEAR(rivlin_stretch(P), l_exact, 1e-12);
      const auto spec = pressurised_tube(axisymmetric, 8, P, 8);
      const auto d = model::discretize(spec);
      ASSERT_EQ(d.follower_loads.size(), 1u);
      const auto sol = model::solve_contact(spec, d);
      ASSERT_TRUE(sol.converged) << sol.message;
      const double l_fe = bore_stretch(d, sol.u);
      std::printf("%s tube, P = %.6f: bore stretch %.10f, Rivlin %.10f, relative error %.1e\n",
                  axisymmetric ? "axisymmetric" : "plane-strain", P, l_fe, l_exact,
                  std::abs(l_fe - l_exact) / l_exact);
      EXPECT_NEAR(l_fe, l_exact, 1e-5 * l_exact) << (axisymmetric ? "axisymmetric" : "plane strain");
    }
}

// The analytic tangent of the whole system with a follower pressure (its load stiffness among
// the mixed element's blocks) shall be the central differences of the residual at the converged
// inflated tube, plane strain and axisymmetric, p = 3, to 1e-6 relative (differences of step
// 1e-6 (|x| + 1e-3): truncation ~ h² |f'''| and round-off ~ 1e-16 |r| / h, both below 1e-7 of
// the largest entry).
TEST(FollowerPressure, SystemTangentMatchesDifferences) {
  for (bool axisymmetric : {false, true}) {
    const auto spec = pressurised_tube(axisymmetric, 3, rivlin_pressure(1.3), 4);
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    double asymmetry = 0;
    const double mismatch = test_problems::tangent_mismatch(spec, d, sol, &asymmetry);
    std::printf("%s: tangent mismatch %.1e, asymmetry %.1e\n", axisymmetric ? "axisymmetric" : "plane strain",
                mismatch, asymmetry);
    EXPECT_LE(mismatch, 1e-6);
  }
}
