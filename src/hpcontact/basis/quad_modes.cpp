// Hierarchic (p-version) and Lagrange (h-version) shape functions on the reference square.
#include "hpcontact/basis/quad_modes.hpp"

#include <algorithm>
#include <stdexcept>

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/core/error.hpp"

namespace hpcontact::basis {

namespace {

/// Calls put(i, j, sign) for every mode of h in mode order: the mode is sign · a_i(xi) b_j(eta)
/// with the 1D hierarchic functions a, b (index 0: (1 − t)/2, 1: (1 + t)/2, k ≥ 2: phi_k).
template <class Put>
void each_mode(const HierarchicQuad& h, Put&& put) {
  // Vertex modes (eq. 2.67): (1/4)(1 + xi_i xi)(1 + eta_i eta), V1..V4 counter-clockwise.
  put(0, 0, 1.0);
  put(1, 0, 1.0);
  put(1, 1, 1.0);
  put(0, 1, 1.0);

  // Edge modes (eq. 2.68–2.71); with a reversed edge, phi_k(-t) = (-1)^k phi_k(t) flips odd k.
  auto sign = [&h](int e, int k) { return (h.edge_reversed[e] && k % 2 == 1) ? -1.0 : 1.0; };
  for (int k = 2; k <= h.edge_degree[0]; ++k) put(k, 0, sign(0, k));  // E1: phi_k(xi)(1 - eta)/2
  for (int k = 2; k <= h.edge_degree[1]; ++k) put(1, k, sign(1, k));  // E2: (1 + xi)/2 phi_k(eta)
  for (int k = 2; k <= h.edge_degree[2]; ++k) put(k, 1, sign(2, k));  // E3: phi_k(xi)(1 + eta)/2
  for (int k = 2; k <= h.edge_degree[3]; ++k) put(0, k, sign(3, k));  // E4: (1 - xi)/2 phi_k(eta)

  // Internal modes (eq. 2.72): phi_i(xi) phi_j(eta); the trunk space keeps i + j <= p_max.
  const bool trunk = h.space == Space::trunk;
  const int p_max = std::max(h.p_xi, h.p_eta);
  for (int i = 2; i <= h.p_xi; ++i)
    for (int j = 2; j <= h.p_eta && !(trunk && i + j > p_max); ++j) put(i, j, 1.0);
}

}  // namespace

int HierarchicQuad::n_internal_modes() const {
  if (space == Space::tensor_product) return (p_xi - 1) * (p_eta - 1);
  // Trunk space: phi_i(xi) phi_j(eta) with 2 <= i <= p_xi, 2 <= j <= p_eta, i + j <= p.
  const int p = std::max(p_xi, p_eta);
  int count = 0;
  for (int i = 2; i <= p_xi; ++i) count += std::max(0, std::min(p_eta, p - i) - 1);
  return count;
}

int HierarchicQuad::n_modes() const {
  int n = 4 + n_internal_modes();
  for (int e = 0; e < 4; ++e) n += n_edge_modes(e);
  return n;
}

std::vector<std::array<int, 2>> HierarchicQuad::mode_indices() const {
  std::vector<std::array<int, 2>> ij;
  ij.reserve(n_modes());
  each_mode(*this, [&](int i, int j, double) { ij.push_back({i, j}); });
  return ij;
}

void HierarchicQuad::evaluate(double xi, double eta, double* N, double* dN_dxi,
                              double* dN_deta) const {
  // Always checked, not only in debug builds: a degree outside these bounds would read 1D values
  // below that were never computed (a silent wrong basis), and the check is five comparisons
  // against the O(p²) work of an evaluation.
  HPC_REQUIRE(p_xi >= 1 && p_eta >= 1, std::logic_error,
              "HierarchicQuad: degrees must be >= 1 (got p_xi = ", p_xi, ", p_eta = ", p_eta, ")");
  for (int e = 0; e < 4; ++e) {
    const int own = (e % 2 == 0) ? p_xi : p_eta;  // E1, E3 along xi; E2, E4 eta
    HPC_REQUIRE(edge_degree[e] >= 1 && edge_degree[e] <= own, std::logic_error,
                "HierarchicQuad: edge_degree[", e, "] = ", edge_degree[e], " must lie in [1, ", own,
                "]");
  }

  // Every mode is a product a[i](xi) b[j](eta) of 1D hierarchic functions (eq. 2.57–2.59):
  // index 0 is (1 - t)/2, index 1 is (1 + t)/2, index k >= 2 is phi_k(t). Evaluate both 1D
  // bases once, on the stack for the degrees met in practice.
  constexpr int stack_degree = 31;
  const int p_max = std::max(p_xi, p_eta);
  std::array<double, 4 * (stack_degree + 1)> stack_buffer;
  std::vector<double> heap_buffer;
  double* a = stack_buffer.data();
  if (p_max > stack_degree) {
    heap_buffer.resize(4 * (p_max + 1));
    a = heap_buffer.data();
  }
  double* da = a + (p_max + 1);
  double* b = da + (p_max + 1);
  double* db = b + (p_max + 1);
  hierarchic_1d(p_xi, xi, a, da);
  hierarchic_1d(p_eta, eta, b, db);

  int m = 0;
  each_mode(*this, [&](int i, int j, double sign) {
    N[m] = sign * a[i] * b[j];
    if (dN_dxi) dN_dxi[m] = sign * da[i] * b[j];
    if (dN_deta) dN_deta[m] = sign * a[i] * db[j];
    ++m;
  });

  HPC_ASSERT(m == n_modes(), "HierarchicQuad: wrote ", m, " modes, expected ", n_modes());
}

namespace {

/// Reference coordinates of the Lagrange nodes: V1..V4, mid-edges of E1..E4, centre.
constexpr std::array<std::array<double, 2>, 9> lagrange_node_table{{
    {-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0},  // vertices
    {0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0},    // mid-edge nodes of E1..E4
    {0.0, 0.0},                                          // centre (Q9 only)
}};

/// 1D quadratic Lagrange function of the node at c in {-1, 0, 1}, and its derivative, at t.
void quadratic_1d(double c, double t, double& l, double& dl) {
  if (c < 0.0) {
    l = 0.5 * t * (t - 1.0);
    dl = t - 0.5;
  } else if (c > 0.0) {
    l = 0.5 * t * (t + 1.0);
    dl = t + 0.5;
  } else {
    l = 1.0 - t * t;
    dl = -2.0 * t;
  }
}

}  // namespace

int lagrange_n_nodes(LagrangeType type) {
  switch (type) {
    case LagrangeType::q4: return 4;
    case LagrangeType::q8: return 8;
    case LagrangeType::q9: return 9;
  }
  HPC_REQUIRE(false, InputError, "lagrange_n_nodes: unknown LagrangeType ",
              static_cast<int>(type));
  return 0;
}

void lagrange_evaluate(LagrangeType type, double xi, double eta, double* N, double* dN_dxi,
                       double* dN_deta) {
  const int n = lagrange_n_nodes(type);
  for (int i = 0; i < n; ++i) {
    const double xi_i = lagrange_node_table[i][0];
    const double eta_i = lagrange_node_table[i][1];
    const double s = 1.0 + xi_i * xi;    // 1 + xi_i xi
    const double t = 1.0 + eta_i * eta;  // 1 + eta_i eta
    double value = 0.0, d_xi = 0.0, d_eta = 0.0;
    switch (type) {
      case LagrangeType::q4:
        // Bilinear: N_i = (1/4)(1 + xi_i xi)(1 + eta_i eta).
        value = 0.25 * s * t;
        d_xi = 0.25 * xi_i * t;
        d_eta = 0.25 * eta_i * s;
        break;
      case LagrangeType::q8:
        if (i < 4) {
          // Serendipity corner: N_i = (1/4)(1 + xi_i xi)(1 + eta_i eta)(xi_i xi + eta_i eta - 1).
          value = 0.25 * s * t * (xi_i * xi + eta_i * eta - 1.0);
          d_xi = 0.25 * xi_i * t * (2.0 * xi_i * xi + eta_i * eta);
          d_eta = 0.25 * eta_i * s * (xi_i * xi + 2.0 * eta_i * eta);
        } else if (xi_i == 0.0) {
          // Mid-edge of E1 or E3: N_i = (1/2)(1 - xi^2)(1 + eta_i eta).
          value = 0.5 * (1.0 - xi * xi) * t;
          d_xi = -xi * t;
          d_eta = 0.5 * eta_i * (1.0 - xi * xi);
        } else {
          // Mid-edge of E2 or E4: N_i = (1/2)(1 + xi_i xi)(1 - eta^2).
          value = 0.5 * s * (1.0 - eta * eta);
          d_xi = 0.5 * xi_i * (1.0 - eta * eta);
          d_eta = -eta * s;
        }
        break;
      case LagrangeType::q9: {
        // Tensor product of 1D quadratic Lagrange functions on the nodes -1, 0, 1.
        double lx, dlx, ly, dly;
        quadratic_1d(xi_i, xi, lx, dlx);
        quadratic_1d(eta_i, eta, ly, dly);
        value = lx * ly;
        d_xi = dlx * ly;
        d_eta = lx * dly;
        break;
      }
    }
    N[i] = value;
    if (dN_dxi) dN_dxi[i] = d_xi;
    if (dN_deta) dN_deta[i] = d_eta;
  }
}

std::vector<std::array<double, 2>> lagrange_nodes(LagrangeType type) {
  const int n = lagrange_n_nodes(type);
  return {lagrange_node_table.begin(), lagrange_node_table.begin() + n};
}

}  // namespace hpcontact::basis
