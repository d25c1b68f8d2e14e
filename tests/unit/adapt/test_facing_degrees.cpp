// Facing contact edges of two bodies get the same degree, the larger; edges that do not face
// each other, and pairs against rigid obstacles, keep theirs.
#include <gtest/gtest.h>

#include "hpcontact/adapt/facing_degrees.hpp"

using namespace hpcontact;

namespace {

/// A strip of `n` unit squares along y = y0 (x from x0), its bottom (top = false) or top edges in
/// the edge set "contact", element ids 1..n with the given degrees.
model::BodySpec strip(const std::string& name, int n, double x0, double y0, bool top,
                      const std::vector<int>& degrees) {
  model::BodySpec b;
  b.name = name;
  for (int i = 0; i <= n; ++i) {
    b.node_ids.push_back(i + 1);
    b.nodes.push_back({x0 + i, y0});
    b.node_ids.push_back(n + 2 + i);
    b.nodes.push_back({x0 + i, y0 + 1});
  }
  model::EdgeSetSpec contact;
  contact.name = "contact";
  for (int i = 0; i < n; ++i) {
    b.element_ids.push_back(i + 1);
    b.elements.push_back({i + 1, i + 2, n + 3 + i, n + 2 + i});
    if (top) contact.edges.push_back({n + 3 + i, n + 2 + i});
    else contact.edges.push_back({i + 1, i + 2});
    b.element_degrees[i + 1] = {degrees[i], degrees[i]};
  }
  b.edge_sets.push_back(contact);
  return b;
}

model::ContactPairSpec pair_between(const std::string& body, const std::string& other) {
  model::ContactPairSpec c;
  c.body = body;
  c.edge_sets = {"contact"};
  c.obstacle.kind = model::ObstacleKind::body;
  c.obstacle.body = other;
  c.obstacle.edge_sets = {"contact"};
  c.friction.law = "coulomb";
  c.friction.mu = 0.3;
  return c;
}

int degree(const model::BodySpec& b, int id) { return b.element_degrees.at(id)[0]; }

}  // namespace

TEST(FacingDegrees, FacingElementsTakeTheLargerDegree) {
  model::ProblemSpec spec;
  // upper strip on the lower one, element for element; degrees differ in both directions
  spec.bodies = {strip("upper", 3, 0, 0, false, {8, 6, 4}), strip("lower", 3, 0, -1, true, {6, 8, 4})};
  spec.contact = {pair_between("upper", "lower")};
  adapt::match_facing_degrees(spec);
  for (int id : {1, 2}) {
    EXPECT_EQ(degree(spec.bodies[0], id), 8) << id;
    EXPECT_EQ(degree(spec.bodies[1], id), 8) << id;
  }
  EXPECT_EQ(degree(spec.bodies[0], 3), 4);
  EXPECT_EQ(degree(spec.bodies[1], 3), 4);
}

TEST(FacingDegrees, ShiftedMeshesFaceWhereMostOfAnEdgeIsCovered) {
  model::ProblemSpec spec;
  // the lower strip shifted by a quarter of an element: each upper element faces the lower one
  // it covers three quarters of
  spec.bodies = {strip("upper", 3, 0, 0, false, {2, 2, 7}), strip("lower", 3, 0.25, -1, true, {3, 2, 2})};
  spec.contact = {pair_between("upper", "lower")};
  adapt::match_facing_degrees(spec);
  EXPECT_EQ(degree(spec.bodies[0], 1), 3);  // faces lower 1 (overlap 0.75)
  EXPECT_EQ(degree(spec.bodies[1], 1), 3);
  EXPECT_EQ(degree(spec.bodies[0], 2), 2);  // faces lower 2
  EXPECT_EQ(degree(spec.bodies[1], 3), 7);  // faces upper 3
  EXPECT_EQ(degree(spec.bodies[0], 3), 7);

  // shifted by half an element: each upper element overlaps two lower ones by half its length,
  // which is not "facing" (more than half)
  spec.bodies = {strip("upper", 2, 0, 0, false, {2, 9}), strip("lower", 2, 0.5, -1, true, {5, 4})};
  adapt::match_facing_degrees(spec);
  EXPECT_EQ(degree(spec.bodies[0], 1), 2);  // half overlaps only: nothing faces
  EXPECT_EQ(degree(spec.bodies[0], 2), 9);
  EXPECT_EQ(degree(spec.bodies[1], 1), 5);
}

TEST(FacingDegrees, BodiesApartOrAgainstARigidObstacleKeepTheirDegrees) {
  model::ProblemSpec spec;
  spec.bodies = {strip("upper", 2, 0, 0, false, {8, 6}), strip("lower", 2, 0, -5, true, {4, 4})};
  spec.contact = {pair_between("upper", "lower")};
  adapt::match_facing_degrees(spec);  // the lower strip's top lies 4 below: not facing
  EXPECT_EQ(degree(spec.bodies[0], 1), 8);
  EXPECT_EQ(degree(spec.bodies[1], 1), 4);

  spec.bodies[1] = strip("lower", 2, 0, -1, true, {4, 4});
  spec.contact[0].obstacle.kind = model::ObstacleKind::plane;
  adapt::match_facing_degrees(spec);
  EXPECT_EQ(degree(spec.bodies[0], 1), 8);
  EXPECT_EQ(degree(spec.bodies[1], 1), 4);
}

TEST(FacingDegrees, OnlyPairsWithFrictionEnforcedExactly) {
  model::ProblemSpec spec;
  spec.bodies = {strip("upper", 1, 0, 0, false, {8}), strip("lower", 1, 0, -1, true, {4})};
  spec.contact = {pair_between("upper", "lower")};
  spec.contact[0].friction.law = "none";
  adapt::match_facing_degrees(spec);
  EXPECT_EQ(degree(spec.bodies[1], 1), 4);
  spec.contact[0].friction.law = "coulomb";
  spec.contact[0].enforcement = model::Enforcement::penalty;
  adapt::match_facing_degrees(spec);
  EXPECT_EQ(degree(spec.bodies[1], 1), 4);
  spec.contact[0].enforcement = model::Enforcement::augmented_lagrangian;
  adapt::match_facing_degrees(spec);
  EXPECT_EQ(degree(spec.bodies[1], 1), 8);
}

// One element facing two of different degrees: the upper strip's one element (length 2) lies on
// two lower elements of degrees 3 and 6, and faces both (each covers all of itself, the shorter).
// All three end with the largest degree, 6: the couple met first (degrees 4 and 3) is matched
// before the upper element takes 6 from the second, and must be matched again.
TEST(FacingDegrees, AnElementFacingTwoTakesTheLargestAndSoDoBoth) {
  model::ProblemSpec spec;
  model::BodySpec upper = strip("upper", 1, 0, 0, false, {4});
  // stretch the one element over two lower ones: its right nodes (2 and 4) to x = 2
  for (size_t i = 0; i < upper.node_ids.size(); ++i)
    if (upper.nodes[i][0] == 1) upper.nodes[i][0] = 2;
  spec.bodies = {upper, strip("lower", 2, 0, -1, true, {3, 6})};
  spec.contact = {pair_between("upper", "lower")};
  adapt::match_facing_degrees(spec);
  EXPECT_EQ(degree(spec.bodies[0], 1), 6);
  EXPECT_EQ(degree(spec.bodies[1], 1), 6);
  EXPECT_EQ(degree(spec.bodies[1], 2), 6);
}
