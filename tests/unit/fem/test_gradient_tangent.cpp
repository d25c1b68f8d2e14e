// The element tangent from the first elasticity tensor: the products agree with the plain sum
// over points, slots and modes, K is exactly symmetric, and 𝔸 is the derivative of P = F S.
#include "hpcontact/fem/gradient_tangent.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

using namespace hpcontact;

namespace {

/// A symmetric s × s matrix per point, side by side.
Eigen::MatrixXd symmetric_blocks(int s, int nq) {
  Eigen::MatrixXd A(s, s * nq);
  for (int q = 0; q < nq; ++q) {
    const Eigen::MatrixXd R = Eigen::MatrixXd::Random(s, s);
    A.middleCols(s * q, s) = R + R.transpose();
  }
  return A;
}

/// The St. Venant–Kirchhoff stress S(E) = λ tr E I + 2μ E of a 3 × 3 F (plane block and F_θθ),
/// and its ℂ in Voigt order (E11, E22, 2 E12, E33).
struct Law {
  double lambda = 1.3, mu = 0.7;
  Eigen::Matrix3d stress(const Eigen::Matrix3d& F) const {
    const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
    return lambda * E.trace() * Eigen::Matrix3d::Identity() + 2 * mu * E;
  }
  Eigen::Matrix4d voigt() const {
    Eigen::Matrix4d C = Eigen::Matrix4d::Zero();
    for (int i : {0, 1, 3})
      for (int j : {0, 1, 3}) C(i, j) = lambda + (i == j ? 2 * mu : 0.0);
    C(2, 2) = mu;
    return C;
  }
};

}  // namespace

// gradient_tangent shall equal Σ_q Σ_st D_i(a, s_q) 𝔸_q(s, t) D_k(b, t_q) summed term by term
// (to 1e-13 of its largest entry), for the plane's 2 + 2 slots and the axisymmetric 3 + 2, and
// be exactly symmetric.
TEST(GradientTangent, EqualsThePlainSumAndIsSymmetric) {
  std::srand(3);
  for (const auto [s0, s1] : {std::pair{2, 2}, std::pair{3, 2}}) {
    const int n = 7, nq = 11, s = s0 + s1;
    const Eigen::MatrixXd D0 = Eigen::MatrixXd::Random(n, s0 * nq), D1 = Eigen::MatrixXd::Random(n, s1 * nq);
    const Eigen::MatrixXd A = symmetric_blocks(s, nq);
    const Eigen::MatrixXd K = fem::gradient_tangent(D0, D1, s0, s1, A);
    Eigen::MatrixXd plain = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    const Eigen::MatrixXd* D[2] = {&D0, &D1};
    const int slots[2] = {s0, s1}, first[2] = {0, s0};
    for (int i = 0; i < 2; ++i)
      for (int k = 0; k < 2; ++k)
        for (int a = 0; a < n; ++a)
          for (int b = 0; b < n; ++b)
            for (int q = 0; q < nq; ++q)
              for (int si = 0; si < slots[i]; ++si)
                for (int tk = 0; tk < slots[k]; ++tk)
                  plain(i * n + a, k * n + b) += (*D[i])(a, slots[i] * q + si) *
                                                 A(first[i] + si, s * q + first[k] + tk) *
                                                 (*D[k])(b, slots[k] * q + tk);
    EXPECT_LT((K - plain).cwiseAbs().maxCoeff(), 1e-13 * plain.cwiseAbs().maxCoeff()) << s0 << "+" << s1;
    EXPECT_TRUE(K == K.transpose()) << s0 << "+" << s1;
  }
}

// first_elasticity shall be the derivative of first_piola along each slot (central differences of
// P = F S(F), h = 1e-6, to 1e-8 of max|𝔸|), on the axisymmetric slots with F_θθ, where the
// shear's Voigt convention (2 E12) and the hoop component both take part.
TEST(GradientTangent, FirstElasticityIsTheDerivativeOfP) {
  const Law law;
  Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
  F.topLeftCorner<2, 2>() << 1.2, 0.3, -0.2, 0.9;
  F(2, 2) = 1.1;
  const auto& slots = fem::kAxisymmetricSlots;
  const auto A = fem::first_elasticity(slots, F, law.stress(F), law.voigt(), 2.0);
  const double h = 1e-6;
  for (std::size_t t = 0; t < slots.size(); ++t) {
    Eigen::Matrix3d Fp = F, Fm = F;
    Fp(slots[t].first, slots[t].second) += h;
    Fm(slots[t].first, slots[t].second) -= h;
    const auto column = (fem::first_piola(slots, Fp, law.stress(Fp), 2.0) -
                         fem::first_piola(slots, Fm, law.stress(Fm), 2.0)) / (2 * h);
    EXPECT_LT((column - A.col(t)).cwiseAbs().maxCoeff(), 1e-8 * A.cwiseAbs().maxCoeff()) << "slot " << t;
  }
}
