// Lines, circles and body boundaries as the frames contact results are reported in.
#include "hpcontact/contact/surface_frame.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include <Eigen/Dense>

#include "hpcontact/basis/quadrature.hpp"

namespace hpcontact::contact {

namespace {

class LineFrame final : public SurfaceFrame {
public:
  LineFrame(const Vec2& origin, const Vec2& tangent, const Vec2& normal)
      : o_(origin), t_(tangent.normalized()),
        n_(normal.norm() > 0 ? Vec2(normal.normalized()) : Vec2(-t_.y(), t_.x())) {}
  double coordinate(const Vec2& X) const override { return (X - o_).dot(t_); }
  double rate(const Vec2&, const Vec2& dX) const override { return t_.dot(dX); }
  Vec2 normal(const Vec2&) const override { return n_; }
  bool straight() const override { return true; }
  std::string describe() const override {
    std::ostringstream os;
    os << "line through (" << o_.x() + 0.0 << ", " << o_.y() + 0.0 << ") along (" << t_.x() + 0.0
       << ", " << t_.y() + 0.0 << ")";  // + 0.0: no "-0"
    return os.str();
  }

private:
  Vec2 o_, t_, n_;
};

/// φ − φ₀ wrapped into (−π, π].
double wrapped(double a) {
  constexpr double pi = std::numbers::pi;
  while (a <= -pi) a += 2 * pi;
  while (a > pi) a -= 2 * pi;
  return a;
}

class ArcFrame final : public SurfaceFrame {
public:
  ArcFrame(const Vec2& centre, double radius, const Vec2& origin, bool concave)
      : c_(centre), r_(radius), concave_(concave),
        phi0_(std::atan2(origin.y() - centre.y(), origin.x() - centre.x())) {}
  double coordinate(const Vec2& X) const override {
    return r_ * wrapped(std::atan2(X.y() - c_.y(), X.x() - c_.x()) - phi0_);
  }
  // dφ = (e_φ · dX) / |X − c|, e_φ the unit vector of increasing φ
  double rate(const Vec2& X, const Vec2& dX) const override {
    const Vec2 d = X - c_;
    return r_ * Vec2(-d.y(), d.x()).dot(dX) / d.squaredNorm();
  }
  Vec2 normal(const Vec2& X) const override {
    const Vec2 radial = (X - c_).normalized();
    return concave_ ? Vec2(-radial) : radial;
  }
  std::optional<double> angle(const Vec2& X) const override {
    return std::atan2(X.y() - c_.y(), X.x() - c_.x()) * 180 / std::numbers::pi;
  }
  std::optional<std::pair<Vec2, double>> circle() const override { return std::make_pair(c_, r_); }
  std::string describe() const override {
    std::ostringstream os;
    os << "circle about (" << c_.x() + 0.0 << ", " << c_.y() + 0.0 << ") of radius " << r_;
    return os.str();
  }

private:
  Vec2 c_;
  double r_;
  bool concave_;
  double phi0_;
};

class ProfileFrame final : public SurfaceFrame {
public:
  ProfileFrame(std::shared_ptr<const RigidProfile> profile, const Vec2& origin)
      : profile_(std::move(profile)), s0_(arc_length(origin)) {}
  double coordinate(const Vec2& X) const override {
    const double s = arc_length(X) - s0_;
    if (!profile_->profile().spec().closed) return s;
    const double perimeter = profile_->profile().length();
    return s - perimeter * std::ceil(s / perimeter - 0.5);  // into (−L/2, L/2]
  }
  double rate(const Vec2& X, const Vec2& dX) const override {
    const auto& chain = profile_->profile();
    const auto foot = chain.closest(X);
    const auto& piece = chain.pieces()[foot.piece];
    if (foot.end >= 0) {  // a sharp corner: along the parallel curve through X
      const Vec2 n = normal(X);
      return Vec2(n.y(), -n.x()).dot(dX);
    }
    if (!piece.arc) return piece.direction.dot(dX);
    // s = r |φ − φ_start| grows with φ where the arc turns left: ds = ±r (e_φ·dX)/|X − c|.
    const Vec2 d = X - piece.centre;
    const double sign = piece.turn > 0 ? 1.0 : -1.0;
    return sign * piece.radius * Vec2(-d.y(), d.x()).dot(dX) / d.squaredNorm();
  }
  Vec2 normal(const Vec2& X) const override {
    Vec2 n;
    profile_->gap(X, &n, nullptr);
    return n;
  }
  std::string describe() const override { return profile_->describe(); }

private:
  double arc_length(const Vec2& X) const {
    return profile_->profile().arc_length(profile_->profile().closest(X));
  }
  std::shared_ptr<const RigidProfile> profile_;
  double s0_;
};

class BoundaryFrame final : public SurfaceFrame {
public:
  explicit BoundaryFrame(std::shared_ptr<const DeformableBoundary> b) : b_(std::move(b)) {
    // the arc length at the start of each edge (Gauss–Legendre of |dX/dt|, 24 points per edge)
    const auto& rule = basis::gauss_legendre(24);
    start_.push_back(0);
    BoundaryPoint bp;
    for (int k = 0; k < b_->n_edges(); ++k) {
      double length = 0;
      for (int i = 0; i < rule.size(); ++i) {
        b_->evaluate(k, rule.points[i], bp);
        length += rule.weights[i] * bp.dx_dt.norm();
      }
      start_.push_back(start_.back() + length);
    }
  }
  double coordinate(const Vec2& X) const override {
    BoundaryPoint foot;
    if (b_->project(X, foot)) return start_[foot.edge] + length_to(foot.edge, foot.t);
    // beyond a free end: along the end's tangent
    BoundaryPoint a, e;
    b_->evaluate(0, -1, a);
    b_->evaluate(b_->n_edges() - 1, 1, e);
    const double to_start = (X - a.x).norm(), to_end = (X - e.x).norm();
    return to_start < to_end ? (X - a.x).dot(a.dx_dt.normalized())
                             : start_.back() + (X - e.x).dot(e.dx_dt.normalized());
  }
  // by central differences of the exact coordinate (its foot's arc length)
  double rate(const Vec2& X, const Vec2& dX) const override {
    const double h = 1e-7 * (start_.back() > 0 ? start_.back() : 1.0) / std::max(dX.norm(), 1e-300);
    return (coordinate(X + h * dX) - coordinate(X - h * dX)) / (2 * h);
  }
  Vec2 normal(const Vec2& X) const override {
    BoundaryPoint foot;
    if (b_->project(X, foot)) return foot.normal;
    return Vec2::Zero();
  }
  std::string describe() const override { return "the undeformed contact boundary of the other body"; }

private:
  /// Arc length along edge k from t = −1 to t.
  double length_to(int k, double t) const {
    const auto& rule = basis::gauss_legendre(24);
    double length = 0;
    BoundaryPoint bp;
    for (int i = 0; i < rule.size(); ++i) {
      const double r = -1 + 0.5 * (t + 1) * (rule.points[i] + 1);
      b_->evaluate(k, r, bp);
      length += 0.5 * (t + 1) * rule.weights[i] * bp.dx_dt.norm();
    }
    return length;
  }
  std::shared_ptr<const DeformableBoundary> b_;
  std::vector<double> start_;
};

/// Points along the boundary's edges: 8 per edge and its end.
std::vector<Vec2> samples(const DeformableBoundary& b) {
  std::vector<Vec2> pts;
  for (int k = 0; k < b.n_edges(); ++k)
    for (int i = 0; i < 8; ++i) pts.push_back(b.undeformed(k, -1 + i / 4.0));
  pts.push_back(b.undeformed(b.n_edges() - 1, 1));
  return pts;
}

/// The circle through the points by algebraic least squares (x² + y² + D x + E y + F = 0).
std::optional<std::pair<Vec2, double>> fitted_circle(const std::vector<Vec2>& pts) {
  Eigen::MatrixXd A(pts.size(), 3);
  Eigen::VectorXd rhs(pts.size());
  for (size_t i = 0; i < pts.size(); ++i) {
    A.row(i) << pts[i].x(), pts[i].y(), 1;
    rhs(i) = -pts[i].squaredNorm();
  }
  const Eigen::Vector3d s = A.colPivHouseholderQr().solve(rhs);
  const Vec2 c(-s(0) / 2, -s(1) / 2);
  const double r2 = c.squaredNorm() - s(2);
  if (!(r2 > 0) || !std::isfinite(r2)) return std::nullopt;
  return std::make_pair(c, std::sqrt(r2));
}

}  // namespace

bool conforming(const std::pair<Vec2, double>& a, const std::pair<Vec2, double>& b) {
  const double r = std::max(a.second, b.second);
  return (a.first - b.first).norm() <= 0.1 * r && std::abs(a.second - b.second) <= 0.1 * r;
}

SurfaceFramePtr line_frame(const Vec2& origin, const Vec2& tangent, const Vec2& normal) {
  return std::make_shared<LineFrame>(origin, tangent, normal);
}

SurfaceFramePtr arc_frame(const Vec2& centre, double radius, const Vec2& origin, bool concave) {
  return std::make_shared<ArcFrame>(centre, radius, origin, concave);
}

SurfaceFramePtr profile_frame(std::shared_ptr<const RigidProfile> profile, const Vec2& origin) {
  return std::make_shared<ProfileFrame>(std::move(profile), origin);
}

SurfaceFramePtr boundary_frame(std::shared_ptr<const DeformableBoundary> boundary) {
  return std::make_shared<BoundaryFrame>(std::move(boundary));
}

SurfaceFramePtr surface_of(std::shared_ptr<const DeformableBoundary> boundary, const Vec2& origin) {
  const auto pts = samples(*boundary);
  const Vec2 a = pts.front(), b = pts.back();
  double length = 0;
  for (size_t i = 1; i < pts.size(); ++i) length += (pts[i] - pts[i - 1]).norm();
  const double tol = 1e-9 * length;
  BoundaryPoint start;
  boundary->evaluate(0, -1, start);
  // a line: every sample on the chord through the ends
  const Vec2 t = (b - a).normalized();
  bool straight = (b - a).norm() > 0;
  for (const Vec2& p : pts) straight = straight && std::abs((p - a).x() * t.y() - (p - a).y() * t.x()) <= tol;
  if (straight) {
    // along +x (+y for a line along y), the normal the boundary's outward one
    const Vec2 along = t.x() < -1e-12 || (std::abs(t.x()) <= 1e-12 && t.y() < 0) ? Vec2(-t) : t;
    return line_frame(a + (origin - a).dot(along) * along, along, start.normal);
  }
  if (const auto circle = fitted_circle(pts)) {
    const auto [c, r] = *circle;
    bool round = true;
    for (const Vec2& p : pts) round = round && std::abs((p - c).norm() - r) <= tol;
    if (round) {
      const bool concave = start.normal.dot(start.x - c) < 0;  // the normal points to the centre
      // the origin's angle: of `origin`, or of the boundary's middle where origin is the centre
      const Vec2 at = (origin - c).norm() > tol ? origin : pts[pts.size() / 2];
      return arc_frame(c, r, at, concave);
    }
  }
  return boundary_frame(std::move(boundary));
}

}  // namespace hpcontact::contact
