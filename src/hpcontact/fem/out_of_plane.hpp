// The measure of a plane model in the third direction: a constant thickness, or the circle
// 2π r of an axisymmetric body (x = r) — what turns a line or area integral of the section into
// one over the solid.
#pragma once

#include <numbers>

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::fem {

struct OutOfPlane {
  double thickness = 1.0;
  bool axisymmetric = false;
  OutOfPlane() = default;
  OutOfPlane(double t) : thickness(t) {}  // NOLINT(google-explicit-constructor): a plane body's
  OutOfPlane(double t, bool axi) : thickness(t), axisymmetric(axi) {}
  /// At the undeformed point X: the thickness, or 2π X.x().
  double at(const Vec2& X) const {
    return axisymmetric ? 2 * std::numbers::pi * X.x() : thickness;
  }
};

}  // namespace hpcontact::fem
