// Unit tests of the Gauss–Legendre and Gauss–Lobatto rules: exactness, symmetry, accuracy, cache.
#include "hpcontact/basis/quadrature.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <numeric>
#include <thread>
#include <vector>

#include "hpcontact/basis/legendre.hpp"
#include "hpcontact/core/error.hpp"

namespace hb = hpcontact::basis;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

/// int_{-1}^{1} x^k dx.
double monomial_integral(int k) { return k % 2 == 1 ? 0.0 : 2.0 / (k + 1); }

/// Relative error of the rule on x^k, measured against int |x|^k = 2/(k+1) so odd k are covered.
double monomial_error(const hb::QuadratureRule1D& rule, int k) {
  double sum = 0.0;
  for (int i = 0; i < rule.size(); ++i) sum += rule.weights[i] * std::pow(rule.points[i], k);
  return std::abs(sum - monomial_integral(k)) / (2.0 / (k + 1));
}

/// Tolerance for x^k: 1e-14, widened for large k because a node error of one ulp changes x^k
/// by k ulps (the condition number of x -> x^k is k).
double monomial_tolerance(int k) { return std::max(1e-14, 4.0 * k * eps); }

/// Golub–Welsch: the Gauss nodes are the eigenvalues of the Jacobi matrix of the Legendre
/// recurrence, with off-diagonal k / sqrt(4k^2 - 1); the weights are 2 v_0^2. An independent
/// reference for the Newton-based rule.
hb::QuadratureRule1D golub_welsch(int n) {
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd sub(n - 1);
  for (int k = 1; k < n; ++k) sub[k - 1] = k / std::sqrt(4.0 * k * k - 1.0);
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver;
  solver.computeFromTridiagonal(diagonal, sub);
  hb::QuadratureRule1D rule;
  for (int i = 0; i < n; ++i) {
    rule.points.push_back(solver.eigenvalues()[i]);
    rule.weights.push_back(2.0 * std::pow(solver.eigenvectors()(0, i), 2));
  }
  return rule;
}

}  // namespace

// The n-point Gauss–Legendre rule shall integrate x^k exactly for every k <= 2n - 1.
TEST(GaussLegendre, ExactForMonomialsUpToDegree2nMinus1) {
  for (int n : {1, 2, 5, 10, 30, 64, 100}) {
    const auto& rule = hb::gauss_legendre(n);
    ASSERT_EQ(rule.size(), n);
    for (int k = 0; k <= 2 * n - 1; ++k)
      EXPECT_LE(monomial_error(rule, k), monomial_tolerance(k)) << "n = " << n << ", k = " << k;
  }
}

// The n-point Gauss–Legendre rule shall not be exact for x^{2n} (its degree is exactly 2n - 1).
TEST(GaussLegendre, NotExactBeyondDegree2nMinus1) {
  for (int n : {1, 2, 5, 10})
    EXPECT_GT(monomial_error(hb::gauss_legendre(n), 2 * n), 1e-6) << "n = " << n;
}

// Gauss–Legendre nodes shall be ascending, strictly inside (-1, 1), symmetric, with symmetric
// positive weights summing to 2.
TEST(GaussLegendre, SymmetricAscendingWeightsSumToTwo) {
  for (int n = 1; n <= 200; ++n) {
    const auto& rule = hb::gauss_legendre(n);
    const double sum = std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0);
    EXPECT_NEAR(sum, 2.0, 1e-14) << "n = " << n;
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(rule.weights[i], 0.0);
      EXPECT_GT(rule.points[i], -1.0);
      EXPECT_LT(rule.points[i], 1.0);
      EXPECT_EQ(rule.points[i], -rule.points[n - 1 - i]) << "n = " << n << ", i = " << i;
      EXPECT_EQ(rule.weights[i], rule.weights[n - 1 - i]) << "n = " << n << ", i = " << i;
      if (i > 0) {
        EXPECT_LT(rule.points[i - 1], rule.points[i]);
      }
    }
  }
}

// Small Gauss–Legendre rules shall match their closed forms.
TEST(GaussLegendre, ClosedFormsForSmallN) {
  const auto& r1 = hb::gauss_legendre(1);
  EXPECT_EQ(r1.points[0], 0.0);
  EXPECT_NEAR(r1.weights[0], 2.0, 1e-15);
  const auto& r2 = hb::gauss_legendre(2);
  EXPECT_NEAR(r2.points[1], 1.0 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(r2.weights[0], 1.0, 1e-15);
  const auto& r3 = hb::gauss_legendre(3);
  EXPECT_NEAR(r3.points[2], std::sqrt(0.6), 1e-15);
  EXPECT_EQ(r3.points[1], 0.0);
  EXPECT_NEAR(r3.weights[0], 5.0 / 9.0, 1e-15);
  EXPECT_NEAR(r3.weights[1], 8.0 / 9.0, 1e-15);
}

// Nodes and weights shall agree to 1e-14 (absolute) with Golub–Welsch eigenvalues up to n = 200.
TEST(GaussLegendre, NodesAndWeightsMatchGolubWelschUpTo200) {
  for (int n : {2, 7, 20, 50, 101, 150, 200}) {
    const auto& rule = hb::gauss_legendre(n);
    const auto reference = golub_welsch(n);
    for (int i = 0; i < n; ++i) {
      EXPECT_NEAR(rule.points[i], reference.points[i], 1e-14) << "n = " << n << ", i = " << i;
      EXPECT_NEAR(rule.weights[i], reference.weights[i], 1e-14) << "n = " << n << ", i = " << i;
    }
  }
}

// For n up to 200 the rule shall integrate every L_k, k <= 2n - 1, to 2 delta_k0 within 1e-14
// (a well-conditioned exactness check: |L_k| <= 1 on [-1, 1]).
TEST(GaussLegendre, IntegratesLegendrePolynomialsUpTo200Points) {
  for (int n : {100, 150, 200}) {
    const auto& rule = hb::gauss_legendre(n);
    const int k_max = 2 * n - 1;
    std::vector<double> moments(k_max + 1, 0.0), L(k_max + 1);
    for (int i = 0; i < n; ++i) {
      hb::legendre(k_max, rule.points[i], L.data(), nullptr);
      for (int k = 0; k <= k_max; ++k) moments[k] += rule.weights[i] * L[k];
    }
    for (int k = 0; k <= k_max; ++k)
      EXPECT_NEAR(moments[k], k == 0 ? 2.0 : 0.0, 1e-14) << "n = " << n << ", k = " << k;
  }
}

// The 64-point rule shall integrate cos over [-1, 1] to 2 sin 1 within a few ulps.
TEST(GaussLegendre, CosineIntegralAt64Points) {
  const double two_sin_1 = 1.6829419696157930133050046432606;  // 2 sin(1), 32 digits
  const auto& rule = hb::gauss_legendre(64);
  double sum = 0.0;
  for (int i = 0; i < rule.size(); ++i) sum += rule.weights[i] * std::cos(rule.points[i]);
  EXPECT_NEAR(sum, two_sin_1, 8 * eps);
}

// The n-point Gauss–Lobatto rule shall contain both end points and be exact for x^k, k <= 2n - 3.
TEST(GaussLobatto, EndPointsAndExactnessUpToDegree2nMinus3) {
  for (int n : {2, 3, 4, 5, 10, 30, 64, 100}) {
    const auto& rule = hb::gauss_lobatto(n);
    ASSERT_EQ(rule.size(), n);
    EXPECT_EQ(rule.points.front(), -1.0);
    EXPECT_EQ(rule.points.back(), 1.0);
    EXPECT_NEAR(rule.weights.front(), 2.0 / (n * (n - 1.0)), 1e-15);
    for (int k = 0; k <= 2 * n - 3; ++k)
      EXPECT_LE(monomial_error(rule, k), monomial_tolerance(k)) << "n = " << n << ", k = " << k;
    // The error on x^{2n-2} decays like 4^{-n}: only small rules show the degree is sharp.
    if (n <= 10) {
      EXPECT_GT(monomial_error(rule, 2 * n - 2), 1e-6) << "n = " << n;
    }
  }
}

// Gauss–Lobatto nodes shall be ascending, symmetric, with symmetric positive weights summing to 2,
// and the interior nodes shall be the roots of L'_{n-1}.
TEST(GaussLobatto, SymmetricAscendingInteriorRootsOfDerivative) {
  for (int n = 2; n <= 200; ++n) {
    const auto& rule = hb::gauss_lobatto(n);
    const double sum = std::accumulate(rule.weights.begin(), rule.weights.end(), 0.0);
    EXPECT_NEAR(sum, 2.0, 1e-14) << "n = " << n;
    std::vector<double> L(n), dL(n);
    for (int i = 0; i < n; ++i) {
      EXPECT_GT(rule.weights[i], 0.0);
      EXPECT_EQ(rule.points[i], -rule.points[n - 1 - i]);
      EXPECT_EQ(rule.weights[i], rule.weights[n - 1 - i]);
      if (i > 0) {
        EXPECT_LT(rule.points[i - 1], rule.points[i]) << "n = " << n << ", i = " << i;
      }
      if (i > 0 && i < n - 1) {
        // Newton's estimate of the root error, L'_m / L''_m with m = n - 1 and L''_m from the
        // Legendre equation (eq. 2.61): (1 - x^2) L''_m = 2x L'_m - m(m+1) L_m.
        const int m = n - 1;
        const double x = rule.points[i];
        hb::legendre(m, x, L.data(), dL.data());
        const double d2L = (2.0 * x * dL[m] - m * (m + 1.0) * L[m]) / ((1.0 - x) * (1.0 + x));
        EXPECT_LE(std::abs(dL[m] / d2L), 1e-14) << "n = " << n << ", i = " << i;
      }
    }
  }
}

// Small Gauss–Lobatto rules shall match their closed forms (trapezoid, Simpson).
TEST(GaussLobatto, ClosedFormsForSmallN) {
  const auto& r2 = hb::gauss_lobatto(2);
  EXPECT_EQ(r2.weights[0], 1.0);
  EXPECT_EQ(r2.weights[1], 1.0);
  const auto& r3 = hb::gauss_lobatto(3);
  EXPECT_EQ(r3.points[1], 0.0);
  EXPECT_NEAR(r3.weights[0], 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(r3.weights[1], 4.0 / 3.0, 1e-15);
  const auto& r4 = hb::gauss_lobatto(4);
  EXPECT_NEAR(r4.points[2], 1.0 / std::sqrt(5.0), 1e-15);
  EXPECT_NEAR(r4.weights[2], 5.0 / 6.0, 1e-15);
}

// Requests for too few points shall be rejected as input errors.
TEST(Quadrature, RejectsTooFewPoints) {
  EXPECT_THROW(hb::gauss_legendre(0), hpcontact::InputError);
  EXPECT_THROW(hb::gauss_legendre(-3), hpcontact::InputError);
  EXPECT_THROW(hb::gauss_lobatto(1), hpcontact::InputError);
}

// A rule shall be computed once: repeated and concurrent requests return the same object.
TEST(Quadrature, CachedAndThreadSafe) {
  EXPECT_EQ(&hb::gauss_legendre(17), &hb::gauss_legendre(17));
  EXPECT_EQ(&hb::gauss_lobatto(17), &hb::gauss_lobatto(17));

  constexpr int n_threads = 8;
  std::vector<const hb::QuadratureRule1D*> seen(n_threads);
  std::vector<std::thread> threads;
  for (int t = 0; t < n_threads; ++t)
    threads.emplace_back([t, &seen] {
      for (int n = 201; n <= 230; ++n) hb::gauss_lobatto(n);
      seen[t] = &hb::gauss_legendre(231);
    });
  for (auto& thread : threads) thread.join();
  for (int t = 1; t < n_threads; ++t) EXPECT_EQ(seen[t], seen[0]);
  EXPECT_NEAR(monomial_error(*seen[0], 2), 0.0, 1e-14);
}
