// Parametric boundary curves x(s), s in [0, 1], that give element edges their exact shape.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::geometry {

/// A smooth curve x(s) on s in [0, 1]; x(0) is its start, x(1) its end.
class Curve : public std::enable_shared_from_this<Curve> {
public:
  virtual ~Curve() = default;
  virtual Vec2 point(double s) const = 0;
  /// dx/ds.
  virtual Vec2 tangent(double s) const = 0;
  /// d²x/ds².
  virtual Vec2 second_derivative(double s) const = 0;
  /// Short description for messages, e.g. "arc(center=(0,0), r=10)".
  virtual std::string describe() const = 0;
  /// The same point set traversed from end to start (the curve must be owned by a shared_ptr).
  virtual std::shared_ptr<const Curve> reversed() const;
  /// Length by Gauss quadrature.
  double length() const;
};

using CurvePtr = std::shared_ptr<const Curve>;

/// Straight segment from a to b.
class LineSegment final : public Curve {
public:
  LineSegment(Vec2 a, Vec2 b) : a_(a), b_(b) {}
  Vec2 point(double s) const override { return a_ + s * (b_ - a_); }
  Vec2 tangent(double) const override { return b_ - a_; }
  Vec2 second_derivative(double) const override { return Vec2::Zero(); }
  std::string describe() const override;
  std::shared_ptr<const Curve> reversed() const override;

private:
  Vec2 a_, b_;
};

/// Circular arc x(s) = c + r (cos θ(s), sin θ(s)) with θ(s) = θ0 + s (θ1 - θ0), uniform in angle.
class CircularArc final : public Curve {
public:
  CircularArc(Vec2 center, double radius, double theta0, double theta1)
      : c_(center), r_(radius), t0_(theta0), t1_(theta1) {}
  Vec2 point(double s) const override;
  Vec2 tangent(double s) const override;
  Vec2 second_derivative(double s) const override;
  std::string describe() const override;
  std::shared_ptr<const Curve> reversed() const override;
  Vec2 center() const { return c_; }
  double radius() const { return r_; }
  double theta0() const { return t0_; }
  double theta1() const { return t1_; }

private:
  Vec2 c_;
  double r_, t0_, t1_;
};

/// The shorter arc of the circle (center, radius) from a to b (both must lie on the circle to
/// within tol·radius, else InputError naming `what`). A half circle needs an explicit direction:
/// ccw = +1 (counter-clockwise), -1 (clockwise), 0 (shorter arc; error if ambiguous).
std::shared_ptr<CircularArc> arc_through(Vec2 a, Vec2 b, Vec2 center, double radius, int ccw,
                                         const std::string& what, double tol = 1e-6);

/// A general curve given by functions; the derivatives default to central differences.
class FunctionCurve final : public Curve {
public:
  using Fn = std::function<Vec2(double)>;
  FunctionCurve(Fn x, Fn dx, std::string description);
  Vec2 point(double s) const override { return x_(s); }
  Vec2 tangent(double s) const override;
  Vec2 second_derivative(double s) const override;
  std::string describe() const override { return description_; }

private:
  Fn x_, dx_;
  std::string description_;
};

}  // namespace hpcontact::geometry
