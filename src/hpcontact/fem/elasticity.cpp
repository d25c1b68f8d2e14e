// Stiffness by blocks: with G_x = dN/dx sqrt(w det J), the four blocks of B^T D B are sums of
// the three products G_x G_x^T, G_y G_y^T, G_x G_y^T scaled by the entries of D (isotropic D has
// D13 = D23 = 0), which lets the matrix products do the work.
#include "hpcontact/fem/elasticity.hpp"

#include "hpcontact/fem/point_blocks.hpp"

namespace hpcontact::fem {

Eigen::MatrixXd stiffness(const ElementValues& ev, const material::Elasticity& D, double thickness) {
  const int n = ev.n_modes();
  const Eigen::VectorXd s = (ev.JxW * thickness).cwiseSqrt();
  const Eigen::MatrixXd Gx = ev.dN_dx * s.asDiagonal();
  const Eigen::MatrixXd Gy = ev.dN_dy * s.asDiagonal();
  Eigen::MatrixXd XX = Eigen::MatrixXd::Zero(n, n), YY = XX, XY = XX;
  for_point_blocks(ev.n_points(), 6.0 * n * n, [&](int first, int count) {
    const auto gx = Gx.middleCols(first, count), gy = Gy.middleCols(first, count);
    XX.noalias() += gx * gx.transpose();
    YY.noalias() += gy * gy.transpose();
    XY.noalias() += gx * gy.transpose();
  });
  const double d11 = D(0, 0), d12 = D(0, 1), d22 = D(1, 1), d33 = D(2, 2);
  Eigen::MatrixXd K(2 * n, 2 * n);
  K.topLeftCorner(n, n) = d11 * XX + d33 * YY;
  K.bottomRightCorner(n, n) = d22 * YY + d33 * XX;
  K.topRightCorner(n, n) = d12 * XY + d33 * XY.transpose();
  K.bottomLeftCorner(n, n) = K.topRightCorner(n, n).transpose();
  return K;
}

Eigen::MatrixXd axisymmetric_stiffness(const ElementValues& ev, const material::LinearElastic& m) {
  const int n = ev.n_modes(), np = ev.n_points();
  Eigen::VectorXd w(np), inv_r(np);
  for (int k = 0; k < np; ++k) {
    w(k) = ev.JxW(k) * OutOfPlane(0, true).at(ev.x[k]);
    inv_r(k) = 1 / ev.x[k].x();
  }
  // The plane part as plane strain with the weights 2π r JxW, then the hoop row H = N / r.
  const Eigen::VectorXd s = w.cwiseSqrt();
  const Eigen::MatrixXd Gx = ev.dN_dx * s.asDiagonal();
  const Eigen::MatrixXd Gy = ev.dN_dy * s.asDiagonal();
  const Eigen::MatrixXd H = ev.N * (inv_r.cwiseProduct(s)).asDiagonal();
  const material::Elasticity D = m.D();
  const double l = m.lambda(), l2m = D(0, 0), mu = D(2, 2);
  Eigen::MatrixXd XX = Eigen::MatrixXd::Zero(n, n), YY = XX, XY = XX, HX = XX, HY = XX, HH = XX;
  for_point_blocks(np, 12.0 * n * n, [&](int first, int count) {
    const auto gx = Gx.middleCols(first, count), gy = Gy.middleCols(first, count);
    const auto h = H.middleCols(first, count);
    XX.noalias() += gx * gx.transpose();
    YY.noalias() += gy * gy.transpose();
    XY.noalias() += gx * gy.transpose();
    HX.noalias() += h * gx.transpose();
    HY.noalias() += h * gy.transpose();
    HH.noalias() += h * h.transpose();
  });
  Eigen::MatrixXd K(2 * n, 2 * n);
  K.topLeftCorner(n, n) = l2m * XX + mu * YY + l * (HX + HX.transpose()) + l2m * HH;
  K.bottomRightCorner(n, n) = l2m * YY + mu * XX;
  K.topRightCorner(n, n) = l * XY + mu * XY.transpose() + l * HY;
  K.bottomLeftCorner(n, n) = K.topRightCorner(n, n).transpose();
  return K;
}

Eigen::VectorXd body_force(const ElementValues& ev, const Vec2& b, const OutOfPlane& measure) {
  const int n = ev.n_modes();
  Eigen::VectorXd f(2 * n);
  Eigen::VectorXd m(ev.n_points());
  for (int k = 0; k < ev.n_points(); ++k) m(k) = ev.JxW(k) * measure.at(ev.x[k]);
  const Eigen::VectorXd w = ev.N * m;
  f.head(n) = b.x() * w;
  f.tail(n) = b.y() * w;
  return f;
}

Eigen::Matrix3Xd strains(const ElementValues& ev, const Eigen::VectorXd& u_e) {
  const int n = ev.n_modes();
  Eigen::Matrix3Xd eps(3, ev.n_points());
  const auto ux = u_e.head(n), uy = u_e.tail(n);
  eps.row(0) = ux.transpose() * ev.dN_dx;
  eps.row(1) = uy.transpose() * ev.dN_dy;
  eps.row(2) = ux.transpose() * ev.dN_dy + uy.transpose() * ev.dN_dx;
  return eps;
}

Eigen::Vector3d strain(const PointValues& pv, const Eigen::VectorXd& u_e) {
  const int n = static_cast<int>(pv.N.size());
  const auto ux = u_e.head(n), uy = u_e.tail(n);
  return {ux.dot(pv.dN_dx), uy.dot(pv.dN_dy), ux.dot(pv.dN_dy) + uy.dot(pv.dN_dx)};
}

}  // namespace hpcontact::fem
