// A point of a body's boundary at a state: where the displacement carries it, and its gap
// against an obstacle.
#include "hpcontact/model/boundary_point.hpp"

#include "hpcontact/fem/edge_load.hpp"

namespace hpcontact::model {

Vec2 displaced(const Body& body, int q, const Eigen::VectorXd& N, const Vec2& X,
               const Eigen::VectorXd& u) {
  const auto& es = body.dofs.element(q);
  Vec2 x = X;
  for (int a = 0; a < es.n_modes(); ++a) {
    const int dof = body.dof_offset + 2 * es.modes[a];
    x += N(a) * Vec2(u(dof), u(dof + 1));
  }
  return x;
}

double gap_at(const Body& body, const contact::Obstacle& obstacle, int q, int le, double t,
              const Eigen::VectorXd& u, Vec2* x_out, Vec2* X_out) {
  const auto& es = body.dofs.element(q);
  Eigen::VectorXd N(es.n_modes());
  const auto r = fem::edge_reference_point(le, t);
  es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
  const Vec2 X = fem::edge_geometry(body.maps[q], le, t, nullptr, nullptr);
  if (X_out) *X_out = X;
  const Vec2 x = displaced(body, q, N, X, u);
  if (x_out) *x_out = x;
  return obstacle.gap(x, nullptr, nullptr);
}

std::pair<Vec2, Vec2> boundary_position(const Body& body, int q, int le, double t,
                                        const Eigen::VectorXd& u) {
  Vec2 x, X;
  gap_at(body, contact::RigidPlane(Vec2::Zero(), Vec2(0, 1)), q, le, t, u, &x, &X);
  return {X, x};
}

}  // namespace hpcontact::model
