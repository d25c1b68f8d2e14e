// The edge-mode coefficients of a field along an edge (L2 projection, or the mid-edge node).
#include "hpcontact/model/edge_interpolant.hpp"

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/basis/quadrature.hpp"

namespace hpcontact::model {

std::vector<double> edge_mode_values(const Body& body, int e, const std::function<double(const Vec2&)>& g) {
  const int p = body.dofs.edge_degree(e);
  if (p < 2) return {};
  if (body.dofs.lagrange()) return {g(body.mesh.edge_point(e, 0.0))};
  const auto& edge = body.mesh.edge(e);
  const double g0 = g(body.mesh.node(edge.v0)), g1 = g(body.mesh.node(edge.v1));
  const int m = p - 1;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(m, m);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m);
  const auto& rule = basis::gauss_legendre(p + 10);
  std::vector<double> phi(p + 1);
  for (int i = 0; i < rule.size(); ++i) {
    const double t = rule.points[i], w = rule.weights[i];
    const double r = g(body.mesh.edge_point(e, t)) - (0.5 * (1 - t) * g0 + 0.5 * (1 + t) * g1);
    basis::hierarchic_1d(p, t, phi.data(), nullptr);
    for (int k = 0; k < m; ++k) {
      rhs(k) += w * phi[k + 2] * r;
      for (int l = 0; l < m; ++l) M(k, l) += w * phi[k + 2] * phi[l + 2];
    }
  }
  const Eigen::VectorXd a = M.ldlt().solve(rhs);
  return {a.data(), a.data() + m};
}

}  // namespace hpcontact::model
