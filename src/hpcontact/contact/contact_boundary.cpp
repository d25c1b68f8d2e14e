// Contact points: only the modes of the edge's two vertices and the edge itself are non-zero on
// it, so each point keeps p + 1 modes instead of the element's (p + 1)².
#include "hpcontact/contact/contact_boundary.hpp"

#include <map>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/fem/edge_load.hpp"

namespace hpcontact::contact {

std::vector<ContactPoint> contact_points_at(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                            const std::vector<mesh::ElementMap>& maps, int e,
                                            int edge_index, const std::vector<double>& ts,
                                            const std::vector<double>& ws, const fem::OutOfPlane& thickness) {
  const auto& edge = mesh.edge(e);
  HPC_REQUIRE(edge.on_boundary(), InputError, mesh.context(), ": contact edge ",
              mesh.node_id(edge.v0), "-", mesh.node_id(edge.v1), " is not on the boundary");
  const int q = edge.quads[0], le = edge.local_edge[0];
  const auto& es = dofs.element(q);
  const int n = es.n_modes();
  Eigen::VectorXd N(n);
  // Which local modes live on this edge: evaluate at an interior point of the edge.
  std::vector<int> local;
  {
    const auto r = fem::edge_reference_point(le, 0.123456789);
    es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
    for (int a = 0; a < n; ++a)
      if (N(a) != 0.0) local.push_back(a);
  }
  std::vector<ContactPoint> points;
  for (size_t i = 0; i < ts.size(); ++i) {
    ContactPoint cp;
    cp.element = q;
    cp.local_edge = le;
    cp.edge = edge_index;
    cp.t = ts[i];
    double ds_dt;
    cp.X = fem::edge_geometry(maps[q], le, cp.t, &cp.normal, &ds_dt);
    cp.weight = ws[i] * ds_dt * thickness.at(cp.X);
    const auto r = fem::edge_reference_point(le, cp.t);
    es.evaluate(r[0], r[1], N.data(), nullptr, nullptr);
    cp.N.resize(local.size());
    for (size_t k = 0; k < local.size(); ++k) {
      cp.modes.push_back(es.modes[local[k]]);
      cp.N(k) = N(local[k]);
    }
    points.push_back(std::move(cp));
  }
  return points;
}

std::vector<ContactPoint> contact_points(const mesh::Mesh& mesh, const fem::DofMap& dofs,
                                         const std::vector<mesh::ElementMap>& maps,
                                         const std::vector<int>& edges, int n_points,
                                         const fem::OutOfPlane& thickness) {
  const auto& rule = basis::gauss_legendre(n_points);
  std::vector<ContactPoint> points;
  for (size_t k = 0; k < edges.size(); ++k) {
    auto pts = contact_points_at(mesh, dofs, maps, edges[k], static_cast<int>(k), rule.points,
                                 rule.weights, thickness);
    points.insert(points.end(), pts.begin(), pts.end());
  }
  return points;
}

std::vector<ChainEdge> chain_edges(const mesh::Mesh& m, const std::vector<int>& edges) {
  std::map<int, std::vector<int>> at_node;  // vertex -> positions in `edges`
  for (size_t k = 0; k < edges.size(); ++k)
    for (int v : {m.edge(edges[k]).v0, m.edge(edges[k]).v1}) at_node[v].push_back(static_cast<int>(k));
  std::vector<bool> used(edges.size(), false);
  std::vector<ChainEdge> chain;
  auto walk = [&](int k, int from) {
    const size_t first = chain.size();
    while (k >= 0 && !used[k]) {
      used[k] = true;
      const auto& e = m.edge(edges[k]);
      ChainEdge ce;
      ce.edge = edges[k];
      ce.start = from;
      ce.end = e.v0 == from ? e.v1 : e.v0;
      ce.continues = chain.size() > first;
      // Local edge parameters run from the element's local vertex kEdgeVertices[le][0].
      const int q = e.quads[0], le = e.local_edge[0];
      ce.against = m.quad(q)[mesh::kEdgeVertices[le][0]] != ce.start;
      chain.push_back(ce);
      int next = -1;
      for (int j : at_node[ce.end])
        if (!used[j]) next = j;
      k = next;
      from = ce.end;
    }
    // A closed loop: its last edge ends where the first one starts.
    if (chain.size() > first + 1 && chain.back().end == chain[first].start) chain.back().closes = true;
  };
  // Chains start at a vertex of one edge; what is left are closed loops.
  for (const auto& [v, ks] : at_node)
    if (ks.size() == 1 && !used[ks[0]]) walk(ks[0], v);
  for (size_t k = 0; k < edges.size(); ++k)
    if (!used[k]) walk(static_cast<int>(k), m.edge(edges[k]).v0);
  return chain;
}

}  // namespace hpcontact::contact
