// Positions along the surface two bodies meet on: the arc length of a point's foot on the
// contact pair's obstacle surface (a line, a circle, another body's undeformed boundary), the
// frame a pair's pressures, zone ends and extent are reported in.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hpcontact/contact/deformable_boundary.hpp"
#include "hpcontact/contact/obstacle.hpp"
#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::contact {

/// The surface a contact pair's points are reported along. coordinate(X) is the arc length
/// along the surface from the frame's origin to the foot of X (the closest point of the
/// surface); rate(X, dX) its derivative along dX, so that a traction per unit length of the
/// body's own boundary times 1 / rate(X, T) (T the boundary's unit tangent) is the traction per
/// unit length of the surface: the contact pressure whatever the surface's shape.
class SurfaceFrame {
public:
  virtual ~SurfaceFrame() = default;
  /// Arc length along the surface from the origin to the foot of X (signed).
  virtual double coordinate(const Vec2& X) const = 0;
  /// d coordinate(X + h dX) / dh at h = 0.
  virtual double rate(const Vec2& X, const Vec2& dX) const = 0;
  /// The surface's unit normal at the foot of X, out of the obstacle (towards the body).
  virtual Vec2 normal(const Vec2& X) const = 0;
  /// A straight surface (a line): where a half width means what its name says.
  virtual bool straight() const { return false; }
  /// For a circular surface, the angle of the foot of X about the centre [degrees, atan2 of
  /// X − centre, in (−180, 180]]; none otherwise.
  virtual std::optional<double> angle(const Vec2& X) const { return std::nullopt; }
  /// A circular surface's centre and radius; none otherwise.
  virtual std::optional<std::pair<Vec2, double>> circle() const { return std::nullopt; }
  /// "line through (0, 0) along (1, 0)", "circle about (0, 0) of radius 10", ...
  virtual std::string describe() const = 0;
};
using SurfaceFramePtr = std::shared_ptr<const SurfaceFrame>;

/// The line through `origin` along `tangent`: coordinate (X − origin)·tangent, the linear
/// theory's common tangent (a plane obstacle; Hertz and Shtayerman place the pressure on it).
/// normal: `normal` (unit; the side the body is on), the tangent turned left if zero.
SurfaceFramePtr line_frame(const Vec2& origin, const Vec2& tangent, const Vec2& normal = Vec2::Zero());

/// The circle about `centre` of `radius`: coordinate radius·(φ − φ₀), φ the angle of X about the
/// centre and φ₀ that of `origin` (the branch cut opposite it); normal radial, outwards when
/// `concave` is false (the body outside the circle: a pin's surface seen by a plate, a rigid
/// cylinder), inwards when true (the body inside it: a hole, a pin's seat).
SurfaceFramePtr arc_frame(const Vec2& centre, double radius, const Vec2& origin, bool concave);

/// A rigid profile (segments, fillet arcs, corners): the arc length along it from the foot of
/// `origin` to the foot of X (a closed profile's wrapped into (−L/2, L/2], L its perimeter),
/// normal the obstacle's at X. A sharp corner has no length: points whose foot it is (in its fan
/// of normals) change their coordinate along the curve parallel to the profile through them,
/// rate = τ·dX with τ the normal turned right.
SurfaceFramePtr profile_frame(std::shared_ptr<const RigidProfile> profile, const Vec2& origin);

/// Another body's undeformed contact boundary (its chained edges): the arc length from the
/// boundary's start along its edges to the foot of X, normal the boundary's outward one. The
/// boundary's displacement must be zero (it is projected undeformed).
SurfaceFramePtr boundary_frame(std::shared_ptr<const DeformableBoundary> boundary);

/// The frame of a body's chained contact edges (undeformed, its displacement zero) seen as a
/// surface: a line if points along its edges lie on one (to 1e-9 of the boundary's length), a
/// circle if they lie on one, else the boundary itself. `origin` fixes the frame's origin (its
/// foot on a line, its angle on a circle); the normal is the boundary's outward one.
SurfaceFramePtr surface_of(std::shared_ptr<const DeformableBoundary> boundary, const Vec2& origin);

/// Whether two circles are nearly one (conforming surfaces: a pin in its hole, a shaft in a
/// hub): centres and radii within 10 % of the larger radius. Their contact zone can span any
/// arc, and positions are arc lengths along the circle; two circles that are not (a cylinder on
/// another, a ball on a flat) touch over a zone small against their radii, where the linear
/// theory's common tangent is the surface.
bool conforming(const std::pair<Vec2, double>& a, const std::pair<Vec2, double>& b);

}  // namespace hpcontact::contact
