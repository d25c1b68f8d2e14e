// Hierarchic (p-version) shape functions of the reference hexahedron [-1, 1]^3.
//
//   reference hexahedron, vertices V0..V7 in VTK/Gmsh order, edges E0..E11:
//
//              V7 -----E6----> V6           zeta
//             /|              /|             ^   eta
//           E7 |            E5 |             |  /
//           /  E10          /  E11           | /
//         V4 -----E4----> V5   |             |/
//          |   |           |   |             +------> xi
//          |   V3 -----E2--|-> V2
//         E8  /           E9  /           V0 (-1,-1,-1)  V1 (1,-1,-1)  V2 (1,1,-1)  V3 (-1,1,-1)
//          | E3            | E1           V4..V7: V0..V3 at zeta = +1
//          |/              |/
//         V0 -----E0----> V1
//
//   Every local edge runs along the positive direction of its reference axis (the parameter of
//   the edge is that coordinate), as in the quad (quad_modes.hpp):
//     along xi:   E0 V0->V1, E2 V3->V2, E4 V4->V5, E6 V7->V6
//     along eta:  E1 V1->V2, E3 V0->V3, E5 V5->V6, E7 V4->V7
//     along zeta: E8 V0->V4, E9 V1->V5, E10 V3->V7, E11 V2->V6
//   (VTK's edge order. E0..E3 are the quad's E1..E4 on the bottom face, E4..E7 the same on the
//   top.)
//
//   Faces (VTK and deal.II order) with their local axes (s, t): s is the lower of the two free
//   reference coordinates, t the higher, both along the positive axis; the origin (s, t) =
//   (-1, -1) is the face's vertex with both at -1. Vertices listed as origin, end of s, opposite
//   corner, end of t:
//     F0 xi   = -1: (s, t) = (eta, zeta)  V0 V3 V7 V4
//     F1 xi   = +1: (s, t) = (eta, zeta)  V1 V2 V6 V5
//     F2 eta  = -1: (s, t) = (xi, zeta)   V0 V1 V5 V4
//     F3 eta  = +1: (s, t) = (xi, zeta)   V3 V2 V6 V7
//     F4 zeta = -1: (s, t) = (xi, eta)    V0 V1 V2 V3
//     F5 zeta = +1: (s, t) = (xi, eta)    V4 V5 V6 V7
//   (s x t is the outward normal on F1, F2, F5 and the inward one on F0, F3, F4.)
//
// Orientation. phi_k(-t) = (-1)^k phi_k(t): an edge whose global direction is opposite to the local
// one flips its odd modes. A face's modes are written in the face's GLOBAL axes (S, T) (chosen by
// the mesh from global vertex numbers, mesh/hex_topology.hpp), which are the element's local face
// axes (s, t) possibly swapped and reversed (HexFaceOrientation, 8 cases). Two neighbours that
// follow these rules have identical traces on their common edges and faces.
#pragma once

#include <array>
#include <vector>

#include "hpcontact/basis/quad_modes.hpp"

namespace hpcontact::basis {

/// Reference coordinates of the vertices V0..V7.
inline constexpr int kHexVertexCoordinates[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1},
                                                    {-1, 1, -1},  {-1, -1, 1}, {1, -1, 1},
                                                    {1, 1, 1},    {-1, 1, 1}};

/// Local edge e runs from local vertex kHexEdgeVertices[e][0] to [e][1], along reference axis
/// kHexEdgeAxis[e] (0: xi, 1: eta, 2: zeta), in its positive direction.
inline constexpr int kHexEdgeVertices[12][2] = {{0, 1}, {1, 2}, {3, 2}, {0, 3}, {4, 5}, {5, 6},
                                                {7, 6}, {4, 7}, {0, 4}, {1, 5}, {3, 7}, {2, 6}};
inline constexpr int kHexEdgeAxis[12] = {0, 1, 0, 1, 0, 1, 0, 1, 2, 2, 2, 2};

/// Local face f: its vertices at (s, t) = (-1,-1), (1,-1), (1,1), (-1,1); the reference axes of
/// s and t (kHexFaceAxes[f]); the axis normal to it (kHexFaceNormalAxis[f]), fixed at -1 for
/// even f and +1 for odd f.
inline constexpr int kHexFaceVertices[6][4] = {{0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4},
                                               {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};
inline constexpr int kHexFaceAxes[6][2] = {{1, 2}, {1, 2}, {0, 2}, {0, 2}, {0, 1}, {0, 1}};
inline constexpr int kHexFaceNormalAxis[6] = {0, 0, 1, 1, 2, 2};

/// How a face's global axes (S, T) follow from an element's local face axes (s, t):
///   S = (flip1 ? -1 : 1) * (swap ? t : s),   T = (flip2 ? -1 : 1) * (swap ? s : t).
/// flip1 and flip2 belong to the global axes S and T. The identity is {false, false, false}.
struct HexFaceOrientation {
  bool swap = false;
  bool flip1 = false;
  bool flip2 = false;
  friend bool operator==(const HexFaceOrientation&, const HexFaceOrientation&) = default;
};

/// Number of face modes phi_i(S) phi_j(T), 2 <= i <= p_1, 2 <= j <= p_2 of a face of degrees
/// (p_1, p_2); the trunk space keeps i + j <= max(p_1, p_2). Symmetric in p_1, p_2.
int hex_face_mode_count(int p_1, int p_2, Space space);

/// Hierarchic hexahedron (Szabó–Babuška; the tensor-product extension of seed eq. 2.67–2.72),
/// anisotropic degrees p = {p_xi, p_eta, p_zeta}.
///
/// Every mode is ± a_i(xi) b_j(eta) c_k(zeta) of the 1D hierarchic functions (index 0: (1 − t)/2,
/// 1: (1 + t)/2, k ≥ 2: phi_k; legendre.hpp). Mode order (the index order of every array below):
///   1. the 8 vertex modes V0..V7;
///   2. edge by edge E0..E11, its modes phi_k(edge coordinate) times the two linear factors that
///      are 1 on the edge, k = 2..edge_degree[e];
///   3. face by face F0..F5, its modes phi_i(S) phi_j(T) times the linear factor of the normal
///      coordinate that is 1 on the face, in the face's global axes: i = 2..p_S outer,
///      j = 2..p_T inner, where (p_S, p_T) is face_degree[f] in global order; trunk: i + j <=
///      max(p_S, p_T);
///   4. internal modes phi_i(xi) phi_j(eta) phi_k(zeta), i = 2..p_xi outermost, k innermost;
///      trunk: i + j + k <= max(p_xi, p_eta, p_zeta).
/// The isotropic trunk space of degree p is the serendipity space of superlinear degree p
/// (a monomial's superlinear degree sums only its exponents >= 2), of dimension
/// 8 + 12(p−1) + 3(p−2)(p−3) [faces, p >= 4] + (p−3)(p−4)(p−5)/6 [internal, p >= 6]:
/// 8, 20, 32, 50, 74, 105 for p = 1..6.
struct HierarchicHex {
  std::array<int, 3> p{1, 1, 1};
  Space space = Space::tensor_product;
  /// Degree on each edge (minimum rule); in [1, p[kHexEdgeAxis[e]]].
  std::array<int, 12> edge_degree{1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1};
  /// True where the edge's global direction is opposite to the local one: odd edge modes flip.
  std::array<bool, 12> edge_reversed{};
  /// Degrees of each face along its LOCAL axes (s, t); face_degree[f][a] in [1,
  /// p[kHexFaceAxes[f][a]]].
  std::array<std::array<int, 2>, 6> face_degree{{{1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}, {1, 1}}};
  /// Map of each face's local axes onto its global axes.
  std::array<HexFaceOrientation, 6> face_orientation{};

  int n_edge_modes(int e) const { return edge_degree[e] - 1; }
  int n_face_modes(int f) const;
  int n_internal_modes() const;
  int n_modes() const;

  /// Per mode, in mode order, the indices (i, j, k) of its 1D factors a_i(xi) b_j(eta) c_k(zeta).
  std::vector<std::array<int, 3>> mode_indices() const;
  /// Per mode, in mode order, its sign (±1): the mode is sign · a_i(xi) b_j(eta) c_k(zeta) with
  /// (i, j, k) from mode_indices() (−1 for odd modes of a reversed edge or face axis).
  std::vector<double> mode_signs() const;
  /// Values and reference gradients of all modes at (xi, eta, zeta); each array has n_modes()
  /// entries. The gradient arrays may be null. Throws std::logic_error for degrees out of range.
  void evaluate(double xi, double eta, double zeta, double* N, double* dN_dxi, double* dN_deta,
                double* dN_dzeta) const;
};

/// The element of degrees p with every edge and face at the element's own degree along it, all
/// orientations the identity (a single element, or a mesh with no minimum rule to apply).
HierarchicHex hierarchic_hex(std::array<int, 3> p, Space space);

}  // namespace hpcontact::basis
