// Straight, circular and general parametric curves.
#include "hpcontact/geometry/curve.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "hpcontact/core/error.hpp"

namespace hpcontact::geometry {

namespace {

/// Reversal of any curve by the parameter change s -> 1 - s.
class ReversedCurve final : public Curve {
public:
  explicit ReversedCurve(std::shared_ptr<const Curve> base) : base_(std::move(base)) {}
  Vec2 point(double s) const override { return base_->point(1.0 - s); }
  Vec2 tangent(double s) const override { return -base_->tangent(1.0 - s); }
  Vec2 second_derivative(double s) const override { return base_->second_derivative(1.0 - s); }
  std::string describe() const override { return "reversed " + base_->describe(); }

private:
  std::shared_ptr<const Curve> base_;
};

}  // namespace

std::shared_ptr<const Curve> Curve::reversed() const {
  return std::make_shared<ReversedCurve>(shared_from_this());
}

double Curve::length() const {
  // 20-point Gauss–Legendre on [0, 1]; enough for the smooth curves used as element edges.
  static const double xg[10] = {0.0765265211334973, 0.2277858511416451, 0.3737060887154195,
                                0.5108670019508271, 0.6360536807265150, 0.7463319064601508,
                                0.8391169718222188, 0.9122344282513259, 0.9639719272779138,
                                0.9931285991850949};
  static const double wg[10] = {0.1527533871307258, 0.1491729864726037, 0.1420961093183820,
                                0.1316886384491766, 0.1181945319615184, 0.1019301198172404,
                                0.0832767415767048, 0.0626720483341091, 0.0406014298003869,
                                0.0176140071391521};
  double L = 0.0;
  for (int i = 0; i < 10; ++i)
    for (double sign : {-1.0, 1.0}) L += 0.5 * wg[i] * tangent(0.5 + 0.5 * sign * xg[i]).norm();
  return L;
}

std::string LineSegment::describe() const {
  std::ostringstream os;
  os << "line((" << a_.x() << "," << a_.y() << ")-(" << b_.x() << "," << b_.y() << "))";
  return os.str();
}

std::shared_ptr<const Curve> LineSegment::reversed() const {
  return std::make_shared<LineSegment>(b_, a_);
}

Vec2 CircularArc::point(double s) const {
  const double t = t0_ + s * (t1_ - t0_);
  return c_ + r_ * Vec2(std::cos(t), std::sin(t));
}

Vec2 CircularArc::tangent(double s) const {
  const double t = t0_ + s * (t1_ - t0_);
  return r_ * (t1_ - t0_) * Vec2(-std::sin(t), std::cos(t));
}

Vec2 CircularArc::second_derivative(double s) const {
  const double t = t0_ + s * (t1_ - t0_);
  const double d = t1_ - t0_;
  return -r_ * d * d * Vec2(std::cos(t), std::sin(t));
}

std::string CircularArc::describe() const {
  std::ostringstream os;
  os << "arc(center=(" << c_.x() << "," << c_.y() << "), radius=" << r_ << ")";
  return os.str();
}

std::shared_ptr<const Curve> CircularArc::reversed() const {
  return std::make_shared<CircularArc>(c_, r_, t1_, t0_);
}

std::shared_ptr<CircularArc> arc_through(Vec2 a, Vec2 b, Vec2 center, double radius, int ccw,
                                         const std::string& what, double tol) {
  HPC_REQUIRE(radius > 0.0, InputError, what, ": radius must be > 0 (got ", radius, ")");
  const double ra = (a - center).norm(), rb = (b - center).norm();
  HPC_REQUIRE(std::abs(ra - radius) <= tol * radius, InputError, what, ": end point (", a.x(), ", ",
              a.y(), ") is at distance ", ra, " from the centre, not on the circle of radius ",
              radius);
  HPC_REQUIRE(std::abs(rb - radius) <= tol * radius, InputError, what, ": end point (", b.x(), ", ",
              b.y(), ") is at distance ", rb, " from the centre, not on the circle of radius ",
              radius);
  const double ta = std::atan2(a.y() - center.y(), a.x() - center.x());
  double tb = std::atan2(b.y() - center.y(), b.x() - center.x());
  const double pi = std::numbers::pi;
  double d = tb - ta;  // in (-2π, 2π)
  if (ccw > 0) {
    while (d <= 0) d += 2 * pi;
  } else if (ccw < 0) {
    while (d >= 0) d -= 2 * pi;
  } else {
    while (d > pi) d -= 2 * pi;
    while (d < -pi) d += 2 * pi;
    HPC_REQUIRE(std::abs(std::abs(d) - pi) > 1e-9, InputError, what,
                ": the end points are diametrically opposite; give the direction (ccw: true/false)");
  }
  HPC_REQUIRE(std::abs(d) > 1e-12, InputError, what, ": the arc has zero length");
  return std::make_shared<CircularArc>(center, radius, ta, ta + d);
}

FunctionCurve::FunctionCurve(Fn x, Fn dx, std::string description)
    : x_(std::move(x)), dx_(std::move(dx)), description_(std::move(description)) {}

Vec2 FunctionCurve::tangent(double s) const {
  if (dx_) return dx_(s);
  const double h = 1e-6;
  return (x_(s + h) - x_(s - h)) / (2 * h);
}

Vec2 FunctionCurve::second_derivative(double s) const {
  const double h = 1e-4;
  return (tangent(s + h) - tangent(s - h)) / (2 * h);
}

}  // namespace hpcontact::geometry
