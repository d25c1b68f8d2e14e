// Multiplier nodes along chains of contact edges, and the Lagrange polynomials of each edge's
// Gauss–Lobatto points.
#include "hpcontact/contact/multiplier_nodes.hpp"

#include <algorithm>
#include <cmath>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/edge_load.hpp"

namespace hpcontact::contact {

void MultiplierNodes::shape(int k, double t, Eigen::VectorXd& L) const {
  const auto& tp = edge_points[k];
  const int n = static_cast<int>(tp.size());
  L.resize(n);
  for (int i = 0; i < n; ++i) {
    double v = 1;
    for (int j = 0; j < n; ++j)
      if (j != i) v *= (t - tp[j]) / (tp[i] - tp[j]);
    L(i) = v;
  }
}

double MultiplierNodes::interpolate(int k, double t, const Eigen::Ref<const Eigen::VectorXd>& lambda) const {
  Eigen::VectorXd L;
  shape(k, t, L);
  double v = 0;
  for (int i = 0; i < L.size(); ++i) v += L(i) * lambda(edge_nodes[k][i]);
  return v;
}

MultiplierNodes multiplier_nodes(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                 const std::vector<mesh::ElementMap>& maps,
                                 const std::vector<ChainEdge>& chain, const fem::OutOfPlane& thickness) {
  MultiplierNodes m;
  const int ne = static_cast<int>(chain.size());
  m.edge_nodes.resize(ne);
  m.edge_points.resize(ne);
  int chain_first_node = -1;  // the first node of the current chain
  for (int k = 0; k < ne; ++k) {
    const ChainEdge& ce = chain[k];
    const int p = std::max(1, dofs.edge_degree(ce.edge));
    const auto& rule = basis::gauss_lobatto(p + 1);
    m.edge_points[k] = rule.points;
    const auto pts = contact_points_at(mesh, dofs, maps, ce.edge, k, rule.points, rule.weights, thickness);
    // Each Lobatto point's share ∫ L_i ds t. The Lobatto rule itself gives it when t is constant
    // (exact for L_i ds/dt); with t = 2π r (axisymmetric) it would give a node on the axis no
    // share at all, so the integral is taken by Gauss–Legendre points.
    std::vector<double> share(p + 1);
    for (int i = 0; i <= p; ++i) share[i] = pts[i].weight;
    if (thickness.axisymmetric) {
      const auto& gauss = basis::gauss_legendre(2 * p + 6);
      const auto gp = contact_points_at(mesh, dofs, maps, ce.edge, k, gauss.points, gauss.weights, thickness);
      std::fill(share.begin(), share.end(), 0.0);
      Eigen::VectorXd L;
      for (const auto& g : gp) {
        m.shape(k, g.t, L);
        for (int i = 0; i <= p; ++i) share[i] += L(i) * g.weight;
      }
    }
    const Vec2 a = mesh.node(mesh.edge(ce.edge).v0), b = mesh.node(mesh.edge(ce.edge).v1);
    const double scale = p * p / std::max((a - b).norm(), 1e-300);
    std::vector<int>& nodes = m.edge_nodes[k];
    nodes.assign(p + 1, -1);
    // Lobatto point c in the chain's direction is the edge's local point c, or p − c against it.
    for (int c = 0; c <= p; ++c) {
      const int i = ce.against ? p - c : c;
      int node = -1;
      if (c == 0 && ce.continues) {
        const auto& previous = m.edge_nodes[k - 1];
        node = previous[chain[k - 1].against ? 0 : previous.size() - 1];
      } else if (c == p && ce.closes) {
        node = chain_first_node;
      }
      if (node < 0) {
        MultiplierNode mn;
        mn.element = pts[i].element;
        mn.local_edge = pts[i].local_edge;
        mn.edge = k;
        mn.t = pts[i].t;
        mn.X = pts[i].X;
        node = static_cast<int>(m.nodes.size());
        m.nodes.push_back(mn);
        if (c == 0) chain_first_node = node;
      }
      m.nodes[node].weight += share[i];
      m.nodes[node].stiffness_scale = std::max(m.nodes[node].stiffness_scale, scale);
      nodes[i] = node;
    }
  }
  return m;
}

}  // namespace hpcontact::contact
