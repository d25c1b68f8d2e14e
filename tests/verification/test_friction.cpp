// Friction (Coulomb regularised by a tangential penalty): the analytic tangent of stick and slip
// against central differences of the residual, on two bodies and against a rigid plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>

#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/contact_system.hpp"
#include "hpcontact/model/discretization.hpp"
#include "problems.hpp"

using namespace hpcontact;

// Friction: the analytic tangent (stick: ε_T G_T G_Tᵀ; slip: −μ s ε_N G_T G_nᵀ, not symmetric)
// equals central differences of the residual, friction histories fixed, at the converged end
// of the two-bar examples (two bodies, both sides' points anchored): < 2e-6 of max |K| (measured
// 2.2e-7 with stick, 1.8e-7 with Coulomb).
TEST(FrictionTangent, TwoBarsAgreeWithCentralDifferences) {
  for (const char* name : {"stick.yaml", "coulomb.yaml"}) {
    const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/two-bars/" + name,
                                       {"discretization.degree=[6, 3]", "contact[0].enforcement=penalty"});
    const auto d = model::discretize(spec);
    const auto sol = model::solve_contact(spec, d);
    ASSERT_TRUE(sol.converged) << sol.message;
    double asymmetry = 0;
    const double mismatch = test_problems::tangent_mismatch(spec, d, sol, &asymmetry);
    std::printf("%s: max |K_analytic - K_differences| / max |K| = %.3g, asymmetry %.3g\n", name,
                mismatch, asymmetry);
    EXPECT_LT(mismatch, 2e-6) << name;
  }
}

// Friction against a rigid plane: the distorted patch pressed onto y = 0 (top uy = -0.002),
// then sheared by a traction on its top; Coulomb mu = 0.2 with partial slip, and full stick.
// The analytic tangent (penalty_contact's friction terms) equals central differences: < 5e-7
// of max |K| (measured 4.3e-8 with stick, 8.9e-9 with Coulomb).
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
    c.enforcement = model::Enforcement::penalty;
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
    EXPECT_LT(mismatch, 5e-7) << law;
  }
}

namespace {

/// The sheared block of FrictionPath: [0, 2] × [0, 1] in two elements (nodes 1 2 3 along the
/// bottom, 4 5 6 along the top, node 2 at x = 0.8), E = 1000, ν = 0, plane strain, p = 3, on the
/// rigid plane y = 0 (ε_N = ε_T = 1000, Coulomb μ = 0.3). Its top is held (ux = 0, uy = −δ);
/// its sides follow the uniform normal state (uy = −e − (δ − e) y, ux free); a body force
/// (b_x, 0) pushes it sideways.
model::ProblemSpec sheared_block(double delta, double e, double b_x) {
  model::ProblemSpec spec;
  spec.file = spec.case_name = "sheared-block";
  auto b = test_problems::body("block", 1000, 0);
  test_problems::add_node(b, 1, 0, 0);
  test_problems::add_node(b, 2, 0.8, 0);
  test_problems::add_node(b, 3, 2, 0);
  test_problems::add_node(b, 4, 0, 1);
  test_problems::add_node(b, 5, 0.8, 1);
  test_problems::add_node(b, 6, 2, 1);
  test_problems::add_element(b, 1, 1, 2, 5, 4);
  test_problems::add_element(b, 2, 2, 3, 6, 5);
  test_problems::add_edge_set(b, "bottom", {{1, 2}, {2, 3}});
  test_problems::add_edge_set(b, "top", {{6, 5}, {5, 4}});
  test_problems::add_edge_set(b, "sides", {{4, 1}, {3, 6}});
  model::ConstraintSpec top, sides;
  top.edge_sets = {"top"};
  top.ux = "0";
  top.uy = std::to_string(-delta);
  sides.edge_sets = {"sides"};
  char uy[96];
  std::snprintf(uy, sizeof uy, "%.17g - %.17g*y", -e, delta - e);
  sides.uy = uy;
  b.constraints = {top, sides};
  b.body_force = {b_x, 0};
  spec.bodies.push_back(b);
  model::ContactPairSpec c;
  c.enforcement = model::Enforcement::penalty;
  c.body = "block";
  c.edge_sets = {"bottom"};
  c.obstacle.kind = model::ObstacleKind::plane;
  c.penalty = 1000;
  c.quadrature = 4;
  c.friction.law = "coulomb";
  c.friction.mu = 0.3;
  c.friction.penalty = 1000;
  spec.contact = {c};
  spec.discretization.degree = {3, 3};
  return spec;
}

}  // namespace

// Friction is path dependent and the solver carries each point's slip from step to step: the
// block above is pressed (factor D on the prescribed displacements), sheared by its body force
// (factor L) into slip, unsheared (stick, a residual traction stays), half unpressed (it slips
// back) and pressed again (stick) — and at every converged step each contact point's pressure,
// tangential traction, slip, stick/slip state and displacement are those of the closed form
// (to 1e-9 of μ p and of δ), and the two states at D = 1, L = 0 differ (t_T = −7/6 vs −3/4).
//
// Closed form (h = 1, G = E/2 = 500). The state is uniform in x: σxx = 0, σyy = −p,
// σxy(y) = τ − b_x L y, so ux = a + (τ y − b_x L y²/2)/G (quadratic: in the p = 3 space), uy
// linear; the sides' prescribed uy is that state's and their reactions carry σxy.
//  - Normal: p = ε_N e D = E (δ − e) D / h, so e = δ E / (E + h ε_N) = 0.005 and p = 5 D.
//  - Tangential: ux(h) = 0 gives the bottom's slide a = F − τ h / G with F = b_x L h² / (2G);
//    the point slides by g_T = a from its anchor (it touches at the start, anchored there), and
//    the plane's traction on it is −t_T (τ = t_T). Stick: t_T = ε_T (a − g_s), so
//    t_T = k (F − g_s) with k = ε_T / (1 + ε_T h / G) = 1000/3. Slip (|that| ≥ μ p):
//    t_T = ±μ p and g_s = a − t_T / ε_T (the return mapping, exact for a monotone step).
// With b_x = 8 (F = 0.008 L), by hand: shear: stick at L = 0.2, 0.4 (t_T = 2.67 L), slip from
// L = 0.6 (t_T = 1.5, g_s = 0.0003) to L = 1 (g_s = 0.0035); unshear: stick, t_T = k (F − 0.0035)
// down to −7/6 at L = 0; unpress: stick at D = 5/6 (bound 1.25), slip back at D = 2/3
// (t_T = −1, g_s = 0.003) and D = 1/2 (t_T = −0.75, g_s = 0.00225); press: stick, t_T = −0.75.
TEST(FrictionPath, LoadShearUnloadFollowsTheClosedForm) {
  const double E = 1000, G = 500, h = 1, eps_n = 1000, eps_t = 1000, mu = 0.3;
  const double delta = 0.01, e = delta * E / (E + h * eps_n), b_x = 8;
  auto spec = sheared_block(delta, e, b_x);
  spec.solver.stages = {{1, 0, 2}, {1, 1, 5}, {1, 0, 5}, {0.5, 0, 3}, {1, 0, 2}};
  const auto d = model::discretize(spec);

  struct Expected {
    double p, t, slip, a;
    bool slipping;
  };
  double g_s = 0;  // the closed form's committed slip
  auto closed_form = [&](double D, double L) {
    const double p = eps_n * e * D, F = b_x * L * h * h / (2 * G), k = eps_t / (1 + eps_t * h / G);
    const double stick = k * (F - g_s);
    if (std::abs(stick) < mu * p || stick == 0) return Expected{p, stick, g_s, F - stick * h / G, false};
    const double t = std::copysign(mu * p, stick), a = F - t * h / G;
    g_s = a - t / eps_t;
    return Expected{p, t, g_s, a, true};
  };
  std::vector<std::array<double, 4>> seen;  // D, L, t_T, slip per step (first point)
  double worst_t = 0, worst_u = 0;
  int steps = 0, slipping_steps = 0;
  const auto on_step = [&](const Eigen::VectorXd& u, const model::NonlinearSolution::PathPoint& pp,
                           const std::vector<model::ContactPair>& pairs,
                           const std::vector<Eigen::VectorXd>&) {
    const auto x = closed_form(pp.displacements, pp.loads);
    const auto r = model::evaluate_contact(d, pairs.front(), u);
    ++steps;
    slipping_steps += x.slipping;
    for (size_t i = 0; i < r.states.size(); ++i) {
      const auto& s = r.states[i];
      const double slide = s.x.x() - pairs.front().points[i].X.x();
      worst_t = std::max({worst_t, std::abs(s.pressure - x.p), std::abs(s.t_t - x.t)});
      worst_u = std::max({worst_u, std::abs(s.slip - x.slip), std::abs(slide - x.a)});
      EXPECT_NEAR(s.pressure, x.p, 1e-9 * mu * 5) << "D " << pp.displacements << " L " << pp.loads;
      EXPECT_NEAR(s.t_t, x.t, 1e-9 * mu * 5) << "D " << pp.displacements << " L " << pp.loads;
      EXPECT_NEAR(s.slip, x.slip, 1e-9 * delta) << "D " << pp.displacements << " L " << pp.loads;
      EXPECT_NEAR(slide, x.a, 1e-9 * delta) << "D " << pp.displacements << " L " << pp.loads;
      EXPECT_EQ(s.stick_slip, x.slipping ? contact::StickSlip::slip : contact::StickSlip::stick)
          << "D " << pp.displacements << " L " << pp.loads;
    }
    seen.push_back({pp.displacements, pp.loads, r.states.front().t_t, r.states.front().slip});
  };
  const auto sol = model::solve_contact(spec, d, {}, {}, on_step);
  ASSERT_TRUE(sol.converged) << sol.message;
  std::printf("sheared block: %d steps (%d slipping), max |pressure or t_T − closed form| %.3g, "
              "max |slip or slide − closed form| %.3g\n", steps, slipping_steps, worst_t, worst_u);
  EXPECT_EQ(steps, 17);
  EXPECT_EQ(slipping_steps, 5);  // L = 0.6, 0.8, 1 forwards; D = 2/3, 1/2 backwards
  // The hand values at the ends of the stages (after 2, 7, 12, 15, 17 steps).
  auto at = [&](int step) { return seen.at(step - 1); };
  EXPECT_NEAR(at(7)[2], 1.5, 1e-9);
  EXPECT_NEAR(at(7)[3], 0.0035, 1e-11);
  EXPECT_NEAR(at(12)[2], -7.0 / 6, 1e-9);
  EXPECT_NEAR(at(12)[3], 0.0035, 1e-11);
  EXPECT_NEAR(at(15)[2], -0.75, 1e-9);
  EXPECT_NEAR(at(15)[3], 0.00225, 1e-11);
  EXPECT_NEAR(at(17)[2], -0.75, 1e-9);
  EXPECT_NEAR(at(17)[3], 0.00225, 1e-11);
  // Same loads, different states: the path matters.
  EXPECT_EQ(at(12)[0], at(17)[0]);
  EXPECT_EQ(at(12)[1], at(17)[1]);
}

namespace {

/// Whether two sparse matrices hold the same entries, pattern and bits.
bool identical(solve::SparseMatrix a, solve::SparseMatrix b) {
  a.makeCompressed();
  b.makeCompressed();
  if (a.rows() != b.rows() || a.cols() != b.cols() || a.nonZeros() != b.nonZeros()) return false;
  const auto nnz = a.nonZeros();
  return std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.outerSize() + 1, b.outerIndexPtr()) &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + nnz, b.innerIndexPtr()) &&
         std::equal(a.valuePtr(), a.valuePtr() + nnz, b.valuePtr());
}

}  // namespace

// ContactSystem::evaluate keeps the linear bodies' block, widened to all unknowns, from one
// tangent to the next: the tangent shall be a fresh system's, bit for bit, at a second state
// whose active set differs (the sum's pattern changes), under a force target added (one
// unknown more) and after it is dropped again. Two cylinders in partial slip (exact Coulomb
// friction between the bodies).
TEST(Friction, KeptBodyBlockGivesTheFreshTangent) {
  const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/tests/verification/partial-slip-coarse.yaml");
  const auto d = model::discretize(spec);
  const auto sol = model::solve_contact(spec, d);
  ASSERT_TRUE(sol.converged) << sol.message;
  const auto pairs = model::pairs_of_last_step(sol);
  auto make_system = [&] {
    auto s = std::make_unique<model::ContactSystem>(d, pairs, spec.discretization.condense,
                                                    model::ContactSystem::Tangent::analytic, sol.elastic);
    s->set_factors(sol.displacement_factors, sol.loads_factor);
    return s;
  };
  auto tangent = [](model::ContactSystem& s, const Eigen::VectorXd& x) {
    Eigen::VectorXd r;
    solve::SparseMatrix K;
    s.evaluate(x, r, &K);
    return K;
  };
  auto kept = make_system();
  const Eigen::VectorXd x = kept->unknowns(sol.u, sol.multipliers);
  const solve::SparseMatrix K_converged = tangent(*kept, x);
  const int in_contact = kept->points_in_contact();
  const Eigen::VectorXd x_part = 0.3 * x;  // less pressed: fewer nodes active
  const solve::SparseMatrix K_part = tangent(*kept, x_part);
  EXPECT_NE(kept->points_in_contact(), in_contact);
  EXPECT_TRUE(identical(K_part, tangent(*make_system(), x_part)));

  const std::pair<int, double> target(1, sol.contact.front().resultant.y());
  kept->set_force_target(target);
  auto fresh = make_system();
  fresh->set_force_target(target);
  const Eigen::VectorXd x_target = kept->unknowns(sol.u, sol.multipliers);
  ASSERT_EQ(x_target.size(), x.size() + 1);
  EXPECT_TRUE(identical(tangent(*kept, x_target), tangent(*fresh, x_target)));
  kept->set_force_target(std::nullopt);
  EXPECT_TRUE(identical(tangent(*kept, x), K_converged));
}
