// What a body's stresses say at a point of its contact boundary: −n·σ·n and the tractions along
// the obstacle's normal and tangent, per unit length along a surface frame.
#pragma once

#include <optional>
#include <tuple>

#include <Eigen/Dense>

#include "hpcontact/contact/obstacle.hpp"
#include "hpcontact/contact/surface_frame.hpp"
#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// What the stresses say at local edge parameter t of element q of a contact boundary, and the
/// boundary's position and length per unit length along a surface frame.
struct SideValues {
  Vec2 X;                     ///< the undeformed point
  double s = 0;               ///< position along the frame (of the undeformed point)
  double length_ratio = 1;    ///< dS/ds: undeformed boundary length per unit length along the frame
  double minus_sigma_nn = 0;  ///< −n·σ·n, n the outward normal (under finite strain the deformed one)
  double pressure_from_stress = 0;  ///< n_o·(P N) dS/ds
  double shear_from_stress = 0;     ///< −τ_o·(P N) dS/ds, τ_o = friction_tangent(n_o)
};

/// At local edge parameter t of element q of `body`, against `obstacle` (its normal n_o at the
/// deformed point: the direction the contact force acts along; −N where the point has no foot;
/// τ_o = friction_tangent(n_o) the direction friction acts along):
///   −n·σ·n,   n_o·(P N) dS/ds,   −τ_o·(P N) dS/ds,
/// N the undeformed outward normal, P N = J σ F⁻ᵀ N the traction per unit undeformed length
/// (σ N in the linear theory), n = F⁻ᵀN / |F⁻ᵀN| (N in the linear theory). The body receives
/// the traction λ n_o − λ_T τ_o per unit undeformed length from the multipliers (penalty: p_N,
/// t_T), so the two projections are what the stresses say λ and λ_T are.
SideValues side_values(const Body& body, const ContactPair& pair, const contact::Obstacle& obstacle,
                       const contact::SurfaceFrame& frame, int q, int le, double t,
                       const Eigen::VectorXd& u);

/// dS/ds at the undeformed boundary point X with outward normal N: undeformed boundary length
/// per unit length along `frame` (ds/dS along the boundary's unit tangent); where the boundary
/// runs across the frame the ratio is capped (no pressure there).
double length_ratio(const contact::SurfaceFrame& frame, const Vec2& X, const Vec2& N);

/// Where the stresses at multiplier node j of an exactly enforced pair are taken: a node on a
/// vertex lies on two edges' elements, and the stress is taken in the one whose map is regular
/// at that corner, since where two edges of one smooth curve meet the element there has a 180°
/// corner, its Jacobian vanishes at the corner and its stresses are singular. Where no element
/// is regular at the corner, 1e-3 of the edge inside it. (element, local edge, parameter).
std::optional<std::tuple<int, int, double>> node_stress_point(const Body& body, const ContactPair& pair, int j);

}  // namespace hpcontact::model
