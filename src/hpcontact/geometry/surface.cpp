// Sphere, cylinder and plane as retractions onto themselves, with their derivatives.
#include "hpcontact/geometry/surface.hpp"

#include <sstream>

#include "hpcontact/core/error.hpp"

namespace hpcontact::geometry {

namespace {

std::string format(const Vec3& v) {
  std::ostringstream s;
  s << "(" << v.x() << "," << v.y() << "," << v.z() << ")";
  return s.str();
}

}  // namespace

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
