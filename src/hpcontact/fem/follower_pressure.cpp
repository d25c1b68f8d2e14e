// The follower pressure of one element edge on the deformed boundary, and its load stiffness.
#include "hpcontact/fem/follower_pressure.hpp"

#include <numbers>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/fem/edge_load.hpp"

namespace hpcontact::fem {

namespace {

/// The rotation that turns local edge le's tangent dx/dt into its outward normal (times ds/dt):
/// clockwise on edges 0 and 1 (they run counter-clockwise around the element), counter-clockwise
/// on 2 and 3.
Mat2 outward_rotation(int le) {
  Mat2 R;
  if (le < 2) R << 0, 1, -1, 0;
  else R << 0, -1, 1, 0;
  return R;
}

}  // namespace

FollowerForce follower_pressure(const ElementSpace& space, const mesh::ElementMap& map, int le,
                                double t0, double t1, int n_gauss, const OutOfPlane& measure,
                                const Eigen::Ref<const Eigen::VectorXd>& ue, const PressureFn& pressure,
                                bool tangent) {
  const auto& rule = basis::gauss_legendre(n_gauss);
  const int n = space.n_modes();
  const Mat2 R = outward_rotation(le);
  FollowerForce out;
  out.f = Eigen::VectorXd::Zero(2 * n);
  if (tangent) out.K = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  Eigen::VectorXd N(n), N_xi(n), N_eta(n);
  for (int i = 0; i < rule.size(); ++i) {
    const double t = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * rule.points[i];
    const double w = 0.5 * (t1 - t0) * rule.weights[i];
    const auto r = edge_reference_point(le, t);
    Mat2 J;
    const Vec2 X = map.map(r[0], r[1], &J);
    space.evaluate(r[0], r[1], N.data(), N_xi.data(), N_eta.data());
    // along edges 0, 2 t is ξ, along 1, 3 it is η
    const Eigen::VectorXd& N_t = le % 2 == 0 ? N_xi : N_eta;
    const Vec2 u(N.dot(ue.head(n)), N.dot(ue.segment(n, n)));
    const Vec2 x = X + u;
    const Vec2 X_t = le % 2 == 0 ? Vec2(J.col(0)) : Vec2(J.col(1));
    const Vec2 x_t = X_t + Vec2(N_t.dot(ue.head(n)), N_t.dot(ue.segment(n, n)));
    const double p = pressure(X);
    if (p == 0.0) continue;
    const double m = measure.at(x);
    const Vec2 nds = R * x_t;  // the outward normal times ds/dt of the deformed edge
    const double c = -w * p;
    out.f.head(n) += c * m * nds.x() * N;
    out.f.tail(n) += c * m * nds.y() * N;
    if (!tangent) continue;
    // ∂m/∂x: 2π along x for a ring, nothing for a thickness
    const double dm_dx = measure.axisymmetric ? 2 * std::numbers::pi : 0.0;
    for (int cc = 0; cc < 2; ++cc)
      for (int dd = 0; dd < 2; ++dd) {
        Eigen::MatrixXd block = (c * m * R(cc, dd)) * N * N_t.transpose();
        if (dd == 0 && dm_dx != 0.0) block += (c * nds(cc) * dm_dx) * N * N.transpose();
        out.K.block(cc * n, dd * n, n, n) += block;
      }
  }
  return out;
}

}  // namespace hpcontact::fem
