// Consistent nodal forces of a distributed load on one element edge (seed eq. 2.48).
#pragma once

#include <functional>

#include <Eigen/Dense>

#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
#include "hpcontact/mesh/element_map.hpp"

namespace hpcontact::fem {

/// Reference coordinates of local edge le (0..3) at its local parameter t in [-1, 1]
/// (directions as in basis/quad_modes.hpp).
std::array<double, 2> edge_reference_point(int le, double t);

/// Traction (force per length of edge, per unit thickness) at a boundary point x with outward
/// unit normal n.
using TractionFn = std::function<Vec2(const Vec2& x, const Vec2& n)>;

/// f_e = t ∫ N^T q ds over local edge le between local parameters t0 < t1, with an n_gauss
/// point rule on [t0, t1]. Component-blocked like every element vector.
Eigen::VectorXd edge_load(const ElementSpace& space, const mesh::ElementMap& map, int le, double t0,
                          double t1, int n_gauss, const OutOfPlane& measure, const TractionFn& traction);

/// Point, outward unit normal and ds/dt of local edge le at local parameter t.
Vec2 edge_geometry(const mesh::ElementMap& map, int le, double t, Vec2* normal, double* ds_dt);

}  // namespace hpcontact::fem
