// Coulomb friction regularised by a tangential penalty (seed §3.3, eq. 3.19-3.21): the stick
// anchor and accumulated slip each contact point carries between load steps, and the return
// mapping of the tangential traction.
#pragma once

#include "hpcontact/geometry/vec2.hpp"

namespace hpcontact::contact {

/// The tangential law of a contact pair.
struct FrictionLaw {
  enum class Kind { none, stick, coulomb };
  Kind kind = Kind::none;
  double mu = 0;     ///< Coulomb coefficient (coulomb)
  double eps_t = 0;  ///< tangential penalty ε_T > 0 [force/length³]
  bool active() const { return kind != Kind::none; }
};

/// What a contact point remembers between load steps (the problem is path dependent). A point
/// is anchored at the end of the first load step in which it is in contact: to the foot of its
/// projection on the other side (an edge and parameter of the other body, or a point of a rigid
/// obstacle), with the unit tangent there frozen. From then on its tangential gap is
/// g_T = (x − x_anchor)·τ_anchor, x_anchor the anchor's current position; a point that opens
/// loses its anchor. The tangential gap is measured along the frozen tangent: exact for sliding
/// along a straight boundary that does not turn, an approximation of small rotations otherwise.
struct FrictionHistory {
  bool anchored = false;
  int edge = -1;            ///< two bodies: the anchor's edge of the other body's boundary
  double t = 0;             ///< two bodies: its edge parameter
  Vec2 anchor = Vec2::Zero();  ///< rigid obstacle: the anchor point, obstacle undisplaced
  Vec2 tau = Vec2(1, 0);    ///< unit tangent at the anchor, frozen
  double slip = 0;          ///< accumulated slip g_s (the plastic part of g_T)
};

/// The unit tangent τ that friction is signed along at a point whose obstacle has the outward
/// unit normal n there: n turned clockwise by 90°, τ = (n_y, −n_x), so that (τ, n) is
/// right-handed. Defined by the normal alone, it runs the same way along the whole boundary of
/// an obstacle: along a plane with normal (0, 1) it is (1, 0); against another body it does not
/// depend on the direction that body's edges are parametrised in (an edge's dx/dt would flip
/// between elements listed in opposite orientations, as hp refinement creates).
inline Vec2 friction_tangent(const Vec2& n) { return Vec2(n.y(), -n.x()); }
/// The matrix Q of friction_tangent: τ = Q n (for the derivatives of τ).
inline Mat2 tangent_rotation() { return (Mat2() << 0, 1, -1, 0).finished(); }

/// Stick or slip at one point.
enum class StickSlip { open, stick, slip };

/// Where the tangential traction t_T of a point in contact, pressed by p_N >= 0, lies against
/// Coulomb's cone |t_T| = μ p_N: inside it the point sticks; on it, to a relative 1e-9, it
/// slips (either sign), so that a slipping point, whose traction lies on the cone only to the
/// round-off of its solve, reads as slipping. At the cone's apex (p_N = 0 or μ = 0) every
/// traction slips, zero included. Under the stick law (Kind::stick) every point sticks. The
/// one test of the return mapping and of the exactly enforced pairs' points and nodes.
StickSlip stick_or_slip(const FrictionLaw& law, double t_t, double p_n);

/// The tangential traction t_T (along τ, acting on the other side; the point's body receives
/// −t_T τ), the slip after the return mapping, and the derivatives of t_T that the consistent
/// tangent needs: ∂t_T/∂u = dt_dgt ∂g_T/∂u + dt_dp ∂p_N/∂u.
struct Tangential {
  double traction = 0;
  double slip = 0;  ///< updated accumulated slip
  StickSlip state = StickSlip::open;
  double dt_dgt = 0;  ///< ε_T in stick, 0 in slip
  double dt_dp = 0;   ///< μ sign(t_T) in slip, 0 in stick
};

/// Trial t_T = ε_T (g_T − g_s,n); stick where stick_or_slip puts the trial (inside the cone, or
/// always with Kind::stick) or where the trial is zero, otherwise slip: t_T = μ p_N sign(trial),
/// g_s = g_T − t_T / ε_T. A trial on the cone (to a relative 1e-9) counts as slip, so that a
/// converged state evaluated again after its slips were committed maps to the same states (its
/// slipping points lie exactly on the cone then).
Tangential return_map(const FrictionLaw& law, double g_t, double slip_n, double p_n);

}  // namespace hpcontact::contact
