// Gap kinematics of a contact point: rigid obstacles (dn/dx from the obstacle) and the other
// body's deformed boundary (the covariant linearisation of the closest-point gap, e.g.
// Wriggers, Computational Contact Mechanics, ch. 4; see two_body.hpp for the formula).
#include "hpcontact/contact/point_gap.hpp"

#include "hpcontact/contact/friction.hpp"

namespace hpcontact::contact {

PointGap rigid_point_gap(const ContactPoint& cp, const Obstacle& obstacle, const Eigen::VectorXd& u,
                         int offset, bool second, bool turning) {
  PointGap pg;
  const int m = static_cast<int>(cp.modes.size());
  Vec2 ux = Vec2::Zero();
  for (int k = 0; k < m; ++k) ux += cp.N(k) * Vec2(u(2 * cp.modes[k]), u(2 * cp.modes[k] + 1));
  pg.x = cp.X + ux;
  Mat2 dn = Mat2::Zero();
  pg.g = obstacle.gap(pg.x, &pg.normal, second ? &dn : nullptr);
  pg.found = true;
  pg.tangent = friction_tangent(pg.normal);
  pg.foot = pg.x - pg.g * pg.normal;
  pg.dofs.resize(2 * m);
  pg.dg.resize(2 * m);
  pg.dt.resize(2 * m);
  for (int k = 0; k < m; ++k)
    for (int c = 0; c < 2; ++c) {
      pg.dofs[2 * k + c] = offset + 2 * cp.modes[k] + c;
      pg.dg(2 * k + c) = cp.N(k) * pg.normal(c);
      pg.dt(2 * k + c) = cp.N(k) * pg.tangent(c);
    }
  if (second) {
    pg.d2g.resize(2 * m, 2 * m);
    for (int a = 0; a < m; ++a)
      for (int b = 0; b < m; ++b)
        pg.d2g.block<2, 2>(2 * a, 2 * b) = cp.N(a) * cp.N(b) * dn;
  }
  if (second && turning) {
    // τ = Q n(x): ∂τ/∂u = Q (∂n/∂x) ∂x/∂u; dt_i = N_k τ_c
    const Mat2 Qdn = tangent_rotation() * dn;
    pg.dtau.resize(2, 2 * m);
    for (int b = 0; b < m; ++b) pg.dtau.middleCols<2>(2 * b) = cp.N(b) * Qdn;
    pg.ddt.resize(2 * m, 2 * m);
    for (int a = 0; a < m; ++a)
      for (int c = 0; c < 2; ++c) pg.ddt.row(2 * a + c) = cp.N(a) * pg.dtau.row(c);
  }
  return pg;
}

namespace {

/// A point beyond a free end x_e of the other boundary (normal n_e, unit tangent t_e there):
/// g = (x − x_e)·n_e + |(x − x_e)·t_e| (the gap to the boundary's line, plus how far past its end:
/// continuous at the end, positive beyond it by more than x lies below the line). Its gradient is
/// taken as n_e alone, so that the force a multiplier puts on the point acts along the normal
/// the resultant is reported along (the |·| term's n_e-free part is left out of the tangent:
/// such points are open unless they touch the end's corner). The foot is the end, a material
/// point of the other body; its normal and tangent held fixed (no second derivatives).
PointGap beyond_free_end(const ContactPoint& cp, const Vec2& x, const BoundaryPoint& end,
                         int offset_s, int offset_m) {
  PointGap pg;
  pg.x = x;
  pg.found = true;
  pg.beyond_end = true;
  const Vec2 n = end.normal, t = end.dx_dt.normalized(), r = x - end.x;
  const Vec2 d = n;
  pg.g = r.dot(n) + std::abs(r.dot(t));
  pg.normal = n;
  pg.tangent = friction_tangent(n);
  pg.foot = end.x;
  pg.foot_edge = end.edge;
  pg.foot_t = end.t;
  const int ms = static_cast<int>(cp.modes.size()), mm = static_cast<int>(end.modes.size());
  const int L = 2 * (ms + mm);
  pg.dofs.resize(L);
  pg.dg.resize(L);
  pg.dt.resize(L);
  for (int k = 0; k < ms; ++k)
    for (int c = 0; c < 2; ++c) {
      pg.dofs[2 * k + c] = offset_s + 2 * cp.modes[k] + c;
      pg.dg(2 * k + c) = cp.N(k) * d(c);
      pg.dt(2 * k + c) = cp.N(k) * pg.tangent(c);
    }
  for (int k = 0; k < mm; ++k)
    for (int c = 0; c < 2; ++c) {
      const int j = 2 * (ms + k) + c;
      pg.dofs[j] = offset_m + 2 * end.modes[k] + c;
      pg.dg(j) = -end.N(k) * d(c);
      pg.dt(j) = -end.N(k) * pg.tangent(c);
    }
  pg.d2g = Eigen::MatrixXd::Zero(L, L);
  return pg;
}

}  // namespace

PointGap two_body_point_gap(const ContactPoint& cp, const Eigen::VectorXd& u_s,
                            const DeformableBoundary& master, int offset_s, int offset_m, bool second,
                            const DeformableBoundary* own, bool turning) {
  PointGap pg;
  const int ms = static_cast<int>(cp.modes.size());
  pg.x = cp.X;
  for (int k = 0; k < ms; ++k) pg.x += cp.N(k) * Vec2(u_s(2 * cp.modes[k]), u_s(2 * cp.modes[k] + 1));
  BoundaryPoint foot;
  if (!master.project(pg.x, foot)) {
    if (!master.free_end(pg.x, foot)) return pg;
    return beyond_free_end(cp, pg.x, foot, offset_s, offset_m);
  }
  pg.found = true;
  const Vec2 n_m = foot.normal;
  const Vec2 t = foot.dx_dt;
  const Vec2 r = pg.x - foot.x;
  const double g_m = r.dot(n_m);  // the one-sided gap: the foot is the closest point along n_m
  Vec2 n = n_m;
  BoundaryPoint here;
  double mean_length = 0;  // |n_m − n_s| of the two-sided normal
  if (own) {
    own->evaluate(cp.edge, cp.t, here);
    const Vec2 mean = n_m - here.normal;
    mean_length = mean.norm();
    if (mean_length > 1e-8) n = mean / mean_length;
  }
  const bool two_sided = mean_length > 1e-8;
  pg.normal = n;
  pg.tangent = friction_tangent(n);  // not t/|t|: t follows the edge's parametrisation
  pg.foot = foot.x;
  pg.foot_edge = foot.edge;
  pg.foot_t = foot.t;
  pg.g = r.dot(n);
  const int mm = static_cast<int>(foot.modes.size());
  const int L = 2 * (ms + mm);
  pg.dofs.resize(L);
  pg.dg.resize(L);
  pg.dt.resize(L);
  // Gt = ∂[(x_s − x_m)·t]/∂u and Dn = ∂(n_m·x_m')/∂u at fixed ξ (the one-sided kinematics)
  Eigen::VectorXd Gt = Eigen::VectorXd::Zero(L), Dn = Eigen::VectorXd::Zero(L);
  for (int k = 0; k < ms; ++k)
    for (int c = 0; c < 2; ++c) {
      pg.dofs[2 * k + c] = offset_s + 2 * cp.modes[k] + c;
      pg.dg(2 * k + c) = cp.N(k) * n(c);
      Gt(2 * k + c) = cp.N(k) * t(c);
      pg.dt(2 * k + c) = cp.N(k) * pg.tangent(c);
    }
  for (int k = 0; k < mm; ++k)
    for (int c = 0; c < 2; ++c) {
      const int j = 2 * (ms + k) + c;
      pg.dofs[j] = offset_m + 2 * foot.modes[k] + c;
      pg.dg(j) = -foot.N(k) * n(c);
      Gt(j) = -foot.N(k) * t(c);
      Dn(j) = foot.dN(k) * n_m(c);
      pg.dt(j) = -foot.N(k) * pg.tangent(c);
    }
  if (!second) return pg;  // a residual needs g, dg and dt alone
  // The foot slides, δξ = H·δu / cc, and the tangent x_m' turns with it and with the other
  // body's modes: n_m·δx_m' = W·δu, δn_m = −x_m' (W·δu) / a.
  const double a = t.squaredNorm(), kappa = master.curvature(foot), cc = a - g_m * kappa;
  const Eigen::VectorXd H = Gt + g_m * Dn;
  const Eigen::VectorXd W = Dn + kappa * H / cc;
  Eigen::MatrixXd dn_du;  // ∂n/∂u (2 × L) of the normal the gap is measured along
  if (two_sided) {
    // n̄ = (n_m − n_s)/|n_m − n_s|, n_s the point's own normal at its material point:
    // δn_s = −x_s' (n_s·δx_s') / a_s, n_s·δx_s' = Ws·δu; δn̄ = (I − n̄n̄ᵀ)(δn_m − δn_s)/|n_m − n_s|.
    Eigen::VectorXd Ws = Eigen::VectorXd::Zero(L);
    for (size_t i = 0; i < here.modes.size(); ++i)
      for (int k = 0; k < ms; ++k)
        if (cp.modes[k] == here.modes[i])
          for (int c = 0; c < 2; ++c) Ws(2 * k + c) = here.dN(i) * here.normal(c);
    const Vec2 xs = here.dx_dt;
    const Mat2 P = Mat2::Identity() - n * n.transpose();
    dn_du = (P * xs) * Ws.transpose() / (xs.squaredNorm() * mean_length) -
            (P * t) * W.transpose() / (a * mean_length);
    // The constraint's gradient, exact: δg = n̄·(δx_s − δx_m|ξ) − (n̄·x_m') δξ + r·δn̄. The
    // force stays λ n̄ on both bodies (dg), equal and opposite, so that mirror-image bodies
    // receive mirror-image forces.
    pg.dg_row = pg.dg - (n.dot(t) / cc) * H + dn_du.transpose() * r;
  } else {
    dn_du = -t * W.transpose() / a;
  }
  // ∂v/∂u of a vector field v_i = ±N_k v_c over the dofs (+ on the point's modes, − on the
  // foot's, whose N_k(ξ) slides with the foot) of a unit vector v that turns as dv_du
  const auto turning_field = [&](const Vec2& v, const Eigen::MatrixXd& dv_du) {
    Eigen::MatrixXd D(L, L);
    for (int k = 0; k < ms; ++k)
      for (int c = 0; c < 2; ++c) D.row(2 * k + c) = cp.N(k) * dv_du.row(c);
    for (int k = 0; k < mm; ++k)
      for (int c = 0; c < 2; ++c)
        D.row(2 * (ms + k) + c) = -foot.N(k) * dv_du.row(c) - (foot.dN(k) * v(c) / cc) * H.transpose();
    return D;
  };
  if (second && two_sided) {
    pg.d2g = turning_field(n, dn_du);  // ∂(force direction)/∂u: not symmetric
  } else if (second) {
    // ∂²g/∂u² of the one-sided closest-point gap (symmetric)
    const Eigen::MatrixXd M =
        -(Dn * H.transpose() / cc + Gt * Dn.transpose() / a + kappa * Gt * H.transpose() / (a * cc));
    pg.d2g = 0.5 * (M + M.transpose());
  }
  if (second && turning) {
    // τ = Q n turns with n; dt_i = ±N_k(ξ) τ_c changes with τ and with N_k(ξ)
    pg.dtau = tangent_rotation() * dn_du;
    pg.ddt = turning_field(pg.tangent, pg.dtau);
  }
  return pg;
}

}  // namespace hpcontact::contact
