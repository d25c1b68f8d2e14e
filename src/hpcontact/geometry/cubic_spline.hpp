// A smooth planar curve through given points: the natural cubic spline, parametrised by the
// chord length, continued by straight lines beyond its ends; and the closest point on it.
#pragma once

#include <vector>

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::geometry {

/// x(t) through the points P_0 … P_n (n ≥ 1) at the knots t_i = Σ |P_k+1 − P_k| (chord
/// length), cubic on each [t_i, t_i+1], twice continuously differentiable, with x'' = 0 at both
/// ends (natural). For t < 0 and t > t_n the curve goes on along its end tangents, so that it
/// is C² on the whole real line and every point of the plane has a closest point on it.
class CubicSpline {
public:
  /// Throws InputError if fewer than two points are given or two consecutive ones coincide.
  explicit CubicSpline(std::vector<Vec2> points);

  Vec2 point(double t) const;
  Vec2 derivative(double t) const;         ///< dx/dt (unit length at the knots' chords' scale)
  Vec2 second_derivative(double t) const;  ///< d²x/dt²
  double end() const { return knots_.back(); }  ///< t_n, the parameter of the last point
  const std::vector<Vec2>& points() const { return points_; }

  /// The parameter of the point of the curve (extensions included) nearest to x: on every
  /// segment that may hold it, each local minimum of the distance sampled along the segment
  /// is refined by safeguarded Newton iterations; the nearest one is kept.
  double closest_parameter(const Vec2& x) const;

private:
  int segment(double t) const;  ///< i with t in [t_i, t_i+1], clamped to [0, n−1]

  std::vector<Vec2> points_;
  std::vector<double> knots_;
  std::vector<Vec2> moments_;  ///< x''(t_i)
  // Each segment lies in the disc (centre, radius): segments that cannot hold the closest
  // point are skipped by the search.
  std::vector<Vec2> centres_;
  std::vector<double> radii_;
};

}  // namespace hpcontact::geometry
