// Normal penalty contact of a body's contact points against a rigid obstacle (seed eq. 3.19–3.24).
#pragma once

#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hpcontact/contact/contact_boundary.hpp"
#include "hpcontact/contact/friction.hpp"
#include "hpcontact/contact/obstacle.hpp"

namespace hpcontact::contact {

/// State of one contact point after an evaluation.
struct PointState {
  Vec2 x;                 ///< deformed position
  double gap = 0;         ///< signed normal gap g_N (negative: penetration)
  double pressure = 0;    ///< penalty pressure p_N = eps_N <-g_N> (>= 0, compressive)
  Vec2 traction;          ///< traction on the body, p_N n_obstacle − t_T τ
  Vec2 normal;            ///< the obstacle's outward normal at the closest point
  // Friction (zero and open without it):
  double g_t = 0;         ///< tangential gap (x − x_anchor)·τ of an anchored point
  double t_t = 0;         ///< tangential traction t_T along τ (the body receives −t_T τ)
  double slip = 0;        ///< accumulated slip after the return mapping
  StickSlip stick_slip = StickSlip::open;
  Vec2 tau = Vec2(1, 0);  ///< the tangent t_T acts along (anchored), else the current one
  // Where the point's projection lies, for anchoring it (two bodies: edge and parameter of the
  // other's boundary; rigid: the closest point of the obstacle, x − g n).
  int foot_edge = -1;
  double foot_t = 0;
  Vec2 foot = Vec2::Zero();
};

/// What a contact point does: open (g_N > 0 and no pressure: exact enforcement carries a
/// pressure where the gap between its nodes is slightly open), in contact without friction
/// (g_N ≤ 0, as the penalty counts it active, or a pressure), sticking or slipping. The codes are
/// contact.vtu's `state`.
enum class ContactState { open = 0, contact = 1, stick = 2, slip = 3 };
ContactState contact_state(const PointState& s);
/// "open", "contact", "stick", "slip" (contact.csv's `state`).
const char* state_name(ContactState s);

/// Friction of a pair's points: the law and each point's history (both may be absent).
struct FrictionInput {
  const FrictionLaw* law = nullptr;
  const std::vector<FrictionHistory>* history = nullptr;
  bool active() const { return law && law->active() && history; }
  /// The history of point i when it carries friction: anchored and in contact (g ≤ 0).
  const FrictionHistory* at(size_t i, double gap) const {
    if (!active() || gap > 0) return nullptr;
    const FrictionHistory& h = (*history)[i];
    return h.anchored ? &h : nullptr;
  }
};

/// The tangential part of an anchored point in contact whose anchor is now at `anchor`: g_T
/// along the frozen tangent, the return mapping, and the state's fields (τ, g_T, t_T, slip,
/// stick/slip, the traction less t_T τ).
Tangential add_friction(PointState& ps, const FrictionLaw& law, const FrictionHistory& h,
                        const Vec2& anchor);

/// Penalty contribution of all points against an obstacle.
///
/// With g = g_N(x + u) and the penetration <-g> = max(0, -g), the contact virtual work is
///   delta Pi_c = -eps_N ∫ <-g> n · delta u ds,
/// i.e. the body receives the force f_c = eps_N ∫ N^T <-g> n ds. Its consistent tangent
/// (derivative of -f_c with respect to u) at an active point is
///   K_c = eps_N ∫ N^T (n n^T + g dn/dx) N ds.
/// `u` holds the body's dofs (dof = 2·mode + component); `force` receives f_c at the same
/// indices; `tangent` (may be null) receives triplets of K_c, offset by `offset` in both indices.
///
/// With `frozen` (the states of an undisturbed evaluation), the gap is evaluated with the
/// normal of that state, g = g_0 + n_0·(x − x_0), as the seed's finite-difference tangent
/// requires (footnote to eq. 3.36): a disturbed point does not turn its normal.
///
/// With friction, an anchored active point adds the tangential force −w t_T τ N (t_T from
/// return_map) and the tangent w ∂t_T/∂u τ Nᵀ: ε_T τ τᵀ N Nᵀ in stick, −μ s ε_N τ nᵀ N Nᵀ in
/// slip (s = sign t_T; not symmetric).
void penalty_contact(const std::vector<ContactPoint>& points, const Obstacle& obstacle,
                     double eps_n, const Eigen::VectorXd& u, Eigen::VectorXd& force,
                     std::vector<Eigen::Triplet<double>>* tangent, int offset,
                     std::vector<PointState>* states,
                     const std::vector<PointState>* frozen = nullptr, FrictionInput friction = {});

}  // namespace hpcontact::contact
