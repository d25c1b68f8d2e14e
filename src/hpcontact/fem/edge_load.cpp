// Edge load integration along the exact (or isoparametric) element boundary.
#include "hpcontact/fem/edge_load.hpp"

#include "hpcontact/basis/quadrature.hpp"

namespace hpcontact::fem {

std::array<double, 2> edge_reference_point(int le, double t) {
  switch (le) {
    case 0: return {t, -1.0};
    case 1: return {1.0, t};
    case 2: return {t, 1.0};
    default: return {-1.0, t};
  }
}

Vec2 edge_geometry(const mesh::ElementMap& map, int le, double t, Vec2* normal, double* ds_dt) {
  const auto r = edge_reference_point(le, t);
  Mat2 J;
  const Vec2 x = map.map(r[0], r[1], &J);
  const Vec2 T = (le % 2 == 0) ? Vec2(J.col(0)) : Vec2(J.col(1));
  // E1, E2 run counter-clockwise around the element: the outward normal is T turned clockwise;
  // E3, E4 run clockwise: it is T turned counter-clockwise.
  const double len = T.norm();
  if (normal) *normal = (le < 2 ? Vec2(T.y(), -T.x()) : Vec2(-T.y(), T.x())) / len;
  if (ds_dt) *ds_dt = len;
  return x;
}

Eigen::VectorXd edge_load(const ElementSpace& space, const mesh::ElementMap& map, int le, double t0,
                          double t1, int n_gauss, const OutOfPlane& measure, const TractionFn& traction) {
  const auto& rule = basis::gauss_legendre(n_gauss);
  const int n = space.n_modes();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(2 * n);
  Eigen::VectorXd N(n);
  for (int i = 0; i < rule.size(); ++i) {
    const double t = 0.5 * (t0 + t1) + 0.5 * (t1 - t0) * rule.points[i];
    const double w = 0.5 * (t1 - t0) * rule.weights[i];
    Vec2 normal;
    double ds_dt;
    const Vec2 x = edge_geometry(map, le, t, &normal, &ds_dt);
    const Vec2 q = traction(x, normal);
    const auto r = edge_reference_point(le, t);
    space.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
    const double c = w * ds_dt * measure.at(x);
    f.head(n) += c * q.x() * N;
    f.tail(n) += c * q.y() * N;
  }
  return f;
}

}  // namespace hpcontact::fem
