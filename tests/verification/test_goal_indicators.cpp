// The pieces of goal-oriented degrees (adapt/goal_degrees.hpp): the adjoint of a contact solve
// against finite differences of the functional it weighs, the surplus energies against the
// modes a coarser space lacks, and the estimate's solve started from the step's solution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hpcontact/adapt/error_estimate.hpp"
#include "hpcontact/adapt/solved.hpp"
#include "hpcontact/adapt/transfer.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/contact_solve.hpp"
#include "hpcontact/model/discretization.hpp"
#include "hpcontact/post/fields.hpp"

using namespace hpcontact;

namespace {

/// examples/hertz/p8.yaml (quarter cylinder on a rigid flat, exact contact, force control to
/// F/2) at degree p.
model::ProblemSpec hertz(int p) {
  return io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/hertz/p8.yaml",
                          {"discretization.degree=" + std::to_string(p), "output.vtu=false"});
}

/// J(λ) = Σ_j W_j X_j² λ_j over the normal multipliers (`tangential`: the tangential ones) of
/// the first pair: the second moment of the pressure (the shear) about the symmetry line, which
/// changes with its shape even where the total force is held.
std::vector<Eigen::VectorXd> second_moment_gradient(const adapt::Solved& s, bool tangential = false) {
  std::vector<Eigen::VectorXd> g(s.solution.pairs.size());
  const auto& c = *s.solution.pairs[0].constraints;
  g[0] = Eigen::VectorXd::Zero(s.solution.multipliers[0].size());
  for (int j = 0; j < c.size(); ++j)
    g[0]((tangential ? c.size() : 0) + j) = c.nodes.nodes[j].weight * c.nodes.nodes[j].X.x() * c.nodes.nodes[j].X.x();
  return g;
}

/// The spec with a body force b per volume on its first body (in place of what it has).
model::ProblemSpec with_body_force(model::ProblemSpec spec, const Vec2& b) {
  spec.bodies[0].body_force = {b.x(), b.y()};
  return spec;
}

/// dJ/dε of a body force ε b on the first body against the adjoint's prediction α zᵀ f_b (α the
/// factor the solve put on the loads: 1, or the force control's factor, which scales loads and
/// displacements), J the second moment of the pressure (or the shear): the two agree to
/// `tolerance` of the differences, which are at least `least` times J.
void expect_adjoint_predicts(const model::ProblemSpec& spec, const Vec2& b, double least,
                             double tolerance, bool tangential = false) {
  const auto s = adapt::solve(spec);
  auto J = [&](const adapt::Solved& r) {
    return second_moment_gradient(r, tangential)[0].dot(r.solution.multipliers[0]);
  };
  const Eigen::VectorXd z = model::multiplier_adjoint(s->spec, s->discretization, s->solution,
                                                      second_moment_gradient(*s, tangential));
  const Eigen::VectorXd f_b =
      model::discretize(with_body_force(spec, b)).load - model::discretize(with_body_force(spec, Vec2::Zero())).load;
  const double predicted = s->solution.loads_factor * z.dot(f_b);
  // central differences, Richardson-extrapolated (under force control J is not linear in ε:
  // the factor scales the body force too, and it moves with ε)
  auto central = [&](double eps) {
    const auto plus = adapt::solve(with_body_force(spec, eps * b));
    const auto minus = adapt::solve(with_body_force(spec, -eps * b));
    EXPECT_EQ(plus->solution.multipliers[0].size(), s->solution.multipliers[0].size());
    return (J(*plus) - J(*minus)) / (2 * eps);
  };
  const double differences = (4 * central(5e-4) - central(1e-3)) / 3;
  // far from zero: the body force moves the pressure's (the shear's) shape
  EXPECT_GT(std::abs(differences), least * std::abs(J(*s)));
  EXPECT_NEAR(predicted, differences, tolerance * std::abs(differences));
}

/// On Hertz: a body force of the load's size, its prediction measured to 1e-11.
void expect_adjoint_predicts_on_hertz(const model::ProblemSpec& spec) {
  const Vec2 b(30.0, -200.0);
  expect_adjoint_predicts(spec, b, 1e-3 / (b.norm() * 1e-2), 1e-8);
}

}  // namespace

// Under force control (the factor an unknown held by the target force): the adjoint's load
// term predicts how the pressure's second moment moves with a body force (measured to 1e-11).
TEST(MultiplierAdjoint, PredictsTheFunctionalUnderForceControl) {
  model::ProblemSpec spec = hertz(4);
  ASSERT_TRUE(spec.solver.target_resultant);
  expect_adjoint_predicts_on_hertz(spec);
}

// Under force control through stages (pressed to the force with the loads at 0, then the loads
// applied with the force held): the factor scales the displacements only, the loads keep the
// stage's factor.
TEST(MultiplierAdjoint, PredictsTheFunctionalUnderForceControlThroughStages) {
  model::ProblemSpec spec = hertz(4);
  ASSERT_TRUE(spec.solver.target_resultant);
  model::LoadStageSpec press, load;
  press.loads = 0;
  press.steps = load.steps = 1;
  spec.solver.stages = {press, load};
  expect_adjoint_predicts_on_hertz(spec);
}

// Under displacement control (the centre's displacement prescribed, the force free).
TEST(MultiplierAdjoint, PredictsTheFunctionalUnderDisplacementControl) {
  model::ProblemSpec spec = hertz(4);
  spec.solver.target_resultant.reset();
  for (auto& c : spec.bodies[0].constraints)
    if (c.uy) c.uy = "-0.45";
  expect_adjoint_predicts_on_hertz(spec);
}

// Two equal cylinders (examples/partial-slip/hp-tolerance.yaml's rings at p = 3) pressed by a
// force through stages, then sheared with the force held: the adjoint's load term predicts how
// the shear's second moment moves with a body force on the upper one. Its transposed tangent
// is not singular, but the saddle-point solver's Schur complement of it looked so (reciprocal
// condition 2e-15) and the goal-oriented weights were left out of every hp step there.
TEST(MultiplierAdjoint, PredictsTheShearOfTwoCylindersUnderForceControlThroughStages) {
  const model::ProblemSpec spec = io::read_problem(
      std::string(HPC_SOURCE_DIR) + "/examples/partial-slip/hp-tolerance.yaml",
      {"adapt.method=none", "discretization.degree=3", "output.vtu=false",
       "solver.target_resultant={value: 7}"});
  ASSERT_TRUE(spec.contact[0].friction.law == "coulomb");
  // ε b over the upper half disc: ~1e-6 of P at ε = 1e-3; measured to 1.7e-4: the two-body
  // tangent and the friction states near the stick–slip points
  expect_adjoint_predicts(spec, Vec2(2e-3, -1e-2), 1e-6, 1e-3, true);
}

// The surplus of a field is the energy of the modes the coarser element lacks: none for a vertex
// mode (every space has it), all of it for an edge mode of the new degree, in both elements that
// share the edge.
TEST(SurplusEnergies, AreTheEnergyOfTheModesTheCoarserSpaceLacks) {
  const model::Discretization coarse = model::discretize(hertz(3));
  const model::Discretization fine = model::discretize(hertz(4));
  const auto& body = fine.bodies[0];
  // a vertex mode: the middle node (5, user id), shared by all four elements
  Eigen::VectorXd vertex = Eigen::VectorXd::Zero(fine.n_dofs);
  vertex(body.dof_offset + 2 * body.dofs.vertex_mode(body.mesh.node_index(5))) = 1e-3;
  const auto none = adapt::surplus_energies(coarse, fine, vertex);
  const auto all = post::element_strain_energies(fine, vertex);
  for (int q = 0; q < body.mesh.n_quads(); ++q) {
    EXPECT_GT(all[0][q], 0.0);
    EXPECT_EQ(none[0][q], 0.0);
  }
  // the degree-4 mode of the edge between nodes 2 and 5 (elements 1 and 2)
  const int e = body.mesh.find_edge(body.mesh.node_index(2), body.mesh.node_index(5));
  ASSERT_GE(e, 0);
  Eigen::VectorXd edge = Eigen::VectorXd::Zero(fine.n_dofs);
  edge(body.dof_offset + 2 * body.dofs.edge_mode(e, 4) + 1) = 1e-3;
  const auto surplus = adapt::surplus_energies(coarse, fine, edge);
  const auto energy = post::element_strain_energies(fine, edge);
  int touched = 0;
  for (int q = 0; q < body.mesh.n_quads(); ++q) {
    EXPECT_NEAR(surplus[0][q], energy[0][q], 1e-14 * energy[0][q]);
    touched += energy[0][q] > 0;
  }
  EXPECT_EQ(touched, 2);
}

// The error estimate's solve starts from the step's solution: on the same mesh one degree higher
// the field is the same to round-off at every point (each mode's coefficient where the higher
// space has the same mode), and each pair's pressure is the same polynomial along every edge.
TEST(CarryOver, OneDegreeMoreOnTheSameMeshIsTheSameSolution) {
  const auto s = adapt::solve(hertz(4));
  const model::ProblemSpec higher = adapt::with_degrees_raised(s->spec);
  const model::Discretization d = model::discretize(higher);
  const auto pairs = model::make_contact_pairs(higher, d);
  const model::StartState start = adapt::carry_over(s->discretization, s->solution, d, pairs);
  const auto& lo = s->discretization.bodies[0];
  const auto& hi = d.bodies[0];
  double largest = 0;
  for (int q = 0; q < lo.mesh.n_quads(); ++q)
    for (double xi : {-0.9, -0.3, 0.4, 1.0})
      for (double eta : {-1.0, 0.1, 0.7}) {
        const auto a = post::evaluate(lo, q, xi, eta, s->solution.u);
        const auto b = post::evaluate(hi, q, xi, eta, start.u);
        EXPECT_LT((a.u - b.u).norm(), 1e-12 * (1 + a.u.norm())) << q;
        EXPECT_LT((a.stress - b.stress).norm(), 1e-8 * (1 + a.stress.norm())) << q;
        largest = std::max(largest, a.u.norm());
      }
  EXPECT_GT(largest, 0.1);  // the centre moved by ~0.5 mm: a real field, not zeros
  // the same field's energy, integrated with one Gauss point more per direction (the arcs'
  // blending maps are not polynomial: measured 3e-7 apart)
  EXPECT_NEAR(post::strain_energy(d, start.u), post::strain_energy(s->discretization, s->solution.u),
              1e-6 * post::strain_energy(s->discretization, s->solution.u));
  const auto& old_nodes = s->solution.pairs[0].constraints->nodes;
  const auto& new_nodes = pairs[0].constraints->nodes;
  ASSERT_EQ(start.multipliers[0].size(), new_nodes.size());
  ASSERT_GT(new_nodes.size(), old_nodes.size());
  for (int k = 0; k < static_cast<int>(new_nodes.edge_nodes.size()); ++k)
    for (double t : {-0.95, -0.2, 0.5, 0.99})
      EXPECT_NEAR(new_nodes.interpolate(k, t, start.multipliers[0]),
                  old_nodes.interpolate(k, t, s->solution.multipliers[0]), 1e-9 * 3e4);
}
