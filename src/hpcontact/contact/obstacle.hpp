// Rigid obstacles: a signed gap and its outward normal at any point of the plane.
#pragma once

#include <memory>
#include <string>

#include "hpcontact/geometry/cubic_spline.hpp"
#include "hpcontact/geometry/profile.hpp"
#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::contact {

/// A rigid body seen from a deformable one: gap(x) > 0 outside it, < 0 when x penetrates.
class Obstacle {
public:
  virtual ~Obstacle() = default;
  /// Signed normal gap g_N of point x (seed eq. 3.7 with the obstacle as body 1), its outward
  /// unit normal n at the closest point, and dn/dx (for the consistent tangent).
  virtual double gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const = 0;
  virtual std::string describe() const = 0;
  /// How far the obstacle has moved (a displaced obstacle): anchors of friction on it are kept
  /// in its own frame and moved by this.
  virtual Vec2 offset() const { return Vec2::Zero(); }
};

using ObstaclePtr = std::shared_ptr<const Obstacle>;

/// A rigid obstacle moved by a prescribed displacement d scaled by the load factor λ, like the
/// prescribed displacements of the bodies: gap(x) = gap₀(x − λ d) (a translation keeps n, dn/dx).
class DisplacedObstacle final : public Obstacle {
public:
  DisplacedObstacle(ObstaclePtr base, Vec2 displacement);
  void set_load_factor(double lambda) { factors_ = Vec2(lambda, lambda); }
  /// Separate factors on the displacement's x and y components (a load stage per direction).
  void set_load_factors(const Vec2& factors) { factors_ = factors; }
  double gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const override;
  std::string describe() const override;
  Vec2 offset() const override { return factors_.cwiseProduct(d_); }
  /// The displacement per unit load factor.
  Vec2 direction() const { return d_; }

private:
  ObstaclePtr base_;
  Vec2 d_;
  Vec2 factors_ = Vec2(1, 1);
};

/// Half-plane {(x - point)·normal < 0}; the body lies on the side the normal points to.
class RigidPlane final : public Obstacle {
public:
  RigidPlane(Vec2 point, Vec2 normal);
  double gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const override;
  std::string describe() const override;

private:
  Vec2 p_, n_;
};

/// Rigid disc of radius r (the body outside it), or, with `inside`, a rigid circular hole the
/// body lies within.
class RigidCircle final : public Obstacle {
public:
  RigidCircle(Vec2 center, double radius, bool inside);
  double gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const override;
  std::string describe() const override;

private:
  Vec2 c_;
  double r_;
  bool inside_;
};

/// A rigid obstacle bounded by a smooth curve through given points (geometry::CubicSpline: the
/// natural cubic spline, straight beyond its ends). The body lies to the left of the curve
/// walking from its first point to its last, the side its normal (−x'_y, x'_x)/|x'| points to.
/// The gap is the signed distance to the closest point of the curve.
class RigidCurve final : public Obstacle {
public:
  explicit RigidCurve(std::vector<Vec2> points);
  double gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const override;
  std::string describe() const override;
  const geometry::CubicSpline& spline() const { return spline_; }

private:
  geometry::CubicSpline spline_;
};

/// A rigid obstacle bounded by a profile with corners (geometry::Profile: segments and fillet
/// arcs, open or closed), the body on its left walking along it. The gap is the signed distance
/// to the closest point of the chain: on a segment (x − a)·n with n its normal; on an arc that of
/// its circle; at a corner v that x sees from its fan of normals, s |x − v| with
/// n = s (x − v)/|x − v|, which turns with x: dn/dx = s (I − n nᵀ)/|x − v| (s = +1 outside the
/// obstacle, at a convex corner of it; −1 inside, at a concave one). Where two segments of a
/// concave corner are equally near (on its bisector) the first along the chain is taken.
class RigidProfile final : public Obstacle {
public:
  explicit RigidProfile(geometry::ProfileSpec spec);
  double gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const override;
  std::string describe() const override;
  const geometry::Profile& profile() const { return profile_; }

private:
  geometry::Profile profile_;
};

}  // namespace hpcontact::contact
