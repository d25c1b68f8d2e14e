// Sphere, cylinder and plane as retractions onto themselves, with their derivatives.
#include "hpcontact/geometry/surface.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

#include "hpcontact/core/error.hpp"

namespace hpcontact::geometry {

namespace {

std::string format(const Vec3& v) {
  std::ostringstream s;
  s << "(" << v.x() << "," << v.y() << "," << v.z() << ")";
  return s.str();
}

/// slerp(n0, n1; s) = [sin((1 − s) ω) n0 + sin(s ω) n1] / sin ω for unit n0, n1 at angle ω, and
/// its s-derivative; n0 (derivative 0) when ω vanishes. Throws for antipodal directions.
Vec3 slerp(const Vec3& n0, const Vec3& n1, double s, Vec3* d_ds, const std::string& what) {
  const double w = std::atan2(n0.cross(n1).norm(), n0.dot(n1));
  HPC_REQUIRE(w < std::numbers::pi - 1e-9, InputError, what,
              ": an edge between diametrically opposite points ", format(n0), " and ", format(n1),
              " (the circle through them is not unique)");
  if (w < 1e-14) {
    if (d_ds) *d_ds = Vec3::Zero();
    return n0;
  }
  const double sw = std::sin(w);
  if (d_ds) *d_ds = (w / sw) * (-std::cos((1 - s) * w) * n0 + std::cos(s * w) * n1);
  return (std::sin((1 - s) * w) * n0 + std::sin(s * w) * n1) / sw;
}

}  // namespace

Vec3 Surface::edge(const Vec3& A, const Vec3& B, double t, Vec3* dE) const {
  const Vec3 chord = 0.5 * (1 - t) * A + 0.5 * (1 + t) * B;
  Mat3 dP;
  const Vec3 x = onto(chord, dE ? &dP : nullptr);
  if (dE) *dE = dP * (0.5 * (B - A));
  return x;
}

Sphere::Sphere(Vec3 centre, double radius) : c_(centre), r_(radius) {
  HPC_REQUIRE(radius > 0, InputError, "sphere: radius must be > 0 (got ", radius, ")");
}

Vec3 Sphere::onto(const Vec3& y, Mat3* dP) const {
  const Vec3 d = y - c_;
  const double rho = d.norm();
  HPC_REQUIRE(rho > 1e-14 * r_, InputError, describe(), ": no central projection of its centre ",
              format(y));
  const Vec3 n = d / rho;
  if (dP) *dP = (r_ / rho) * (Mat3::Identity() - n * n.transpose());
  return c_ + r_ * n;
}

Vec3 Sphere::edge(const Vec3& A, const Vec3& B, double t, Vec3* dE) const {
  const Vec3 a = A - c_, b = B - c_;
  HPC_REQUIRE(a.norm() > 1e-14 * r_ && b.norm() > 1e-14 * r_, InputError, describe(),
              ": an edge through its centre");
  Vec3 dn;
  const Vec3 n = slerp(a.normalized(), b.normalized(), 0.5 * (t + 1), dE ? &dn : nullptr, describe());
  if (dE) *dE = 0.5 * r_ * dn;
  return c_ + r_ * n;
}

std::string Sphere::describe() const {
  std::ostringstream s;
  s << "sphere(centre=" << format(c_) << ", R=" << r_ << ")";
  return s.str();
}

Cylinder::Cylinder(Vec3 point_on_axis, Vec3 axis, double radius)
    : c_(point_on_axis), a_(axis), r_(radius) {
  HPC_REQUIRE(axis.norm() > 0, InputError, "cylinder: the axis direction must not be zero");
  HPC_REQUIRE(radius > 0, InputError, "cylinder: radius must be > 0 (got ", radius, ")");
  a_.normalize();
}

Vec3 Cylinder::onto(const Vec3& y, Mat3* dP) const {
  const Vec3 d = y - c_;
  const double along = a_.dot(d);
  const Vec3 w = d - along * a_;
  const double rho = w.norm();
  HPC_REQUIRE(rho > 1e-14 * r_, InputError, describe(), ": no radial projection of ", format(y),
              ", a point of the axis");
  const Vec3 n = w / rho;
  if (dP) {
    const Mat3 axial = a_ * a_.transpose();
    *dP = axial + (r_ / rho) * (Mat3::Identity() - n * n.transpose()) * (Mat3::Identity() - axial);
  }
  return c_ + along * a_ + r_ * n;
}

Vec3 Cylinder::edge(const Vec3& A, const Vec3& B, double t, Vec3* dE) const {
  const double hA = a_.dot(A - c_), hB = a_.dot(B - c_);
  const Vec3 wA = A - c_ - hA * a_, wB = B - c_ - hB * a_;
  HPC_REQUIRE(wA.norm() > 1e-14 * r_ && wB.norm() > 1e-14 * r_, InputError, describe(),
              ": an edge through its axis");
  const double s = 0.5 * (t + 1);
  Vec3 dn;
  const Vec3 n = slerp(wA.normalized(), wB.normalized(), s, dE ? &dn : nullptr, describe());
  if (dE) *dE = 0.5 * ((hB - hA) * a_ + r_ * dn);
  return c_ + ((1 - s) * hA + s * hB) * a_ + r_ * n;
}

std::string Cylinder::describe() const {
  std::ostringstream s;
  s << "cylinder(point=" << format(c_) << ", axis=" << format(a_) << ", R=" << r_ << ")";
  return s.str();
}

Plane::Plane(Vec3 point, Vec3 normal) : c_(point), n_(normal) {
  HPC_REQUIRE(normal.norm() > 0, InputError, "plane: the normal must not be zero");
  n_.normalize();
}

Vec3 Plane::onto(const Vec3& y, Mat3* dP) const {
  if (dP) *dP = Mat3::Identity() - n_ * n_.transpose();
  return y - ((y - c_).dot(n_)) * n_;
}

std::string Plane::describe() const {
  std::ostringstream s;
  s << "plane(point=" << format(c_) << ", normal=" << format(n_) << ")";
  return s.str();
}

}  // namespace hpcontact::geometry
