// Gap functions of the rigid plane, circle, curve and profile.
#include "hpcontact/contact/obstacle.hpp"

#include <sstream>

#include "hpcontact/core/error.hpp"

namespace hpcontact::contact {

RigidPlane::RigidPlane(Vec2 point, Vec2 normal) : p_(point), n_(normal) {
  HPC_REQUIRE(normal.norm() > 0, InputError, "a rigid plane needs a non-zero normal");
  n_.normalize();
}

double RigidPlane::gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const {
  if (normal) *normal = n_;
  if (dnormal_dx) dnormal_dx->setZero();
  return (x - p_).dot(n_);
}

std::string RigidPlane::describe() const {
  std::ostringstream os;
  os << "plane(point=(" << p_.x() << "," << p_.y() << "), normal=(" << n_.x() << "," << n_.y()
     << "))";
  return os.str();
}

RigidCircle::RigidCircle(Vec2 center, double radius, bool inside)
    : c_(center), r_(radius), inside_(inside) {
  HPC_REQUIRE(radius > 0, InputError, "a rigid circle needs a radius > 0 (got ", radius, ")");
}

double RigidCircle::gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const {
  const Vec2 d = x - c_;
  const double r = d.norm();
  const Vec2 e = r > 0 ? Vec2(d / r) : Vec2(1, 0);
  const double s = inside_ ? -1.0 : 1.0;  // the outward normal of the obstacle
  if (normal) *normal = s * e;
  if (dnormal_dx) *dnormal_dx = r > 0 ? Mat2(s * (Mat2::Identity() - e * e.transpose()) / r) : Mat2::Zero();
  return s * (r - r_);
}

std::string RigidCircle::describe() const {
  std::ostringstream os;
  os << (inside_ ? "hole" : "disc") << "(center=(" << c_.x() << "," << c_.y() << "), radius=" << r_
     << ")";
  return os.str();
}

RigidCurve::RigidCurve(std::vector<Vec2> points) : spline_(std::move(points)) {}

double RigidCurve::gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const {
  const double t = spline_.closest_parameter(x);
  const Vec2 foot = spline_.point(t), d = spline_.derivative(t), dd = spline_.second_derivative(t);
  const double speed = d.norm();
  const Vec2 e = d / speed;
  const Vec2 n(-e.y(), e.x());
  if (normal) *normal = n;
  if (dnormal_dx) {
    // The foot moves with x as dt/dx = x' / (|x'|² + (x(t) − x)·x'') (from (x(t) − x)·x' = 0),
    // and the normal turns with t as dn/dt = R (x'' − (x''·e) e) / |x'| (R: +90°).
    const double stiffness = d.squaredNorm() + (foot - x).dot(dd);
    const Vec2 de = (dd - dd.dot(e) * e) / speed;
    const Vec2 dn(-de.y(), de.x());
    *dnormal_dx = stiffness > 0 ? Mat2(dn * d.transpose() / stiffness) : Mat2::Zero();
  }
  return (x - foot).dot(n);
}

std::string RigidCurve::describe() const {
  const auto& p = spline_.points();
  std::ostringstream os;
  os << "curve(" << p.size() << " points from (" << p.front().x() << "," << p.front().y()
     << ") to (" << p.back().x() << "," << p.back().y() << "))";
  return os.str();
}

RigidProfile::RigidProfile(geometry::ProfileSpec spec) : profile_(std::move(spec)) {}

double RigidProfile::gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const {
  const auto foot = profile_.closest(x);
  const auto& piece = profile_.pieces()[foot.piece];
  Vec2 n;
  Mat2 dn = Mat2::Zero();
  double g;
  if (foot.end < 0 && !piece.arc) {
    n = Vec2(-piece.direction.y(), piece.direction.x());
    g = (x - piece.start).dot(n);
  } else if (foot.end < 0) {
    // The arc's circle: the body inside it where the chain turns left (towards the centre).
    // (At the centre itself every point of the arc is as near: its start is taken.)
    const Vec2 v = x - piece.centre;
    const double rho = v.norm();
    const Vec2 e = rho > 0 ? Vec2(v / rho) : Vec2((piece.start - piece.centre) / piece.radius);
    const double s = piece.turn > 0 ? -1.0 : 1.0;
    n = s * e;
    g = s * (rho - piece.radius);
    if (rho > 0) dn = s * (Mat2::Identity() - e * e.transpose()) / rho;
  } else {
    // A sharp corner: the body's side is the one the sum of the two pieces' normals points to.
    const Vec2 normals = foot.end == 0 ? piece.start_normals : piece.end_normals;
    const Vec2 v = x - foot.point;
    const double d = v.norm();
    const double s = v.dot(normals) >= 0 ? 1.0 : -1.0;
    if (d > 0) {
      n = s * v / d;
      g = s * d;
      dn = s * (Mat2::Identity() - n * n.transpose()) / d;
    } else {
      n = normals.normalized();
      g = 0;
    }
  }
  if (normal) *normal = n;
  if (dnormal_dx) *dnormal_dx = dn;
  return g;
}

std::string RigidProfile::describe() const {
  const auto& p = profile_.spec().points;
  std::ostringstream os;
  os << "profile(" << (profile_.spec().closed ? "closed, " : "") << p.size() << " points from ("
     << p.front().x() << "," << p.front().y() << ") to (" << p.back().x() << "," << p.back().y()
     << "))";
  return os.str();
}

DisplacedObstacle::DisplacedObstacle(ObstaclePtr base, Vec2 displacement)
    : base_(std::move(base)), d_(displacement) {}

double DisplacedObstacle::gap(const Vec2& x, Vec2* normal, Mat2* dnormal_dx) const {
  return base_->gap(x - offset(), normal, dnormal_dx);
}

std::string DisplacedObstacle::describe() const {
  std::ostringstream os;
  os << base_->describe() << " displaced by ";
  if (factors_.x() == factors_.y()) os << factors_.x() << " x (" << d_.x() << "," << d_.y() << ")";
  else os << "(" << factors_.x() << " x " << d_.x() << "," << factors_.y() << " x " << d_.y() << ")";
  return os.str();
}

}  // namespace hpcontact::contact
