// A point of a body's boundary at a state: where the displacement carries it, and its gap
// against an obstacle.
#pragma once

#include <utility>

#include <Eigen/Dense>

#include "hpcontact/contact/obstacle.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// The point X of element q displaced by u (all dofs): X + Σ_a N_a u_a, N the element's shape
/// functions there (in the element's mode order).
Vec2 displaced(const Body& body, int q, const Eigen::VectorXd& N, const Vec2& X,
               const Eigen::VectorXd& u);

/// Gap of the deformed boundary at local edge parameter t ∈ [-1, 1] of local edge le of element
/// q against `obstacle`; the deformed point in x_out, the undeformed one in X_out (either may be
/// null).
double gap_at(const Body& body, const contact::Obstacle& obstacle, int q, int le, double t,
              const Eigen::VectorXd& u, Vec2* x_out, Vec2* X_out = nullptr);

/// The position of a boundary point, undeformed and deformed (u all dofs).
std::pair<Vec2, Vec2> boundary_position(const Body& body, int q, int le, double t,
                                        const Eigen::VectorXd& u);

}  // namespace hpcontact::model
