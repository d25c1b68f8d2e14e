// The stick–slip points of an exactly enforced pair with Coulomb friction: where the friction
// state changes between neighbouring active multiplier nodes (docs/theory.md §8a).
#include "hpcontact/model/stick_slip_points.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/core/roots.hpp"
#include "hpcontact/model/boundary_point.hpp"
#include "hpcontact/model/contact_zone_ends.hpp"

namespace hpcontact::model {

ZoneEnds stick_slip_points(const Body& body, const ContactPair& pair,
                           const std::vector<ContactResult::Node>& nodes, const Eigen::VectorXd& u,
                           const Eigen::VectorXd& lambda, const Eigen::VectorXd& lambda_t,
                           const Eigen::VectorXd& slips) {
  const PairConstraints& c = *pair.constraints;
  const double zero = 1e-8 * c.friction.mu * std::max(lambda.maxCoeff(), 0.0);
  ZoneEnds z;
  for (size_t k = 0; k < c.nodes.edge_nodes.size(); ++k) {
    const auto& en = c.nodes.edge_nodes[k];
    const auto& edge = body.mesh.edge(pair.edges[k]);
    const double kappa = edge_stiffness(body, edge, static_cast<int>(en.size()) - 1);
    const int e = static_cast<int>(k);
    auto psi = [&](double t) {
      return std::abs(c.nodes.interpolate(e, t, lambda_t) + kappa * c.nodes.interpolate(e, t, slips)) -
             c.friction.mu * c.nodes.interpolate(e, t, lambda);
    };
    for (size_t i = 0; i + 1 < en.size(); ++i) {
      if (!nodes[en[i]].active || !nodes[en[i + 1]].active) continue;
      const double ta = c.nodes.edge_points[k][i], tb = c.nodes.edge_points[k][i + 1];
      const double fa = psi(ta), fb = psi(tb);
      if ((fa < -zero) == (fb < -zero)) continue;
      const double t_point = std::abs(fa) <= zero   ? ta
                             : std::abs(fb) <= zero ? tb
                                                    : pegasus_root(psi, ta, tb, fa, fb, 1e-14);
      const auto [X, x] = boundary_position(body, edge.quads[0], edge.local_edge[0], t_point, u);
      z.X.push_back(X);
      z.x.push_back(x);
    }
  }
  return z;
}


}  // namespace hpcontact::model
