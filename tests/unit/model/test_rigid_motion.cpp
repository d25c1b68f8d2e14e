// Rigid-body motions left free by prescribed displacement components: each case has a motion
// that can be checked by hand (u = (a - θ(y - y0), b + θ(x - x0)) vanishing at the constraints).
#include "hpcontact/model/rigid_motion.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using hpcontact::Vec2;
using hpcontact::model::free_rigid_motions;
using hpcontact::model::PointConstraint;

using Motions = std::vector<std::string>;

TEST(RigidMotion, NothingPrescribedLeavesEveryMotion) {
  EXPECT_EQ(free_rigid_motions({}, 1.0), Motions{"every rigid-body motion (nothing is prescribed)"});
}

TEST(RigidMotion, PinnedPointLeavesTheRotationAboutIt) {
  EXPECT_EQ(free_rigid_motions({{Vec2(2, 3), 0}, {Vec2(2, 3), 1}}, 10.0),
            Motions{"rotation about (2, 3)"});
}

TEST(RigidMotion, RollerAlongAVerticalLineLeavesTheVerticalTranslation) {
  // ux = 0 on the edge x = 0 (both ends): no x translation, no rotation.
  EXPECT_EQ(free_rigid_motions({{Vec2(0, 0), 0}, {Vec2(0, 4), 0}}, 5.0),
            Motions{"translation in y"});
  EXPECT_EQ(free_rigid_motions({{Vec2(0, 0), 1}, {Vec2(3, 0), 1}}, 5.0),
            Motions{"translation in x"});
}

TEST(RigidMotion, TwoComponentsAtTwoPointsLeaveARotationAboutTheirCrossing) {
  // ux at (0, 0) and uy at (1, 1): the rotation about (1, 0) moves neither.
  EXPECT_EQ(free_rigid_motions({{Vec2(0, 0), 0}, {Vec2(1, 1), 1}}, 2.0),
            Motions{"rotation about (1, 0)"});
}

TEST(RigidMotion, OneComponentLeavesATranslationAndARotation) {
  EXPECT_EQ(free_rigid_motions({{Vec2(1, 1), 0}}, 2.0), (Motions{"translation in y", "rotation"}));
}

TEST(RigidMotion, StaticallyDeterminateSupportHoldsTheBody) {
  // Pin at (0, 0), roller uy at (10, 0): the usual simply supported beam.
  EXPECT_TRUE(free_rigid_motions({{Vec2(0, 0), 0}, {Vec2(0, 0), 1}, {Vec2(10, 0), 1}}, 10.0).empty());
  // Far from the origin and tiny: the test is relative to the body's size.
  const Vec2 o(1e6, -2e6);
  EXPECT_TRUE(free_rigid_motions({{o, 0}, {o, 1}, {o + Vec2(1e-3, 0), 1}}, 1e-3).empty());
}

TEST(RigidMotion, ParallelRollersDoNotStopTheTranslationAlongThem) {
  // uy at three points on the line y = 2: the x translation stays free, the rotation does not.
  EXPECT_EQ(free_rigid_motions({{Vec2(0, 2), 1}, {Vec2(1, 2), 1}, {Vec2(5, 2), 1}}, 5.0),
            Motions{"translation in x"});
}
