// Two-body penalty contact: closest-point gap, its first and second variations (the standard
// covariant linearisation, e.g. Wriggers, Computational Contact Mechanics, ch. 4) at each point.
#include "hpcontact/contact/two_body.hpp"

#include <cmath>
#include <limits>

namespace hpcontact::contact {

void two_body_contact(const std::vector<ContactPoint>& points, const Eigen::VectorXd& u_s,
                      const DeformableBoundary& master, double eps_n, double weight_factor,
                      Eigen::VectorXd& force_s, Eigen::VectorXd& force_m,
                      std::vector<Eigen::Triplet<double>>* tangent, int offset_s, int offset_m,
                      std::vector<PointState>* states, FrictionInput friction) {
  if (states) states->assign(points.size(), PointState{});
  BoundaryPoint foot;
  for (size_t i = 0; i < points.size(); ++i) {
    const ContactPoint& cp = points[i];
    const int ms = static_cast<int>(cp.modes.size());
    Vec2 xs = cp.X;
    for (int k = 0; k < ms; ++k)
      xs += cp.N(k) * Vec2(u_s(2 * cp.modes[k]), u_s(2 * cp.modes[k] + 1));
    if (!master.project(xs, foot)) {
      if (states) {
        (*states)[i] = PointState{xs, std::numeric_limits<double>::infinity(), 0, Vec2::Zero(), Vec2(0, 1)};
        (*states)[i].tau = Vec2::Zero();  // no foot, no tangent
      }
      continue;
    }
    const Vec2 n = foot.normal, t = foot.dx_dt;
    const double g = (xs - foot.x).dot(n);
    const double p = g < 0 ? -eps_n * g : 0.0;
    PointState ps{xs, g, p, p * n, n};
    ps.tau = friction_tangent(n);
    ps.foot_edge = foot.edge;
    ps.foot_t = foot.t;
    ps.foot = foot.x;
    const FrictionHistory* h = friction.at(i, g);
    Tangential tr;
    BoundaryPoint at;  // the anchor, deformed
    if (h) {
      master.evaluate(h->edge, h->t, at);
      tr = add_friction(ps, *friction.law, *h, at.x);
    }
    if (states) (*states)[i] = ps;
    if (g > 0) continue;
    const double w = weight_factor * cp.weight;
    const int mm = static_cast<int>(foot.modes.size());
    // local dofs: body s's modes first (2 components each), then body m's
    const int L = 2 * (ms + mm);
    Eigen::VectorXd Gn = Eigen::VectorXd::Zero(L), Gt = Eigen::VectorXd::Zero(L),
                    Dn = Eigen::VectorXd::Zero(L);
    for (int k = 0; k < ms; ++k)
      for (int c = 0; c < 2; ++c) {
        Gn(2 * k + c) = cp.N(k) * n(c);
        Gt(2 * k + c) = cp.N(k) * t(c);
      }
    for (int k = 0; k < mm; ++k)
      for (int c = 0; c < 2; ++c) {
        const int j = 2 * (ms + k) + c;
        Gn(j) = -foot.N(k) * n(c);
        Gt(j) = -foot.N(k) * t(c);
        Dn(j) = foot.dN(k) * n(c);
      }
    // forces −∂Π/∂u = w p G_n
    for (int k = 0; k < ms; ++k)
      for (int c = 0; c < 2; ++c) force_s(2 * cp.modes[k] + c) += w * p * Gn(2 * k + c);
    for (int k = 0; k < mm; ++k)
      for (int c = 0; c < 2; ++c)
        force_m(2 * foot.modes[k] + c) += w * p * Gn(2 * (ms + k) + c);
    auto global = [&](int j) {
      const int k = j / 2, c = j % 2;
      return k < ms ? offset_s + 2 * cp.modes[k] + c : offset_m + 2 * foot.modes[k - ms] + c;
    };
    if (h) {
      // Friction: G_T = ∂g_T/∂u on the slave's modes and the anchor's modes of the master (not
      // the foot's); forces −w t_T G_T; tangent w G_T (dt_dgt G_T − dt_dp ε_N G_n)ᵀ.
      for (int k = 0; k < ms; ++k)
        for (int c = 0; c < 2; ++c) force_s(2 * cp.modes[k] + c) -= w * tr.traction * cp.N(k) * h->tau(c);
      for (size_t k = 0; k < at.modes.size(); ++k)
        for (int c = 0; c < 2; ++c) force_m(2 * at.modes[k] + c) += w * tr.traction * at.N(k) * h->tau(c);
      if (tangent) {
        std::vector<std::pair<int, double>> GT;  // (global dof, entry of G_T)
        GT.reserve(2 * (ms + at.modes.size()));
        for (int k = 0; k < ms; ++k)
          for (int c = 0; c < 2; ++c) GT.emplace_back(offset_s + 2 * cp.modes[k] + c, cp.N(k) * h->tau(c));
        for (size_t k = 0; k < at.modes.size(); ++k)
          for (int c = 0; c < 2; ++c) GT.emplace_back(offset_m + 2 * at.modes[k] + c, -at.N(k) * h->tau(c));
        for (const auto& [r, vr] : GT) {
          if (tr.dt_dgt != 0)
            for (const auto& [c, vc] : GT)
              if (vr * vc != 0.0) tangent->emplace_back(r, c, w * tr.dt_dgt * vr * vc);
          if (tr.dt_dp != 0)
            for (int j = 0; j < L; ++j)
              if (vr * Gn(j) != 0.0) tangent->emplace_back(r, global(j), -w * tr.dt_dp * eps_n * vr * Gn(j));
        }
      }
    }
    if (!tangent) continue;
    const double a = t.squaredNorm(), kappa = master.curvature(foot), cc = a - g * kappa;
    const Eigen::VectorXd H = Gt + g * Dn;
    const Eigen::MatrixXd M =
        -(Dn * H.transpose() / cc + Gt * Dn.transpose() / a + kappa * Gt * H.transpose() / (a * cc));
    const Eigen::MatrixXd K = w * (eps_n * Gn * Gn.transpose() - p * 0.5 * (M + M.transpose()));
    for (int r = 0; r < L; ++r)
      for (int s = 0; s < L; ++s)
        if (K(r, s) != 0.0) tangent->emplace_back(global(r), global(s), K(r, s));
  }
}

}  // namespace hpcontact::contact
