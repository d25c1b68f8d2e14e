// Hierarchic shape functions on the reference cube: products of 1D hierarchic functions.
#include "hpcontact/basis/hex_modes.hpp"

#include <algorithm>
#include <stdexcept>

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::basis {

namespace {

/// 1D factor index of the linear function that is 1 at reference coordinate c in {-1, 1}.
int linear_index(int c) { return c > 0 ? 1 : 0; }

/// Calls put({i, j, k}, sign) for every mode of h in mode order: the mode is
/// sign · a_i(xi) b_j(eta) c_k(zeta) (index 0: (1 − t)/2, 1: (1 + t)/2, k ≥ 2: phi_k).
template <class Put>
void each_mode(const HierarchicHex& h, Put&& put) {
  // Vertex modes: the trilinear (1/8)(1 + xi_v xi)(1 + eta_v eta)(1 + zeta_v zeta), V0..V7.
  for (const auto& x : kHexVertexCoordinates)
    put({linear_index(x[0]), linear_index(x[1]), linear_index(x[2])}, 1.0);

  // Edge modes: phi_k along the edge's axis times the linear factors of the two other axes that
  // are 1 on the edge (read at the edge's first vertex). A reversed edge flips odd k.
  for (int e = 0; e < 12; ++e) {
    const int* x = kHexVertexCoordinates[kHexEdgeVertices[e][0]];
    std::array<int, 3> index{linear_index(x[0]), linear_index(x[1]), linear_index(x[2])};
    for (int k = 2; k <= h.edge_degree[e]; ++k) {
      index[kHexEdgeAxis[e]] = k;
      put(index, (h.edge_reversed[e] && k % 2 == 1) ? -1.0 : 1.0);
    }
  }

  // Face modes: phi_i(S) phi_j(T) times the linear factor of the normal axis that is 1 on the face,
  // in the face's global axes. With S = ±(swap ? t : s), T = ±(swap ? s : t), the factor
  // phi_i(S) is ± phi_i of the local coordinate t (swap) or s, the sign (-1)^i where S runs
  // against it; likewise phi_j(T).
  const bool trunk = h.space == Space::trunk;
  for (int f = 0; f < 6; ++f) {
    const HexFaceOrientation& o = h.face_orientation[f];
    const int axis_s = kHexFaceAxes[f][0], axis_t = kHexFaceAxes[f][1];
    const int p_s = h.face_degree[f][0], p_t = h.face_degree[f][1];
    const int p_1 = o.swap ? p_t : p_s, p_2 = o.swap ? p_s : p_t;  // degrees along S, T
    const int p_face = std::max(p_1, p_2);
    std::array<int, 3> index{};
    index[kHexFaceNormalAxis[f]] = f % 2;  // 0 on the face at -1 (even f), 1 at +1 (odd f)
    for (int i = 2; i <= p_1; ++i)
      for (int j = 2; j <= p_2 && !(trunk && i + j > p_face); ++j) {
        index[axis_s] = o.swap ? j : i;
        index[axis_t] = o.swap ? i : j;
        const bool negative = (o.flip1 && i % 2 == 1) != (o.flip2 && j % 2 == 1);
        put(index, negative ? -1.0 : 1.0);
      }
  }

  // Internal modes phi_i(xi) phi_j(eta) phi_k(zeta); the trunk space keeps i + j + k <= p_max.
  const int p_max = std::max({h.p[0], h.p[1], h.p[2]});
  for (int i = 2; i <= h.p[0]; ++i)
    for (int j = 2; j <= h.p[1]; ++j)
      for (int k = 2; k <= h.p[2] && !(trunk && i + j + k > p_max); ++k) put({i, j, k}, 1.0);
}

}  // namespace

int hex_face_mode_count(int p_1, int p_2, Space space) {
  // The face modes of a hex are, in count and order, the internal modes of a quad of the face's
  // degrees (quad_modes.hpp: i outer, j inner, trunk i + j <= max).
  HierarchicQuad quad;
  quad.p_xi = p_1;
  quad.p_eta = p_2;
  quad.space = space;
  return quad.n_internal_modes();
}

int HierarchicHex::n_face_modes(int f) const {
  return hex_face_mode_count(face_degree[f][0], face_degree[f][1], space);
}

int HierarchicHex::n_internal_modes() const {
  if (space == Space::tensor_product) return (p[0] - 1) * (p[1] - 1) * (p[2] - 1);
  const int p_max = std::max({p[0], p[1], p[2]});
  int count = 0;
  for (int i = 2; i <= p[0]; ++i)
    for (int j = 2; j <= p[1]; ++j) count += std::max(0, std::min(p[2], p_max - i - j) - 1);
  return count;
}

int HierarchicHex::n_modes() const {
  int n = 8 + n_internal_modes();
  for (int e = 0; e < 12; ++e) n += n_edge_modes(e);
  for (int f = 0; f < 6; ++f) n += n_face_modes(f);
  return n;
}

std::vector<std::array<int, 3>> HierarchicHex::mode_indices() const {
  std::vector<std::array<int, 3>> ijk;
  ijk.reserve(n_modes());
  each_mode(*this, [&](const std::array<int, 3>& index, double) { ijk.push_back(index); });
  return ijk;
}

std::vector<double> HierarchicHex::mode_signs() const {
  std::vector<double> signs;
  signs.reserve(n_modes());
  each_mode(*this, [&](const std::array<int, 3>&, double sign) { signs.push_back(sign); });
  return signs;
}

void HierarchicHex::evaluate(double xi, double eta, double zeta, double* N, double* dN_dxi,
                             double* dN_deta, double* dN_dzeta) const {
  // Always checked, as for the quad: a degree out of range would read 1D values that were never
  // computed (a silent wrong basis), and the checks cost nothing against the O(p³) evaluation.
  HPC_REQUIRE(p[0] >= 1 && p[1] >= 1 && p[2] >= 1, std::logic_error,
              "HierarchicHex: degrees must be >= 1 (got p = ", p[0], ", ", p[1], ", ", p[2], ")");
  for (int e = 0; e < 12; ++e) {
    const int own = p[kHexEdgeAxis[e]];
    HPC_REQUIRE(edge_degree[e] >= 1 && edge_degree[e] <= own, std::logic_error,
                "HierarchicHex: edge_degree[", e, "] = ", edge_degree[e], " must lie in [1, ", own,
                "]");
  }
  for (int f = 0; f < 6; ++f)
    for (int a = 0; a < 2; ++a) {
      const int own = p[kHexFaceAxes[f][a]];
      HPC_REQUIRE(face_degree[f][a] >= 1 && face_degree[f][a] <= own, std::logic_error,
                  "HierarchicHex: face_degree[", f, "][", a, "] = ", face_degree[f][a],
                  " must lie in [1, ", own, "]");
    }

  // The 1D hierarchic functions (seed eq. 2.57–2.59) and their derivatives along each axis,
  // evaluated once; on the stack for the degrees met in practice.
  constexpr int stack_degree = 31;
  const int p_max = std::max({p[0], p[1], p[2]});
  std::array<double, 6 * (stack_degree + 1)> stack_buffer;
  std::vector<double> heap_buffer;
  double* buffer = stack_buffer.data();
  if (p_max > stack_degree) {
    heap_buffer.resize(6 * (p_max + 1));
    buffer = heap_buffer.data();
  }
  const int stride = p_max + 1;
  double* a = buffer;
  double* da = a + stride;
  double* b = da + stride;
  double* db = b + stride;
  double* c = db + stride;
  double* dc = c + stride;
  hierarchic_1d(p[0], xi, a, da);
  hierarchic_1d(p[1], eta, b, db);
  hierarchic_1d(p[2], zeta, c, dc);

  int m = 0;
  each_mode(*this, [&](const std::array<int, 3>& index, double sign) {
    const auto [i, j, k] = index;
    N[m] = sign * a[i] * b[j] * c[k];
    if (dN_dxi) dN_dxi[m] = sign * da[i] * b[j] * c[k];
    if (dN_deta) dN_deta[m] = sign * a[i] * db[j] * c[k];
    if (dN_dzeta) dN_dzeta[m] = sign * a[i] * b[j] * dc[k];
    ++m;
  });

  HPC_ASSERT(m == n_modes(), "HierarchicHex: wrote ", m, " modes, expected ", n_modes());
}

HierarchicHex hierarchic_hex(std::array<int, 3> p, Space space) {
  HierarchicHex h;
  h.p = p;
  h.space = space;
  for (int e = 0; e < 12; ++e) h.edge_degree[e] = p[kHexEdgeAxis[e]];
  for (int f = 0; f < 6; ++f) h.face_degree[f] = {p[kHexFaceAxes[f][0]], p[kHexFaceAxes[f][1]]};
  return h;
}

}  // namespace hpcontact::basis
