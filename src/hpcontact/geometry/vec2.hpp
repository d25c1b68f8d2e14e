// Small fixed-size vector and matrix types of the plane.
#pragma once

#include <Eigen/Dense>

namespace hpcontact {

using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

}  // namespace hpcontact
