// The normal gap of one contact point against its obstacle, linearised in the displacements:
// the kinematics shared by the contact laws (penalty, multipliers).
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/contact/contact_boundary.hpp"
#include "hpcontact/contact/deformable_boundary.hpp"
#include "hpcontact/contact/obstacle.hpp"

namespace hpcontact::contact {

/// g_N of a point at the current state, with ∂g/∂u over the dofs it depends on and, when asked
/// for, ∂²g/∂u² (symmetric): against a rigid obstacle g(x) with ∇g = N n and ∇²g = N Nᵀ dn/dx;
/// against another body's deformed boundary the closest-point gap and its covariant
/// linearisation (two_body_contact).
struct PointGap {
  bool found = false;  ///< false: the other body's boundary has no closest point to it
  /// Two bodies: x lies beyond a free end of the other boundary (no closest point inside it);
  /// g is then measured from that end: g = (x − x_e)·n_e + |(x − x_e)·t_e|, positive once x is
  /// past the end by more than it lies below the boundary's line (DeformableBoundary::free_end).
  bool beyond_end = false;
  double g = std::numeric_limits<double>::infinity();
  Vec2 x = Vec2::Zero();       ///< deformed position
  Vec2 normal = Vec2(0, 1);    ///< the obstacle's outward unit normal at the closest point
  Vec2 tangent = Vec2(1, 0);   ///< unit tangent of the obstacle there, friction_tangent(normal)
  Vec2 foot = Vec2::Zero();    ///< the closest point
  int foot_edge = -1;          ///< two bodies: its edge of the other boundary, and parameter
  double foot_t = 0;
  std::vector<int> dofs;       ///< global dofs: the point's body's, then the other body's
  /// The direction of the force a pressure puts on the dofs: ∂g/∂u, except with a mean normal
  /// (two_body_point_gap), where it is n̄ N on both bodies and the gradient is dg_row.
  Eigen::VectorXd dg;
  Eigen::VectorXd dg_row;      ///< with `second`: ∂g/∂u where it differs from dg (mean normal), else empty
  /// τ·∂(x − x_foot)/∂u at dofs, the foot held as a material point of the obstacle: the
  /// tangential relative displacement of the point per unit dof (friction).
  Eigen::VectorXd dt;
  /// ∂dg/∂u at dofs (empty unless asked for): ∂²g/∂u², symmetric, except with a mean normal
  Eigen::MatrixXd d2g;
  /// With d2g and `turning`: how the tangent turns and the foot slides with u —
  /// ∂τ/∂u (2 × dofs) and ∂dt/∂u (dofs × dofs, row i the derivative of dt_i), the terms of
  /// friction's tangent that a curved obstacle or another body adds to a plane's.
  Eigen::MatrixXd dtau, ddt;
};

/// Against a rigid obstacle; u holds the body's dofs (dof = 2·mode + component), `offset` the
/// global index of its first.
/// `second`: d2g; `turning` (with second, for friction): dtau and ddt too.
PointGap rigid_point_gap(const ContactPoint& cp, const Obstacle& obstacle, const Eigen::VectorXd& u,
                         int offset, bool second, bool turning = false);

/// Against the deformed boundary of another body (its displacement set); offsets as above.
/// With `own` (the point's body's contact boundary, its displacement set, its edges those the
/// point's ContactPoint::edge counts) the gap is measured along the mean normal
/// n̄ = (n_m − n_s)/|n_m − n_s| of the two boundaries (n_s the point's own outward normal), not
/// the other body's alone: the two-sided pairing, which treats both bodies alike, so that
/// mirror-image bodies press each other along the mirror's normal. The pressure's force is
/// λ n̄ N on both bodies (dg: mirror-image forces on mirror-image bodies, so that a tangential
/// traction that the mirror says is zero is zero to round-off); the constraint's gradient dg_row,
/// d2g = ∂dg/∂u and the turning of the tangent τ = friction_tangent(n̄) are exact (n̄ turns with
/// both boundaries, the foot slides along the other), so that Newton converges quadratically.
PointGap two_body_point_gap(const ContactPoint& cp, const Eigen::VectorXd& u_s,
                            const DeformableBoundary& master, int offset_s, int offset_m, bool second,
                            const DeformableBoundary* own = nullptr, bool turning = false);

}  // namespace hpcontact::contact
