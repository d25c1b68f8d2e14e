// Stick-slip transitions along a contact boundary: only between neighbouring points of which one
// sticks and the other slips, never across a point without a friction state or a chain break.
#include <gtest/gtest.h>

#include "hpcontact/contact/stick_slip.hpp"

namespace hpcontact::contact {
namespace {

using S = StickSlip;

/// A row of three unit squares, nodes 0..3 along y = 0 and 4..7 along y = 1: the bottom edges
/// (0-1, 1-2, 2-3) form one open chain.
mesh::Mesh strip() {
  return mesh::Mesh({Vec2(0, 0), Vec2(1, 0), Vec2(2, 0), Vec2(3, 0), Vec2(0, 1), Vec2(1, 1), Vec2(2, 1),
                     Vec2(3, 1)},
                    {1, 2, 3, 4, 5, 6, 7, 8}, {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}}, {1, 2, 3}, {},
                    "strip");
}

std::vector<PointState> states_of(const std::vector<S>& kinds) {
  std::vector<PointState> states(kinds.size());
  for (size_t i = 0; i < kinds.size(); ++i) {
    states[i].stick_slip = kinds[i];
    states[i].gap = kinds[i] == S::open ? 1 : -1;
  }
  return states;
}

std::vector<Vec2> along_x(size_t n) {
  std::vector<Vec2> X;
  for (size_t i = 0; i < n; ++i) X.emplace_back(0.5 * static_cast<double>(i), 0);
  return X;
}

TEST(StickSlip, TransitionsLieBetweenNeighboursOfDifferentState) {
  const auto m = strip();
  const int e01 = m.find_edge(0, 1), e12 = m.find_edge(1, 2), e23 = m.find_edge(2, 3);
  // two points per edge, along the chain
  const auto order = boundary_order(m, {e01, e01, e12, e12, e23, e23});
  EXPECT_EQ(order.follows, (std::vector<char>{0, 1, 1, 1, 1, 1}));
  EXPECT_FALSE(order.closed);
  const auto t = stick_slip_transitions(states_of({S::slip, S::stick, S::stick, S::stick, S::slip, S::slip}),
                                        along_x(6), order);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_DOUBLE_EQ(t[0].x(), 0.25);  // between points 0 and 1
  EXPECT_DOUBLE_EQ(t[1].x(), 1.75);  // between points 3 and 4
}

TEST(StickSlip, NoTransitionAcrossPointsWithoutFrictionState) {
  const auto m = strip();
  const int e01 = m.find_edge(0, 1), e12 = m.find_edge(1, 2);
  const auto order = boundary_order(m, {e01, e01, e01, e12, e12});
  // stick, open, slip: two zones, no transition; stick, contact (not anchored yet), slip: neither
  auto states = states_of({S::stick, S::open, S::slip, S::open, S::stick});
  states[3].gap = -1;  // in contact, without a friction state
  EXPECT_TRUE(stick_slip_transitions(states, along_x(5), order).empty());
}

TEST(StickSlip, NoTransitionAcrossTheStartOfAnotherChain) {
  const auto m = strip();
  const int e01 = m.find_edge(0, 1), e23 = m.find_edge(2, 3);  // two chains: 1-2 is left out
  const auto order = boundary_order(m, {e01, e01, e23, e23});
  EXPECT_EQ(order.follows, (std::vector<char>{0, 1, 0, 1}));
  EXPECT_TRUE(stick_slip_transitions(states_of({S::stick, S::stick, S::slip, S::slip}), along_x(4), order).empty());
}

TEST(StickSlip, AClosedBoundaryWrapsAround) {
  // the boundary of one square, its four edges in a loop: the last point follows the first
  const mesh::Mesh m({Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}, {1, 2, 3, 4}, {{0, 1, 2, 3}}, {1}, {},
                     "square");
  const std::vector<int> loop = {m.find_edge(0, 1), m.find_edge(1, 2), m.find_edge(2, 3), m.find_edge(3, 0)};
  const auto order = boundary_order(m, loop);
  EXPECT_TRUE(order.closed);
  const auto t = stick_slip_transitions(states_of({S::slip, S::stick, S::stick, S::stick}),
                                        {Vec2(0.5, 0), Vec2(1, 0.5), Vec2(0.5, 1), Vec2(0, 0.5)}, order);
  ASSERT_EQ(t.size(), 2u);  // 0-1 and, around the loop, 3-0
  EXPECT_DOUBLE_EQ(t[1].x(), 0.25);
  EXPECT_DOUBLE_EQ(t[1].y(), 0.25);
  // an open chain of the first three edges does not wrap
  EXPECT_FALSE(boundary_order(m, {loop[0], loop[1], loop[2]}).closed);
}

}  // namespace
}  // namespace hpcontact::contact
