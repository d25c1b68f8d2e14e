// The exact curve a boundary node slides along when rp relocates it (seed §4.8).
#pragma once

#include <string>

#include "hpcontact/geometry/vec2.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::adapt {

/// A boundary node of a body whose two boundary edges lie on one circle or one straight line:
/// it can move along that curve between its two boundary neighbours and the geometry stays
/// exact (the arcs are given by centre and radius, so they follow the node). The track is
/// parametrised by the angle about the centre (circle) or the coordinate along the line,
/// increasing from the `lower` neighbour towards the `upper` one.
class BoundaryTrack {
public:
  /// The track of node `node_id` (user id) of body `body`; AdaptError saying why when the node
  /// is not on the boundary, sits at a corner, or lies on a parametric curve.
  BoundaryTrack(const model::ProblemSpec& spec, int body, int node_id);

  double parameter(const Vec2& X) const;  ///< of the point of the curve nearest to X
  Vec2 point(double s) const;             ///< on the exact curve
  double node() const { return s_node_; }  ///< the node's own parameter
  double lower() const { return s_lower_; }
  double upper() const { return s_upper_; }
  /// Whether the node can move to s: strictly between its neighbours, by 1 % of the track.
  bool reaches(double s) const {
    const double margin = 0.01 * (s_upper_ - s_lower_);
    return s > s_lower_ + margin && s < s_upper_ - margin;
  }
  /// Whether X lies on the curve (to 1e-6 of the track's chord) at a parameter the node reaches.
  bool reaches(const Vec2& X) const {
    const double s = parameter(X), chord = (point(s_upper_) - point(s_lower_)).norm();
    return reaches(s) && (point(s) - X).norm() <= 1e-6 * chord;
  }
  int node_id() const { return node_id_; }
  int body() const { return body_; }
  /// "circle (centre, radius)" or "line".
  std::string describe() const;

private:
  int body_, node_id_;
  bool circle_ = false;
  Vec2 center_ = Vec2::Zero();  ///< circle centre, or the node on a line
  Vec2 axis_ = Vec2(1, 0);      ///< circle: direction to the node; line: unit direction
  double radius_ = 0;
  double s_node_ = 0, s_lower_ = 0, s_upper_ = 0;
};

/// Moves node `node_id` of body `body` to parameter s of its track. If an element would be
/// invalid (det J <= 0 anywhere), the interior nodes joined to it by an element edge follow half
/// and then all of its displacement; AdaptError when none of these gives a valid mesh, or when s
/// is not strictly between the node's boundary neighbours.
model::ProblemSpec with_node_moved(const model::ProblemSpec& spec, const BoundaryTrack& track,
                                   double s);

/// Position of node `id` (user id) of a body.
Vec2 node_position(const model::BodySpec& body, int id);

}  // namespace hpcontact::adapt
