// Mode numbering with the minimum rule on shared edges and orientation signs for odd edge modes.
#include "hpcontact/fem/dof_map.hpp"

#include <algorithm>

#include "hpcontact/core/error.hpp"

namespace hpcontact::fem {

int ElementSpace::max_degree() const {
  if (!is_lagrange) return std::max(hierarchic.p_xi, hierarchic.p_eta);
  return lagrange_type == basis::LagrangeType::q4 ? 1 : 2;
}

void ElementSpace::evaluate(double xi, double eta, double* N, double* dN_dxi,
                            double* dN_deta) const {
  if (is_lagrange)
    basis::lagrange_evaluate(lagrange_type, xi, eta, N, dN_dxi, dN_deta);
  else
    hierarchic.evaluate(xi, eta, N, dN_dxi, dN_deta);
}

DofMap::DofMap(const mesh::Mesh& mesh, const SpaceOptions& options) : lagrange_(options.lagrange) {
  const int nq = mesh.n_quads();
  if (!lagrange_) {
    HPC_REQUIRE(static_cast<int>(options.degrees.size()) == nq, InputError, mesh.context(),
                ": one polynomial degree per element is needed");
    for (int q = 0; q < nq; ++q) {
      const auto& p = options.degrees[q];
      HPC_REQUIRE(p[0] >= 1 && p[1] >= 1, InputError, mesh.context(), ": element ",
                  mesh.quad_id(q), ": polynomial degrees must be >= 1 (got ", p[0], ", ", p[1], ")");
    }
  }
  // Vertex modes: one per node used by an element.
  vertex_mode_.assign(mesh.n_nodes(), -1);
  for (int q = 0; q < nq; ++q)
    for (int v : mesh.quad(q))
      if (vertex_mode_[v] < 0) vertex_mode_[v] = n_modes_++;

  // Edge degrees: the minimum over the adjacent elements of their degree along the edge.
  edge_degree_.assign(mesh.n_edges(), 1);
  edge_first_mode_.assign(mesh.n_edges(), -1);
  for (int e = 0; e < mesh.n_edges(); ++e) {
    const auto& edge = mesh.edge(e);
    int p = 1 << 30;
    for (int s = 0; s < 2; ++s) {
      if (edge.quads[s] < 0) continue;
      int pe;
      if (lagrange_) {
        pe = options.lagrange_type == basis::LagrangeType::q4 ? 1 : 2;
      } else {
        const auto& deg = options.degrees[edge.quads[s]];
        pe = (edge.local_edge[s] % 2 == 0) ? deg[0] : deg[1];  // E1, E3 run along xi
      }
      p = std::min(p, pe);
    }
    edge_degree_[e] = p;
    edge_first_mode_[e] = n_modes_;
    n_modes_ += p - 1;
  }
  n_external_modes_ = n_modes_;

  // Element spaces and internal modes.
  elements_.resize(nq);
  for (int q = 0; q < nq; ++q) {
    ElementSpace& es = elements_[q];
    es.is_lagrange = lagrange_;
    if (lagrange_) {
      es.lagrange_type = options.lagrange_type;
    } else {
      es.hierarchic.p_xi = options.degrees[q][0];
      es.hierarchic.p_eta = options.degrees[q][1];
      es.hierarchic.space = options.space;
      for (int le = 0; le < 4; ++le) {
        es.hierarchic.edge_degree[le] = edge_degree_[mesh.quad_edge(q, le)];
        es.hierarchic.edge_reversed[le] = mesh.quad_edge_reversed(q, le);
      }
    }
    for (int v : mesh.quad(q)) es.modes.push_back(vertex_mode_[v]);
    for (int le = 0; le < 4; ++le) {
      const int e = mesh.quad_edge(q, le);
      for (int k = 2; k <= edge_degree_[e]; ++k) es.modes.push_back(edge_mode(e, k));
    }
    es.n_internal = lagrange_ ? (options.lagrange_type == basis::LagrangeType::q9 ? 1 : 0)
                              : es.hierarchic.n_internal_modes();
    for (int i = 0; i < es.n_internal; ++i) es.modes.push_back(n_modes_++);
  }
}

}  // namespace hpcontact::fem
