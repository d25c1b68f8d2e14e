// A profile's faults, each naming the key and the point or fillet at fault, and its pieces:
// fillets' arcs tangent to their segments, segments shortened by them.
#include "hpcontact/geometry/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hpcontact/core/error.hpp"

using hpcontact::Vec2;
using namespace hpcontact::geometry;

namespace {

/// The fault of a spec as "key[index]: cause" ("key: cause" for the list as a whole), or "".
std::string fault(const ProfileSpec& spec) {
  const auto f = profile_fault(spec);
  if (!f) return "";
  return f->key + (f->index >= 0 ? "[" + std::to_string(f->index) + "]" : "") + ": " + f->cause;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// Too few points, a repeated point (closed: the first repeated at the end) shall be refused,
// naming the point.
TEST(ProfileFault, TooFewAndRepeatedPoints) {
  EXPECT_TRUE(has(fault({{Vec2(0, 0)}, {}, false}), "points: an open profile needs at least 2 points (got 1)"));
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(1, 0)}, {}, true}), "a closed profile needs at least 3"));
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(2, 1)}, {}, false}),
                  "points[2]: repeats the point before it, points[1]"));
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 0)}, {}, true}),
                  "points[3]: repeats points[0]"));
  EXPECT_EQ(fault({{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1)}, {}, true}), "");
  EXPECT_THROW(Profile({{Vec2(0, 0)}, {}, false}), hpcontact::InputError);
}

// A chain that turns back at a point, or whose segments or continuations cross or touch, shall
// be refused naming the later of the two.
TEST(ProfileFault, SelfIntersections) {
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(2, 0), Vec2(1, 0)}, {}, false}),
                  "points[1]: the chain turns back on itself at points[1]"));
  // A bow tie: its third segment crosses its first.
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(2, 2), Vec2(2, 0), Vec2(0, 2)}, {}, true}),
                  "points[2]: the chain crosses itself: the segment points[2]–points[3] meets the "
                  "segment points[0]–points[1]"));
  // A point on an earlier segment (touching).
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(4, 0), Vec2(4, 2), Vec2(2, 2), Vec2(2, 0)}, {}, false}),
                  "points[3]: the chain crosses itself: the segment points[3]–points[4] meets"));
  // The continuation after the last point runs into the first segment.
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(4, 0), Vec2(4, 2), Vec2(2, 2), Vec2(2, 1)}, {}, false}),
                  "points[4]: the chain crosses itself: the continuation after points[4] meets the "
                  "segment points[0]–points[1]"));
  // A groove (its continuations parallel) is fine.
  EXPECT_EQ(fault({{Vec2(-1, 3), Vec2(-1, 0), Vec2(1, 0), Vec2(1, 3)}, {}, false}), "");
}

// Fillets: one per corner, >= 0, and fitting on their segments, else refused naming the fillet
// and the points.
TEST(ProfileFault, Fillets) {
  const std::vector<Vec2> groove{Vec2(-1, 3), Vec2(-1, 0), Vec2(1, 0), Vec2(1, 3)};
  EXPECT_TRUE(has(fault({groove, {0.5}, false}), "fillet: has 1 radii for the 2 corners"));
  EXPECT_TRUE(has(fault({groove, {0.5, -1}, false}), "fillet[1]: must be >= 0 (got -1)"));
  EXPECT_EQ(fault({groove, {1, 1}, false}), "");  // the bottom taken whole by two arcs
  EXPECT_TRUE(has(fault({groove, {0.5, 1.6}, false}),
                  "fillet[1]: the fillet of radius 1.6 at points[2] needs 1.6 of the segment "
                  "points[1]–points[2] (length 2), of which the fillet at points[1] takes 0.5"));
  // A closed triangle: every point a corner.
  EXPECT_TRUE(has(fault({{Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}, {0, 0}, true}), "for the 3 corners"));
}

// A fillet shall be the arc of its radius tangent to both segments at r tan(|θ|/2) from the
// corner, turning by the corner's angle, the segments shortened to the tangent points.
TEST(Profile, FilletArcTouchesBothSegments) {
  // A corner of 60° turn to the left at (2, 0), radius 3: tangent length 3 tan 30°.
  const Vec2 corner(2, 0), after(std::cos(M_PI / 3), std::sin(M_PI / 3));
  const Profile p({{Vec2(-4, 0), corner, corner + 8 * after}, {3}, false});
  ASSERT_EQ(p.pieces().size(), 3u);
  const auto& arc = p.pieces()[1];
  const double t = 3 * std::tan(M_PI / 6);
  EXPECT_TRUE(arc.arc);
  EXPECT_NEAR(arc.turn, M_PI / 3, 1e-15);
  EXPECT_LT((arc.start - (corner - Vec2(t, 0))).norm(), 1e-14);
  EXPECT_LT((arc.end - (corner + t * after)).norm(), 1e-14);
  EXPECT_NEAR((arc.start - arc.centre).norm(), 3, 1e-14);
  EXPECT_NEAR((arc.end - arc.centre).norm(), 3, 1e-14);
  EXPECT_NEAR((arc.start - arc.centre).dot(Vec2(1, 0)), 0, 1e-14);  // tangent to the first side
  EXPECT_NEAR((arc.end - arc.centre).dot(after), 0, 1e-14);          // and to the second
  EXPECT_LT((p.pieces()[0].end - arc.start).norm(), 1e-15);
  EXPECT_LT((p.pieces()[2].start - arc.end).norm(), 1e-15);
  EXPECT_TRUE(p.pieces()[0].open_before && p.pieces()[2].open_after);
}
