// Gauss-point penalty contact against a rigid obstacle with its consistent tangent.
#include "hpcontact/contact/penalty.hpp"

#include <cmath>

namespace hpcontact::contact {

ContactState contact_state(const PointState& s) {
  if (s.gap > 0 && !(s.pressure > 0)) return ContactState::open;
  if (s.stick_slip == StickSlip::stick) return ContactState::stick;
  if (s.stick_slip == StickSlip::slip) return ContactState::slip;
  return ContactState::contact;
}

const char* state_name(ContactState s) {
  switch (s) {
    case ContactState::open: return "open";
    case ContactState::contact: return "contact";
    case ContactState::stick: return "stick";
    case ContactState::slip: return "slip";
  }
  return "";
}

Tangential add_friction(PointState& ps, const FrictionLaw& law, const FrictionHistory& h,
                        const Vec2& anchor) {
  ps.tau = h.tau;
  ps.g_t = (ps.x - anchor).dot(h.tau);
  const Tangential tr = return_map(law, ps.g_t, h.slip, ps.pressure);
  ps.t_t = tr.traction;
  ps.slip = tr.slip;
  ps.stick_slip = tr.state;
  ps.traction -= tr.traction * h.tau;
  return tr;
}

void penalty_contact(const std::vector<ContactPoint>& points, const Obstacle& obstacle,
                     double eps_n, const Eigen::VectorXd& u, Eigen::VectorXd& force,
                     std::vector<Eigen::Triplet<double>>* tangent, int offset,
                     std::vector<PointState>* states, const std::vector<PointState>* frozen,
                     FrictionInput friction) {
  if (states) states->assign(points.size(), PointState{});
  for (size_t i = 0; i < points.size(); ++i) {
    const ContactPoint& cp = points[i];
    const int m = static_cast<int>(cp.modes.size());
    Vec2 ux = Vec2::Zero();
    for (int k = 0; k < m; ++k) ux += cp.N(k) * Vec2(u(2 * cp.modes[k]), u(2 * cp.modes[k] + 1));
    const Vec2 x = cp.X + ux;
    Vec2 n;
    Mat2 dn = Mat2::Zero();
    double g;
    if (frozen) {
      const PointState& s0 = (*frozen)[i];
      n = s0.normal;
      g = s0.gap + n.dot(x - s0.x);
    } else {
      g = obstacle.gap(x, &n, tangent ? &dn : nullptr);
    }
    const double pen = g < 0 ? -g : 0.0;
    PointState ps{x, g, eps_n * pen, eps_n * pen * n, n};
    ps.tau = friction_tangent(n);
    ps.foot = x - g * n;
    // g = 0 counts as active: the force is zero there but the tangent takes the side of
    // contact, so a body that touches its support without load (a zero initial gap) is held.
    Tangential tr;
    if (const FrictionHistory* h = friction.at(i, g))
      tr = add_friction(ps, *friction.law, *h, h->anchor + obstacle.offset());
    if (states) (*states)[i] = ps;
    if (g > 0) continue;
    const Vec2 f = cp.weight * ps.traction;
    for (int k = 0; k < m; ++k) {
      force(2 * cp.modes[k]) += cp.N(k) * f.x();
      force(2 * cp.modes[k] + 1) += cp.N(k) * f.y();
    }
    if (!tangent) continue;
    // Friction: w τ ∂t_T/∂xᵀ with ∂g_T/∂x = τ, ∂p_N/∂x = −ε_N n (τ = 0 when open).
    const Mat2 C = cp.weight * (eps_n * (n * n.transpose() + g * dn) +
                                ps.tau * (tr.dt_dgt * ps.tau - tr.dt_dp * eps_n * n).transpose());
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b) {
        const double nn = cp.N(a) * cp.N(b);
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c)
            tangent->emplace_back(offset + 2 * cp.modes[a] + r, offset + 2 * cp.modes[b] + c,
                                  nn * C(r, c));
      }
  }
}

}  // namespace hpcontact::contact
