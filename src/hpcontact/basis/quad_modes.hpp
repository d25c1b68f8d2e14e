// Shape functions of the reference quadrilateral [-1, 1]^2: hierarchic (p-version) and Lagrange (h-version).
//
//   reference quad, vertices V1..V4 and edges E1..E4 (seed Fig. 2.4):
//
//        V4 ----E3----> V3          local edge directions (the parameter runs along the arrow):
//        ^               ^            E1: V1 -> V2  (xi,  eta = -1)
//        |               |            E2: V2 -> V3  (eta, xi  = +1)
//        E4              E2           E3: V4 -> V3  (xi,  eta = +1)
//        |               |            E4: V1 -> V4  (eta, xi  = -1)
//        V1 ----E1----> V2
//      (-1,-1)         (1,-1)
//
// Odd edge modes: phi_k(-t) = (-1)^k phi_k(t), so when the global direction of an edge is opposite
// to the local one, the edge modes of odd degree k change sign; even ones are unchanged. Two
// neighbours that apply this rule share identical traces on their common edge.
#pragma once

#include <array>
#include <vector>

namespace hpcontact::basis {

enum class Space { tensor_product, trunk };

/// Hierarchic quadrilateral (Szabó–Babuška, seed eq. 2.67–2.72), anisotropic degrees.
///
/// Mode order (the index order of every array below): the 4 vertex modes V1..V4; then for each
/// edge E1..E4 its modes of degree 2..edge_degree[e]; then the internal modes phi_i(xi) phi_j(eta)
/// with i = 2..p_xi outer, j = 2..p_eta inner (tensor product), restricted to i + j <= max(p_xi, p_eta)
/// in the trunk space.
struct HierarchicQuad {
  int p_xi = 1;
  int p_eta = 1;
  Space space = Space::tensor_product;
  /// Degree used on each edge (minimum rule); must not exceed the element's degree along that edge
  /// (p_xi for E1, E3; p_eta for E2, E4).
  std::array<int, 4> edge_degree{1, 1, 1, 1};
  /// True where the global edge direction is opposite to the local one: odd edge modes flip sign.
  std::array<bool, 4> edge_reversed{false, false, false, false};

  int n_edge_modes(int e) const { return edge_degree[e] - 1; }
  int n_internal_modes() const;
  int n_modes() const;

  /// Per mode, in mode order, the indices (i, j) of its 1D factors a_i(xi) b_j(eta) (0: (1 − t)/2,
  /// 1: (1 + t)/2, k ≥ 2: phi_k): what names a mode across spaces of other degrees on one mesh.
  std::vector<std::array<int, 2>> mode_indices() const;
  /// Values and reference gradients of all modes at (xi, eta); each array has n_modes() entries.
  /// dN_dxi, dN_deta may be null.
  void evaluate(double xi, double eta, double* N, double* dN_dxi, double* dN_deta) const;
};

/// Lagrange quadrilaterals of the isoparametric h-version.
enum class LagrangeType { q4, q8, q9 };

/// Node order: vertices V1..V4 counter-clockwise from (-1,-1); for Q8/Q9 the mid-edge nodes of
/// E1 (eta=-1), E2 (xi=1), E3 (eta=1), E4 (xi=-1); for Q9 the centre last. This is the same
/// vertex / edge / internal order as HierarchicQuad, with one mode per edge and at most one internal.
int lagrange_n_nodes(LagrangeType type);

/// Values and reference gradients of the Lagrange shape functions at (xi, eta); Q8 is serendipity.
/// Each array has lagrange_n_nodes(type) entries, in node order; dN_dxi, dN_deta may be null.
void lagrange_evaluate(LagrangeType type, double xi, double eta, double* N, double* dN_dxi,
                       double* dN_deta);

/// Reference coordinates of the Lagrange nodes in the order above.
std::vector<std::array<double, 2>> lagrange_nodes(LagrangeType type);

}  // namespace hpcontact::basis
