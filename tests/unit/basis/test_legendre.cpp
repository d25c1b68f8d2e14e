// Unit tests of Legendre and integrated Legendre polynomials and the 1D hierarchic basis.
#include "hpcontact/basis/legendre.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hpcontact/basis/quadrature.hpp"

namespace hb = hpcontact::basis;

namespace {

const std::vector<double> sample_points{-1.0, -0.93, -0.5, -0.1, 0.0, 0.27, 0.5, 0.81, 1.0};

}  // namespace

// Bonnet's recursion shall reproduce the closed forms of L_0..L_4 and their derivatives.
TEST(Legendre, RecursionMatchesClosedForms) {
  double L[5], dL[5];
  for (double x : sample_points) {
    hb::legendre(4, x, L, dL);
    const double x2 = x * x;
    EXPECT_EQ(L[0], 1.0);
    EXPECT_EQ(L[1], x);
    EXPECT_NEAR(L[2], 0.5 * (3 * x2 - 1), 1e-15);
    EXPECT_NEAR(L[3], 0.5 * (5 * x2 - 3) * x, 1e-15);
    EXPECT_NEAR(L[4], (35 * x2 * x2 - 30 * x2 + 3) / 8, 1e-15);
    EXPECT_EQ(dL[0], 0.0);
    EXPECT_EQ(dL[1], 1.0);
    EXPECT_NEAR(dL[2], 3 * x, 1e-15);
    EXPECT_NEAR(dL[3], 0.5 * (15 * x2 - 3), 1e-14);
    EXPECT_NEAR(dL[4], (140 * x2 * x - 60 * x) / 8, 1e-14);
  }
}

// L_n(+-1) = (+-1)^n and L'_n(+-1) = (+-1)^{n+1} n(n+1)/2: the derivative is regular at +-1.
TEST(Legendre, ValuesAndDerivativesAtEndPoints) {
  constexpr int n_max = 40;
  std::vector<double> L(n_max + 1), dL(n_max + 1);
  for (double x : {-1.0, 1.0}) {
    hb::legendre(n_max, x, L.data(), dL.data());
    for (int n = 0; n <= n_max; ++n) {
      const double sign = (x < 0 && n % 2 == 1) ? -1.0 : 1.0;
      EXPECT_EQ(L[n], sign) << "n = " << n << ", x = " << x;
      EXPECT_EQ(dL[n], sign * x * 0.5 * n * (n + 1)) << "n = " << n << ", x = " << x;
    }
  }
}

// The Legendre polynomials shall be orthogonal with int L_n L_m = 2/(2n+1) delta_nm (eq. 2.65).
TEST(Legendre, OrthogonalityByQuadrature) {
  constexpr int n_max = 20;
  const auto& rule = hb::gauss_legendre(n_max + 1);  // exact to degree 2 n_max + 1
  std::vector<double> L(n_max + 1);
  std::vector<std::vector<double>> gram(n_max + 1, std::vector<double>(n_max + 1, 0.0));
  for (int q = 0; q < rule.size(); ++q) {
    hb::legendre(n_max, rule.points[q], L.data(), nullptr);
    for (int n = 0; n <= n_max; ++n)
      for (int m = 0; m <= n_max; ++m) gram[n][m] += rule.weights[q] * L[n] * L[m];
  }
  // Round-off of a 21-term sum of terms bounded by 2: a few ulps of 2.
  for (int n = 0; n <= n_max; ++n)
    for (int m = 0; m <= n_max; ++m)
      EXPECT_NEAR(gram[n][m], n == m ? 2.0 / (2 * n + 1) : 0.0, 1e-14) << n << ", " << m;
}

// The derivatives shall agree with central finite differences within the truncation bound.
TEST(Legendre, DerivativeMatchesFiniteDifference) {
  constexpr int n_max = 12;
  constexpr double h = 1e-5;
  std::vector<double> L(n_max + 1), dL(n_max + 1), Lp(n_max + 1), Lm(n_max + 1);
  for (double x : sample_points) {
    hb::legendre(n_max, x, L.data(), dL.data());
    hb::legendre(n_max, x + h, Lp.data(), nullptr);
    hb::legendre(n_max, x - h, Lm.data(), nullptr);
    for (int n = 0; n <= n_max; ++n) {
      // Truncation h^2/6 max|L'''| with max|L'''_n| = L'''_n(1) = (n-2)...(n+3)/48 on [-1, 1]
      // (doubled for the step past the end points), plus round-off eps/h.
      const double d3_max = (n - 2.0) * (n - 1) * n * (n + 1) * (n + 2) * (n + 3) / 48.0;
      const double tol = 2.0 * h * h / 6.0 * std::max(d3_max, 0.0) + 1e-10;
      EXPECT_NEAR(dL[n], (Lp[n] - Lm[n]) / (2 * h), tol) << "n = " << n << ", x = " << x;
    }
  }
}

// phi_j(x) shall equal sqrt((2j-1)/2) int_{-1}^x L_{j-1} (eq. 2.62), checked by Gauss quadrature.
TEST(IntegratedLegendre, EqualsIntegralOfLegendre) {
  for (int j = 2; j <= 20; ++j) {
    const auto& rule = hb::gauss_legendre(j);  // exact to degree 2j - 1 >= j - 1
    std::vector<double> L(j);
    for (double x : sample_points) {
      // Map the rule from [-1, 1] onto [-1, x].
      double integral = 0.0;
      for (int q = 0; q < rule.size(); ++q) {
        const double t = -1.0 + 0.5 * (rule.points[q] + 1.0) * (x + 1.0);
        hb::legendre(j - 1, t, L.data(), nullptr);
        integral += 0.5 * (x + 1.0) * rule.weights[q] * L[j - 1];
      }
      EXPECT_NEAR(hb::integrated_legendre(j, x), std::sqrt(0.5 * (2 * j - 1)) * integral, 1e-14)
          << "j = " << j << ", x = " << x;
    }
  }
}

// phi_j shall vanish at both end points (eq. 2.60) and have parity phi_j(-x) = (-1)^j phi_j(x).
TEST(IntegratedLegendre, VanishesAtEndPointsAndHasParity) {
  for (int j = 2; j <= 40; ++j) {
    EXPECT_NEAR(hb::integrated_legendre(j, -1.0), 0.0, 1e-15) << "j = " << j;
    EXPECT_NEAR(hb::integrated_legendre(j, 1.0), 0.0, 1e-15) << "j = " << j;
    const double parity = j % 2 == 0 ? 1.0 : -1.0;
    for (double x : sample_points)
      EXPECT_NEAR(hb::integrated_legendre(j, -x), parity * hb::integrated_legendre(j, x), 1e-15)
          << "j = " << j << ", x = " << x;
  }
}

// hierarchic_1d shall return the two linear modes and phi_2..phi_p with derivatives
// phi_k' = sqrt((2k-1)/2) L_{k-1} (eq. 2.57–2.59, 2.62).
TEST(Hierarchic1D, ModesAndDerivatives) {
  constexpr int p = 15;
  std::vector<double> N(p + 1), dN(p + 1), N_only(p + 1), L(p + 1);
  for (double xi : sample_points) {
    hb::hierarchic_1d(p, xi, N.data(), dN.data());
    hb::hierarchic_1d(p, xi, N_only.data(), nullptr);
    hb::legendre(p, xi, L.data(), nullptr);
    EXPECT_EQ(N[0], 0.5 * (1 - xi));
    EXPECT_EQ(N[1], 0.5 * (1 + xi));
    EXPECT_EQ(dN[0], -0.5);
    EXPECT_EQ(dN[1], 0.5);
    for (int k = 2; k <= p; ++k) {
      EXPECT_NEAR(N[k], hb::integrated_legendre(k, xi), 1e-15) << "k = " << k;
      EXPECT_NEAR(dN[k], std::sqrt(0.5 * (2 * k - 1)) * L[k - 1], 1e-15) << "k = " << k;
      EXPECT_EQ(N_only[k], N[k]);
    }
  }
}

// The hierarchic 1D derivatives shall agree with central finite differences.
TEST(Hierarchic1D, DerivativeMatchesFiniteDifference) {
  constexpr int p = 10;
  constexpr double h = 1e-6;
  std::vector<double> N(p + 1), dN(p + 1), Np(p + 1), Nm(p + 1);
  for (double xi : sample_points) {
    hb::hierarchic_1d(p, xi, N.data(), dN.data());
    hb::hierarchic_1d(p, xi + h, Np.data(), nullptr);
    hb::hierarchic_1d(p, xi - h, Nm.data(), nullptr);
    // |phi_k'''| <= sqrt((2k-1)/2) L''_{k-1}(1) < 4e3 for k <= 10: truncation h^2/6 * 4e3 < 1e-9,
    // round-off eps/h ~ 2e-10.
    for (int k = 0; k <= p; ++k)
      EXPECT_NEAR(dN[k], (Np[k] - Nm[k]) / (2 * h), 1e-8) << "k = " << k << ", xi = " << xi;
  }
}
