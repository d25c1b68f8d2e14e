// A follower pressure on one element edge: the force of a pressure acting normal to the deformed
// edge per unit deformed length (and deformed ring 2π r), with its load stiffness.
#pragma once

#include <functional>

#include <Eigen/Dense>

#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
#include "hpcontact/mesh/element_map.hpp"

namespace hpcontact::fem {

/// The pressure at the undeformed point X (per unit deformed area; positive pushes into the body).
using PressureFn = std::function<double(const Vec2& X)>;

/// The external force of a follower pressure and its derivative, over an element's displacement
/// dofs (component-blocked, 2 n).
struct FollowerForce {
  Eigen::VectorXd f;  ///< the force on the element (what the residual subtracts)
  Eigen::MatrixXd K;  ///< ∂f/∂u_e, the load stiffness (not symmetric); empty unless asked for
};

/// The force of the pressure p(X) on local edge le of an element between the local parameters
/// t0 < t1 (n_gauss point rule on [t0, t1]) at the element's displacements ue (component-blocked,
/// its first 2 n entries are used). On the deformed edge x(t) = X(t) + u(t), with x_t = dx/dt
/// and R the rotation that turns the edge's tangent into its outward normal (clockwise on local
/// edges 0, 1, counter-clockwise on 2, 3, as edge_geometry),
///   f_a = −∫ N_a p(X) m(x) R x_t dt,   m(x) = the thickness, or 2π x.x (the deformed ring),
/// since n ds = R x_t dt on the deformed edge. With `tangent`, K = ∂f/∂u_e:
///   K_{a c, b d} = −∫ N_a p [m R_cd N_b,t + (R x_t)_c ∂m/∂x_d N_b] dt.
FollowerForce follower_pressure(const ElementSpace& space, const mesh::ElementMap& map, int le,
                                double t0, double t1, int n_gauss, const OutOfPlane& measure,
                                const Eigen::Ref<const Eigen::VectorXd>& ue, const PressureFn& pressure,
                                bool tangent);

}  // namespace hpcontact::fem
