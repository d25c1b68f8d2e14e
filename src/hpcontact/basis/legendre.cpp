// Legendre polynomials, integrated Legendre polynomials and the 1D hierarchic basis by recursion.
#include "hpcontact/basis/legendre.hpp"

#include <cmath>

#include "hpcontact/core/error.hpp"

namespace hpcontact::basis {

void legendre(int n_max, double x, double* L, double* dL) {
  HPC_ASSERT(n_max >= 0, "legendre: n_max must be >= 0 (got ", n_max, ")");
  L[0] = 1.0;
  if (dL) dL[0] = 0.0;
  if (n_max == 0) return;
  L[1] = x;
  if (dL) dL[1] = 1.0;
  // Bonnet (eq. 2.64): n L_n = (2n-1) x L_{n-1} - (n-1) L_{n-2}.
  // Derivative from L'_n - L'_{n-2} = (2n-1) L_{n-1}; the alternative
  // L'_n = n (x L_n - L_{n-1}) / (x^2 - 1) is singular at x = +-1.
  for (int n = 2; n <= n_max; ++n) {
    L[n] = ((2 * n - 1) * x * L[n - 1] - (n - 1) * L[n - 2]) / n;
    if (dL) dL[n] = dL[n - 2] + (2 * n - 1) * L[n - 1];
  }
}

double integrated_legendre(int j, double x) {
  HPC_ASSERT(j >= 2, "integrated_legendre: j must be >= 2 (got ", j, ")");
  // Bonnet's recursion (eq. 2.64) up to L_j; on exit L_km2 = L_{j-2}, L_k = L_j.
  double L_km2 = 1.0;  // L_{k-2}
  double L_km1 = x;    // L_{k-1}
  double L_k = x;
  for (int k = 2; k <= j; ++k) {
    if (k > 2) {
      L_km2 = L_km1;
      L_km1 = L_k;
    }
    L_k = ((2 * k - 1) * x * L_km1 - (k - 1) * L_km2) / k;
  }
  // (eq. 2.62) phi_j = (L_j - L_{j-2}) / sqrt(4j - 2).
  return (L_k - L_km2) / std::sqrt(4.0 * j - 2.0);
}

void hierarchic_1d(int p, double xi, double* N, double* dN) {
  HPC_ASSERT(p >= 1, "hierarchic_1d: p must be >= 1 (got ", p, ")");
  // Nodal modes (eq. 2.57, 2.58).
  N[0] = 0.5 * (1.0 - xi);
  N[1] = 0.5 * (1.0 + xi);
  if (dN) {
    dN[0] = -0.5;
    dN[1] = 0.5;
  }
  // Bubble modes N[k] = phi_k (eq. 2.59, 2.62): phi_k = (L_k - L_{k-2}) / sqrt(4k-2) and
  // phi_k' = sqrt((2k-1)/2) L_{k-1}, with L from Bonnet's recursion (eq. 2.64).
  double L_km2 = 1.0;  // L_{k-2}
  double L_km1 = xi;   // L_{k-1}
  for (int k = 2; k <= p; ++k) {
    const double L_k = ((2 * k - 1) * xi * L_km1 - (k - 1) * L_km2) / k;
    N[k] = (L_k - L_km2) / std::sqrt(4.0 * k - 2.0);
    if (dN) dN[k] = std::sqrt(0.5 * (2 * k - 1)) * L_km1;
    L_km2 = L_km1;
    L_km1 = L_k;
  }
}

}  // namespace hpcontact::basis
