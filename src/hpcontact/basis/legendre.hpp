// Legendre polynomials L_n and the integrated Legendre polynomials phi_j of the p-version.
#pragma once

namespace hpcontact::basis {

/// L_0..L_n_max at x (Bonnet's recursion, seed eq. 2.64) and their derivatives.
/// L and dL must have room for n_max + 1 values; dL may be null.
void legendre(int n_max, double x, double* L, double* dL);

/// phi_j(x) = sqrt((2j-1)/2) * int_{-1}^x L_{j-1} = (L_j - L_{j-2}) / sqrt(4j-2), j >= 2 (seed eq. 2.62).
double integrated_legendre(int j, double x);

/// The one-dimensional hierarchic basis of degree p >= 1 at xi in [-1, 1] (seed eq. 2.57–2.59):
/// N[0] = (1 - xi)/2, N[1] = (1 + xi)/2, N[k] = phi_k(xi) for k = 2..p (index k is the degree).
/// N and dN (may be null) must have room for p + 1 values.
void hierarchic_1d(int p, double xi, double* N, double* dN);

}  // namespace hpcontact::basis
