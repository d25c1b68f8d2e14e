// Geometric hp meshes (adapt/geometric_refinement): conforming, exact on the circle, with the
// displacement continuous across every interior edge for any dofs, degrees rising by layer.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "hpcontact/adapt/facing_degrees.hpp"
#include "hpcontact/adapt/geometric_refinement.hpp"
#include "hpcontact/adapt/hp.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/io/problem_reader.hpp"
#include "hpcontact/model/discretization.hpp"
#include "problems.hpp"

using namespace hpcontact;

namespace {

/// The Hertz quarter refined `steps` times towards node 2 (on the arc), degrees by layer.
model::ProblemSpec graded(int steps, double factor) {
  auto spec = test_problems::quarter_circle_2x2(4);
  for (int k = 0; k < steps; ++k) spec = adapt::refine_towards_node(spec, 0, 2, factor);
  for (const auto& [id, layer] : adapt::element_layers(spec.bodies[0], {2}))
    spec.bodies[0].element_degrees[id] = {1 + layer, 1 + layer};
  return spec;
}

}  // namespace

TEST(HpMesh, RefinementIsConformingAndContinuous) {
  for (const double factor : {0.5, 0.17}) {
    const auto spec = graded(4, factor);
    const auto d = model::discretize(spec);
    const auto& body = d.bodies[0];
    EXPECT_EQ(body.mesh.n_quads(), 4 + 4 * 4);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uni(-1, 1);
    Eigen::VectorXd u(d.n_dofs);
    for (int i = 0; i < u.size(); ++i) u(i) = uni(rng);
    int interior = 0;
    for (int e = 0; e < body.mesh.n_edges(); ++e) {
      const auto& edge = body.mesh.edge(e);
      if (edge.on_boundary()) continue;
      ++interior;
      for (const double t : {-0.83, -0.2, 0.35, 0.9}) {
        const int qa = edge.quads[0], la = edge.local_edge[0];
        const int qb = edge.quads[1], lb = edge.local_edge[1];
        const Vec2 xa = fem::edge_geometry(body.maps[qa], la, t, nullptr, nullptr);
        // The same point seen from the other element: its local edge may run the other way.
        double tb = t;
        if ((fem::edge_geometry(body.maps[qb], lb, t, nullptr, nullptr) - xa).norm() >
            (fem::edge_geometry(body.maps[qb], lb, -t, nullptr, nullptr) - xa).norm())
          tb = -t;
        const Vec2 xb = fem::edge_geometry(body.maps[qb], lb, tb, nullptr, nullptr);
        ASSERT_LT((xa - xb).norm(), 1e-12) << "factor " << factor << " edge " << e;
        EXPECT_LT((test_problems::edge_displacement(body, qa, la, t, u) -
                   test_problems::edge_displacement(body, qb, lb, tb, u)).norm(),
                  1e-12)
            << "factor " << factor << " edge " << e << " t " << t;
      }
    }
    EXPECT_GT(interior, 20);
  }
}

TEST(HpMesh, NewBoundaryNodesLieOnTheCircleAndEdgeSetsFollow) {
  const auto spec = graded(3, 0.17);
  const auto& b = spec.bodies[0];
  // Every node on the arc edge set lies on the circle of radius 10 about (0, 10).
  for (const auto& set : b.edge_sets) {
    if (set.name != "arc") continue;
    EXPECT_EQ(set.edges.size(), 4u + 2 * 3);  // each step splits the two arc edges at node 2
    for (const auto& e : set.edges)
      for (int id : e)
        for (size_t i = 0; i < b.node_ids.size(); ++i)
          if (b.node_ids[i] == id)
            EXPECT_NEAR(std::hypot(b.nodes[i][0], b.nodes[i][1] - 10), 10.0, 1e-12) << id;
  }
  // The element at node 2 shrinks geometrically: its arc edge is 0.17³ of the original.
  const auto d = model::discretize(spec);
  const auto& m = d.bodies[0].mesh;
  double shortest = 1e9;
  for (int e = 0; e < m.n_edges(); ++e)
    if (m.edge(e).v0 == m.node_index(2) || m.edge(e).v1 == m.node_index(2))
      if (m.edge(e).on_boundary() && m.edge(e).curve)
        shortest = std::min(shortest, m.edge(e).curve->length());
  const double first = 10 * std::asin(2.48 / 10);  // arc from node 1 (x = 0) to node 2
  EXPECT_NEAR(shortest, std::pow(0.17, 3) * first, 1e-9);
}

TEST(HpMesh, LayersCountRingsAroundTheCentre) {
  const auto spec = graded(2, 0.5);
  const auto layers = adapt::element_layers(spec.bodies[0], {2});
  std::map<int, int> count;
  for (const auto& [id, layer] : layers) ++count[layer];
  EXPECT_EQ(count[0], 2);  // the two corner squares at node 2
  EXPECT_EQ(count[1], 4);  // the pieces of the last step
  EXPECT_EQ(count[2], 4);  // the pieces of the first step
  EXPECT_EQ(count[3], 2);  // the top elements, which share nodes with the first step's pieces
  EXPECT_EQ(layers.size(), 12u);
}

// The adaptive hp loop shall give the elements at its refinement centre (the node it placed
// on Γ*) the minimum degree and every layer of elements around them one degree more (seed
// §4.7): on examples/hertz/hp.yaml with two refinement steps, every element's degree
// is min_degree + its layer, and the layers reach at least 3.
TEST(HpMesh, AdaptiveDegreesRiseByOnePerLayer) {
  const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/hertz/hp.yaml",
                                     {"adapt.steps=2"});
  const adapt::HpOptions o = adapt::hp_options(spec.adapt);
  const auto out = adapt::refine_towards_zone_ends(spec, o);
  ASSERT_TRUE(out.converged) << out.message;
  ASSERT_EQ(out.history.size(), 3u);
  const auto& last = out.last->spec.bodies[0];
  ASSERT_EQ(out.history.back().centres.size(), 1u);
  const Vec2 centre = out.history.back().centres.front();
  int centre_id = -1;
  for (size_t i = 0; i < last.nodes.size(); ++i)
    if ((Vec2(last.nodes[i][0], last.nodes[i][1]) - centre).norm() < 1e-9) centre_id = last.node_ids[i];
  ASSERT_GE(centre_id, 0);
  int deepest = 0;
  for (const auto& [id, layer] : adapt::element_layers(last, {centre_id})) {
    ASSERT_TRUE(last.element_degrees.count(id)) << "element " << id;
    const auto p = last.element_degrees.at(id);
    EXPECT_EQ(p[0], o.min_degree + layer) << "element " << id << " layer " << layer;
    EXPECT_EQ(p[1], o.min_degree + layer) << "element " << id << " layer " << layer;
    deepest = std::max(deepest, layer);
  }
  EXPECT_GE(deepest, 3);
}

namespace {

/// The degree (the larger of p_xi, p_eta) of the element with user id `id` of body b.
int element_degree(const model::ProblemSpec& spec, size_t b, int id) {
  const auto& body = spec.bodies[b];
  const auto it = body.element_degrees.find(id);
  const auto p = it != body.element_degrees.end() ? it->second : body.degree.value_or(spec.discretization.degree);
  return std::max(p[0], p[1]);
}

}  // namespace

// hp's rules of degrees hold on the mesh of every step it builds, not only on the last: with
// goal-oriented degrees (a tolerance), whose corrections lower degrees but never below it, no
// element lies below adapt.min_degree, and the facing contact edges of the two bars, an exactly
// enforced pair with Coulomb friction, have equal degrees (matching them again changes none).
// examples/two-bars/coulomb-hp.yaml (min_degree 3) to a tolerance of 1e-2, two steps at most;
// step 0 is the input's mesh and degrees.
TEST(HpMesh, EveryStepKeepsTheMinimumDegreeAndEqualFacingDegrees) {
  const auto spec = io::read_problem(std::string(HPC_SOURCE_DIR) + "/examples/two-bars/coulomb-hp.yaml",
                                     {"adapt.tolerance=1e-2", "adapt.steps=2", "output.vtu=false"});
  const int low = spec.adapt.min_degree;
  ASSERT_GE(low, 2);
  const adapt::HpOptions o = adapt::hp_options(spec.adapt);
  ASSERT_EQ(o.degree, model::HpDegree::goal);
  int steps = 0, lowered = 0;
  adapt::refine_towards_zone_ends(spec, o, {}, [&](const adapt::HpIteration& it, const adapt::Solved& s) {
    lowered += it.degrees_lowered;
    if (it.step == 0) return;
    ++steps;
    for (size_t b = 0; b < s.spec.bodies.size(); ++b)
      for (const int id : s.spec.bodies[b].element_ids) {
        const auto& body = s.spec.bodies[b];
        const auto given = body.element_degrees.find(id);
        const auto p = given != body.element_degrees.end() ? given->second
                                                           : body.degree.value_or(s.spec.discretization.degree);
        EXPECT_GE(std::min(p[0], p[1]), low) << "step " << it.step << " body " << b << " element " << id;
      }
    model::ProblemSpec again = s.spec;
    adapt::match_facing_degrees(again);
    for (size_t b = 0; b < s.spec.bodies.size(); ++b)
      for (const int id : s.spec.bodies[b].element_ids)
        EXPECT_EQ(element_degree(again, b, id), element_degree(s.spec, b, id))
            << "step " << it.step << " body " << b << " element " << id;
  });
  EXPECT_EQ(steps, 2);
  EXPECT_GT(lowered, 0);  // the corrections lowered degrees (31 measured)
}
