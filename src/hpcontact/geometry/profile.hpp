// A rigid profile with corners: a chain of straight segments through given points, its corners
// sharp or rounded by circular fillets, open (continued straight beyond its ends) or closed; and
// the closest point on it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::geometry {

/// A profile as given. Its corners are the interior points of an open profile (points[1] …
/// points[n−2]) and every point of a closed one (which joins points[n−1] back to points[0]);
/// `fillets` holds one radius per corner in that order (0: sharp), or nothing (all sharp).
struct ProfileSpec {
  std::vector<Vec2> points;
  std::vector<double> fillets;
  bool closed = false;
};

/// What is wrong with a ProfileSpec: the key ("points" or "fillet"), the index in that list of
/// the entry at fault (-1: the list as a whole), and the cause, naming the points concerned.
struct ProfileFault {
  std::string key;
  int index = -1;
  std::string cause;
};

/// The first fault of `spec`, if any: fewer than 2 points (3 closed); a point that repeats the
/// one before it (closed: the last point the first); a chain that turns back on itself at a
/// point, or whose segments (and an open profile's straight continuations) cross or touch
/// where they are not neighbours; a fillet list whose length is not the number of corners, a
/// negative fillet, or fillets that do not fit on a segment (the tangent lengths r tan(|θ|/2)
/// of its two corners, θ the turn there, add up to more than its length). Fillets lie within
/// their corners: only the straight chain is checked for crossings.
std::optional<ProfileFault> profile_fault(const ProfileSpec& spec);

/// The chain of pieces a ProfileSpec makes: walking from points[0], each segment shortened by the
/// fillets at its ends, and between two segments the fillet's arc (tangent to both, radius r,
/// turning by the corner's angle θ). The side to the left walking along it is the body's.
class Profile {
public:
  /// A straight segment from `start` to `end`, or a circular arc about `centre` of `radius`
  /// turning by `turn` (radians, > 0 to the left: counter-clockwise) from `start` to `end`.
  struct Piece {
    bool arc = false;
    Vec2 start = Vec2::Zero(), end = Vec2::Zero();
    Vec2 direction = Vec2::Zero();  ///< segment: unit vector from start to end
    double length = 0;              ///< segment: |end − start|
    Vec2 centre = Vec2::Zero();     ///< arc
    double radius = 0, turn = 0;    ///< arc
    /// An open profile's first and last segments go on straight beyond its ends.
    bool open_before = false, open_after = false;
    /// At each end the sum of the unit normals (tangents turned left) of the two pieces meeting
    /// there: it points to the body's side of a sharp corner, convex or concave.
    Vec2 start_normals = Vec2::Zero(), end_normals = Vec2::Zero();
    /// Whether the chain turns at its start / end (a sharp corner), or goes on smoothly there
    /// (a fillet's tangent point, a point on a straight line, an open profile's continuation).
    bool sharp_start = false, sharp_end = false;
  };

  /// The closest point of the profile to a point: on `piece`, at a sharp corner at its start
  /// (end = 0) or its end (end = 1), or elsewhere (end = −1: inside the piece, on a segment's
  /// continuation, or at a smooth join, where the point lies on the normal both pieces share).
  struct Foot {
    Vec2 point = Vec2::Zero();
    int piece = -1;
    int end = -1;
  };

  /// Throws InputError with profile_fault's cause.
  explicit Profile(ProfileSpec spec);

  /// The nearest point of the chain (with an open profile's continuations) to x; of equally
  /// near ones the first along the chain.
  Foot closest(const Vec2& x) const;

  /// The arc length along the chain from the first piece's start to a foot (negative on an open
  /// profile's continuation before its start).
  double arc_length(const Foot& foot) const;
  /// The chain's length (a closed one's perimeter), continuations left out.
  double length() const { return starts_.back(); }

  const std::vector<Piece>& pieces() const { return pieces_; }
  const ProfileSpec& spec() const { return spec_; }

private:
  ProfileSpec spec_;
  std::vector<Piece> pieces_;
  std::vector<double> starts_;  ///< arc length at each piece's start, then the total
};

}  // namespace hpcontact::geometry
