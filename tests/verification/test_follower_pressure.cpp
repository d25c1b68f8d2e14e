// Follower pressures on finite-strain bodies against closed forms: Rivlin's thick tube inflated
// by an internal pressure under load control (plane strain and axisymmetric), and the tangent of
// the whole system with a follower load against central differences.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "hpcontact/io/problem_reader.hpp"
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

namespace {

/// A block [0, 2] × [0, 1] of 2 × 2 elements (its middle node moved off the grid) on the rigid
/// plane y = 0 (exact contact on its bottom, no friction), ux = 0 on its left side (a symmetry
/// line), pressed by q on its top and immersed in p_s: p_s on its top and right side (with
/// `penetrating`, from the top down the right side and on along the bottom up to the contact).
model::ProblemSpec immersed_block(bool finite_strain, double q, double p_s, int p, bool penetrating = false) {
  model::ProblemSpec spec;
  spec.file = spec.case_name = finite_strain ? "immersed-block-neo-hooke" : "immersed-block";
  auto b = test_problems::body("block", 1000, 0.3);
  if (finite_strain) b.material.model = "neo-hooke";
  int id = 1;
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) test_problems::add_node(b, id++, i, 0.5 * j);
  b.nodes[4] = {1.1, 0.55};
  auto node = [](int i, int j) { return 1 + 3 * j + i; };
  id = 1;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i)
      test_problems::add_element(b, id++, node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1));
  test_problems::add_edge_set(b, "bottom", {{node(0, 0), node(1, 0)}, {node(1, 0), node(2, 0)}});
  test_problems::add_edge_set(b, "top", {{node(0, 2), node(1, 2)}, {node(1, 2), node(2, 2)}});
  test_problems::add_edge_set(b, "right", {{node(2, 2), node(2, 1)}, {node(2, 1), node(2, 0)}});
  test_problems::add_edge_set(b, "left", {{node(0, 0), node(0, 1)}, {node(0, 1), node(0, 2)}});
  model::ConstraintSpec sym;
  sym.edge_sets = {"left"};
  sym.ux = "0";
  b.constraints = {sym};
  model::EdgeLoadSpec top, fluid;
  top.edge_sets = {"top"};
  top.value = {q + p_s, 0};
  top.follower = true;
  fluid.edge_sets = {"right"};
  fluid.value = {p_s, 0};
  fluid.follower = true;
  if (penetrating) {
    fluid.edge_sets.push_back("bottom");
    fluid.penetration = model::EdgeLoadSpec::Penetration{0, false, {}};
  }
  b.edge_loads = {top, fluid};
  spec.bodies.push_back(b);
  model::ContactPairSpec c;
  c.body = "block";
  c.edge_sets = {"bottom"};
  c.obstacle.kind = model::ObstacleKind::plane;
  c.obstacle.point = {0, 0};
  c.obstacle.normal = {0, 1};
  spec.contact = {c};
  spec.discretization.degree = {p, p};
  spec.solver.load_steps = 2;
  spec.solver.tolerance = 1e-13;
  return spec;
}

}  // namespace

// Patch test: the block of immersed_block, pressed by q = 20 and immersed in p_s = 30 (E = 1000,
// a strain of some 5 %), shall carry the contact pressure q + p_s at every multiplier node to
// 1e-9 relative (round-off of the solve: the state is homogeneous, σ_xx = −p_s, σ_yy = −q − p_s,
// which every p represents exactly), p = 2 and 4, in the linear theory (dead pressures) and for
// neo-Hooke (follower pressures on the deformed sides; the multiplier is the force per
// undeformed length, the Cauchy pressure q + p_s times the bottom's stretch λ_x).
TEST(FollowerPressure, ImmersedBlockPatchTest) {
  const double q = 20, p_s = 30;
  for (bool finite_strain : {false, true})
    for (int p : {2, 4}) {
      const auto spec = immersed_block(finite_strain, q, p_s, p);
      const auto d = model::discretize(spec);
      const auto sol = model::solve_contact(spec, d);
      ASSERT_TRUE(sol.converged) << sol.message;
      const Eigen::VectorXd& lambda = sol.multipliers[0];
      // the multiplier is the force per undeformed length of the contact boundary: the Cauchy
      // pressure times the bottom's stretch λ_x (1 in the linear theory)
      double stretch = 1;
      if (finite_strain) {
        const auto& body = d.bodies[0];
        const int corner = body.mesh.node_index(3);  // (2, 0)
        stretch = 1 + sol.u(body.dof_offset + 2 * body.dofs.vertex_mode(corner)) / 2;
      }
      const double deviation = (lambda.array() - (q + p_s) * stretch).abs().maxCoeff() / (q + p_s);
      std::printf("%s, p = %d: %d nodes, largest deviation of the contact pressure from q + p_s %.1e\n",
                  finite_strain ? "neo-Hooke" : "linear", p, static_cast<int>(lambda.size()), deviation);
      EXPECT_LE(deviation, 1e-9) << (finite_strain ? "neo-Hooke" : "linear") << ", p = " << p;
    }
}

namespace {

/// examples/o-ring/o-ring-pressurised.yaml at degree p with the system pressure p_s.
model::ProblemSpec pressurised_ring(int p, double p_s) {
  auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/o-ring/o-ring-pressurised.yaml");
  spec.discretization.degree = {p, p};
  spec.bodies[0].edge_loads[0].value[0] = p_s;
  return spec;
}

/// The multiplier node of pair k at the undeformed point X (where a penetrating pressure stops).
int node_at(const model::NonlinearSolution& sol, int k, const Vec2& X) {
  const auto& nodes = sol.pairs[k].constraints->nodes.nodes;
  for (int j = 0; j < static_cast<int>(nodes.size()); ++j)
    if ((nodes[j].X - X).norm() < 1e-9) return j;
  return -1;
}

}  // namespace

// One-sided pressure penetration of the squeezed O-ring section (examples/o-ring, p = 8): as the
// system pressure grows (0.5, 1.5, 3 N/mm², 0.1 to 0.7 of the squeeze's peak contact pressure)
// the point where it stops (the contact zone's pressurised end) shall move towards the sealed
// side (measured x = 20.88, 20.85, 20.43 mm), the seal holding: the pressure also presses the
// ring against the wall and so raises the contact pressure (self-energising), which stays
// above it beyond the stop.
TEST(FollowerPressure, RingPenetrationMovesTowardsTheSealedSide) {
  double previous = 1e300;
  for (double p_s : {0.5, 1.5, 3.0}) {
    const auto spec = pressurised_ring(8, p_s);
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    const auto extent = model::wetted_extent(d, d.follower_loads[0], sol.wet_ranges[0]);
    ASSERT_GE(node_at(sol, 0, extent.stop), 0) << "the pressure stops at a multiplier node";
    std::printf("p_s %.2f: the pressure stops at (%.4f, %.4f), wetted length %.4f, %d Newton iterations\n", p_s,
                extent.stop.x(), extent.stop.y(), extent.length, sol.newton_iterations);
    EXPECT_FALSE(sol.wet_ranges[0].leaks);
    EXPECT_LT(extent.stop.x(), previous) << "p_s = " << p_s;
    previous = extent.stop.x();
  }
}

namespace {

/// The block of immersed_block (linear, E = 1000, ν = 0.3), its top pressed down by δ = 0.01
/// (no load on it), the fluid p_s from its top right corner down the right side and on along the
/// bottom until the contact stops it.
model::ProblemSpec squeezed_block(double p_s) {
  auto spec = immersed_block(false, 0, p_s, 3, true);
  auto& b = spec.bodies[0];
  b.edge_loads.erase(b.edge_loads.begin());  // the top's
  model::ConstraintSpec press;
  press.edge_sets = {"top"};
  press.uy = "-0.01";
  b.constraints.push_back(press);
  return spec;
}

}  // namespace

// A seal leaks when the pressure passes its contact pressure: the block of squeezed_block
// pressed by δ/h = 1 % carries a peak contact pressure σ_max (measured without fluid); a fluid
// of 0.5 σ_max shall stop at the contact (at the bottom's right corner, chain position 2, whose
// contact pressure exceeds it: traction continuity to the node spacing), one of 1.5 σ_max shall
// pass every point of the contact (the fluid under the whole bottom) and be reported as leaking.
TEST(FollowerPressure, SealLeaksAboveThePeakContactPressure) {
  const auto dry_spec = squeezed_block(0);
  const auto dry_d = model::discretize(dry_spec);
  const auto dry = model::solve_contact(dry_spec, dry_d);
  ASSERT_TRUE(dry.converged) << dry.message;
  const double peak = dry.multipliers[0].maxCoeff();
  ASSERT_GT(peak, 0);
  for (double share : {0.5, 1.5}) {
    const auto spec = squeezed_block(share * peak);
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    const bool leaks = sol.wet_ranges.back().leaks;
    std::printf("p_s = %.2f of the peak contact pressure %.4f: leaks %d, wetted to chain position %.4f of 4, "
                "largest multiplier %.4f\n", share, peak, leaks, sol.wet_ranges.back().to, sol.multipliers[0].maxCoeff());
    EXPECT_EQ(leaks, share > 1) << share;
    if (share < 1) {
      EXPECT_NEAR(sol.wet_ranges.back().to, 2.0, 1e-12);
      EXPECT_GT(sol.multipliers[0].maxCoeff(), share * peak);
    } else {
      EXPECT_LT(sol.multipliers[0].maxCoeff(), share * peak);
    }
  }
}

// The arc-length method on a follower load (its path's load derivative the follower force at the
// state reached, ContactSystem::load_vector(x)): Rivlin's plane-strain tube of
// ThickTubeInflationMatchesRivlin (p = 6) inflated to P_Rivlin(1.5) along the arc-length path
// shall end at the closed form's bore stretch within 1e-5 relative, as under load control.
TEST(FollowerPressure, ArcLengthInflationMatchesRivlin) {
  auto spec = pressurised_tube(false, 6, rivlin_pressure(1.5), 4);
  spec.solver.control = "arc-length";
  const auto d = model::discretize(spec);
  const auto sol = model::solve_contact(spec, d);
  ASSERT_TRUE(sol.converged) << sol.message;
  const double l_fe = bore_stretch(d, sol.u);
  std::printf("arc-length: %zu path points, loads factor %.12f, bore stretch %.10f (Rivlin 1.5)\n",
              sol.path.size(), sol.loads_factor, l_fe);
  EXPECT_NEAR(sol.loads_factor, 1.0, 1e-12);
  EXPECT_NEAR(l_fe, 1.5, 1e-5 * 1.5);
}
