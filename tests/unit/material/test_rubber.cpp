// The rubber laws (neo-Hooke, Mooney–Rivlin, Yeoh with W = W_iso(Ī₁, Ī₂) + K/2 (J − 1)²): S
// against differences of W, ℂ against differences of S — for the whole law and for each part of
// the split a mixed element will use —, the isochoric part's invariance under C → a C, the
// small-strain limit, a J = 1 uniaxial stretch against the closed form of the invariants, and
// the plane-strain and hoop reductions against differences of their own W and S.
#include "hpcontact/material/rubber.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "hpcontact/material/hyperelastic.hpp"
#include "hpcontact/material/hyperelastic_hoop.hpp"

using namespace hpcontact::material;

namespace {

struct NamedLaw {
  std::string name;
  Law law;
  RubberConstants constants;
};

/// The three laws with constants of a filled rubber (MPa); C20 and C30 large enough that the
/// Yeoh terms are a good part of the stress at Ī₁ − 3 ~ 0.5.
std::vector<NamedLaw> laws() {
  return {{"neo-hooke-split", Law::neo_hooke_split, {.C10 = 0.5, .K = 20}},
          {"mooney-rivlin", Law::mooney_rivlin, {.C10 = 0.4, .C01 = 0.15, .K = 20}},
          {"yeoh", Law::yeoh, {.C10 = 0.5, .C20 = 0.2, .C30 = 0.04, .K = 20}}};
}

/// Random deformation gradients of moderate stretch (principal stretches ~0.6…1.6) with J ≠ 1,
/// a fixed seed.
std::vector<Eigen::Matrix3d> deformations() {
  std::srand(43);
  std::vector<Eigen::Matrix3d> F;
  for (int i = 0; i < 12; ++i) F.push_back(Eigen::Matrix3d::Identity() + 0.3 * Eigen::Matrix3d::Random());
  return F;
}

Eigen::Matrix3d cauchy_green(const Eigen::Matrix3d& F) { return F.transpose() * F; }

/// The 3-D Voigt pairs (11, 22, 33, 23, 13, 12).
constexpr int kI[6] = {0, 1, 2, 1, 0, 0}, kJ[6] = {0, 1, 2, 2, 2, 1};

/// C + δC of the Green–Lagrange strain step h in Voigt component b (engineering shear):
/// δC = 2 δE, so C_ii += 2h, and C_ij, C_ji += h for a shear.
Eigen::Matrix3d step(const Eigen::Matrix3d& C, int b, double h) {
  Eigen::Matrix3d D = C;
  if (b < 3) {
    D(b, b) += 2 * h;
  } else {
    D(kI[b], kJ[b]) += h;
    D(kJ[b], kI[b]) += h;
  }
  return D;
}

Voigt3 voigt(const Eigen::Matrix3d& A) {
  Voigt3 v;
  for (int a = 0; a < 6; ++a) v(a) = A(kI[a], kJ[a]);
  return v;
}

/// max |S − ∂W/∂E| / max |S| and max |ℂ − ∂S/∂E| / max |ℂ| of a part of the law at C, by
/// central differences in the six Voigt strains (step h: truncation h² ~ 1e-12, round-off
/// 1e-16 / h ~ 1e-11 of the entries).
std::pair<double, double> mismatch(const std::function<StressTangent3(const Eigen::Matrix3d&)>& part,
                                   const Eigen::Matrix3d& C) {
  const double h = 1e-6;
  const StressTangent3 s = part(C);
  Voigt3 S_fd;
  Elasticity3 C_fd;
  for (int b = 0; b < 6; ++b) {
    const StressTangent3 p = part(step(C, b, h)), m = part(step(C, b, -h));
    S_fd(b) = (p.W - m.W) / (2 * h);  // dW/d(2 E_ij) = S_ij for a shear
    C_fd.col(b) = (voigt(p.S) - voigt(m.S)) / (2 * h);
  }
  return {(S_fd - voigt(s.S)).cwiseAbs().maxCoeff() / voigt(s.S).cwiseAbs().maxCoeff(),
          (C_fd - s.C).cwiseAbs().maxCoeff() / s.C.cwiseAbs().maxCoeff()};
}

}  // namespace

// The whole law: S = 2 ∂W/∂C and ℂ = 2 ∂S/∂C to 1e-8 relative (the brief asks 1e-7) over 12
// random F with J ≠ 1, each law; ℂ symmetric to round-off.
TEST(RubberLaw, StressAndTangentAreDerivatives) {
  for (const auto& law : laws())
    for (const auto& F : deformations()) {
      const Eigen::Matrix3d C = cauchy_green(F);
      ASSERT_GT(std::abs(F.determinant() - 1), 1e-3);
      const auto [dS, dC] = mismatch([&](const Eigen::Matrix3d& c) { return rubber_stress(law.constants, c); }, C);
      EXPECT_LT(dS, 1e-8) << law.name << " J " << F.determinant();
      EXPECT_LT(dC, 1e-8) << law.name << " J " << F.determinant();
      const Elasticity3 T = rubber_stress(law.constants, C).C;
      EXPECT_LT((T - T.transpose()).cwiseAbs().maxCoeff(), 1e-13 * T.cwiseAbs().maxCoeff());
    }
}

// Each part of the split on its own, as a mixed u–p element will take them: the isochoric S and
// ℂ are derivatives of W_iso, and pressure_stress at a fixed p is the derivative of
// W_p = p (J − 1) (its own W is left 0, so the differences use p (J − 1) here).
TEST(RubberLaw, IsochoricAndPressurePartsAreDerivatives) {
  for (const auto& law : laws())
    for (const auto& F : deformations()) {
      const Eigen::Matrix3d C = cauchy_green(F);
      const auto [dS, dC] = mismatch([&](const Eigen::Matrix3d& c) { return isochoric_stress(law.constants, c); }, C);
      EXPECT_LT(dS, 1e-8) << law.name;
      EXPECT_LT(dC, 1e-8) << law.name;
    }
  for (const auto& F : deformations()) {
    const double p = -1.7;
    const auto [dS, dC] = mismatch(
        [&](const Eigen::Matrix3d& c) {
          StressTangent3 s = pressure_stress(c, p);
          s.W = p * (std::sqrt(c.determinant()) - 1);
          return s;
        },
        cauchy_green(F));
    EXPECT_LT(dS, 1e-8);
    EXPECT_LT(dC, 1e-8);
  }
}

// The volumetric energy: U' and U'' are U's derivatives (differences, 1e-8), U(1) = U'(1) = 0,
// and the law's S is the isochoric S plus J U'(J) C⁻¹ (the sign of the pressure: a pure
// dilatation J > 1 gives a tensile mean Cauchy stress U'(J) = K (J − 1) > 0).
TEST(RubberLaw, VolumetricPartIsThePressure) {
  const double K = 20, h = 1e-6;
  for (double J : {0.7, 0.95, 1.0, 1.2, 2.0}) {
    const auto U = volumetric_energy(K, J), Up = volumetric_energy(K, J + h), Um = volumetric_energy(K, J - h);
    EXPECT_NEAR(U.dU, (Up.U - Um.U) / (2 * h), 1e-8 * K);
    EXPECT_NEAR(U.d2U, (Up.dU - Um.dU) / (2 * h), 1e-8 * K);
  }
  EXPECT_EQ(volumetric_energy(K, 1).U, 0.0);
  EXPECT_EQ(volumetric_energy(K, 1).dU, 0.0);
  for (double a : {0.9, 1.1}) {
    const Eigen::Matrix3d F = a * Eigen::Matrix3d::Identity(), C = cauchy_green(F);
    const double J = a * a * a;
    const auto s = rubber_stress({.C10 = 0.5, .C01 = 0.1, .K = K}, C);
    const Eigen::Matrix3d sigma = F * s.S * F.transpose() / J;
    EXPECT_LT((sigma - K * (J - 1) * Eigen::Matrix3d::Identity()).norm(), 1e-13 * K) << a;
  }
}

// W_iso depends on C̄ = J^(−2/3) C alone: unchanged under C → a C (a = 0.6, 1.7) to round-off,
// and so S_iso : C = 0 (the derivative along C) to 1e-14 of |S_iso| |C|.
TEST(RubberLaw, IsochoricPartIgnoresVolumeChange) {
  for (const auto& law : laws())
    for (const auto& F : deformations()) {
      const Eigen::Matrix3d C = cauchy_green(F);
      const auto s = isochoric_stress(law.constants, C);
      for (double a : {0.6, 1.7})
        EXPECT_NEAR(isochoric_stress(law.constants, a * C).W, s.W, 1e-13 * (1 + std::abs(s.W))) << law.name;
      EXPECT_LT(std::abs((s.S.cwiseProduct(C)).sum()), 1e-14 * s.S.norm() * C.norm()) << law.name;
    }
}

// At C = I: S = 0, W = 0 and ℂ = the linear 3-D D of μ = 2 (C10 + C01) and K (λ = K − 2μ/3),
// i.e. RubberConstants::small_strain's E and ν, to 1e-13.
TEST(RubberLaw, SmallStrainLimitIsLinearElasticity) {
  for (const auto& law : laws()) {
    const auto s = rubber_stress(law.constants, Eigen::Matrix3d::Identity());
    EXPECT_EQ(s.W, 0.0);
    EXPECT_LT(s.S.norm(), 1e-15);
    const LinearElastic m = law.constants.small_strain(Plane::strain);
    EXPECT_NEAR(m.mu(), law.constants.shear_modulus(), 1e-13 * m.mu());
    EXPECT_NEAR(m.lambda() + 2 * m.mu() / 3, law.constants.K, 1e-13 * law.constants.K);
    EXPECT_LT((s.C - m.D3()).cwiseAbs().maxCoeff(), 1e-13 * law.constants.K) << law.name;
  }
}

// An isochoric uniaxial stretch F = diag(λ, λ^(−1/2), λ^(−1/2)) (J = 1, so U' = 0): the closed
// form of an incompressible law's stress difference, σ11 − σ22 = 2 (λ² − 1/λ)(W₁ + W₂/λ) with
// W₁ = C10 + 2 C20 (I₁ − 3) + 3 C30 (I₁ − 3)², W₂ = C01, I₁ = λ² + 2/λ; to 1e-12 relative,
// λ = 0.5 … 3.
TEST(RubberLaw, IsochoricUniaxialStretchClosedForm) {
  for (const auto& law : laws())
    for (double l : {0.5, 0.8, 1.3, 2.0, 3.0}) {
      const Eigen::Matrix3d F = Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal();
      const Eigen::Matrix3d sigma = F * rubber_stress(law.constants, cauchy_green(F)).S * F.transpose();
      const auto& k = law.constants;
      const double x = l * l + 2 / l - 3;
      const double W1 = k.C10 + 2 * k.C20 * x + 3 * k.C30 * x * x, W2 = k.C01;
      const double expected = 2 * (l * l - 1 / l) * (W1 + W2 / l);
      EXPECT_NEAR(sigma(0, 0) - sigma(1, 1), expected, 1e-12 * std::abs(expected)) << law.name << " " << l;
      EXPECT_NEAR(sigma(1, 1), sigma(2, 2), 1e-13 * std::abs(expected));
    }
}

// The plane-strain (C33 = 1) and axisymmetric (C_θθ = F_θθ²) states of the rubber laws: their S
// against differences of their W and ℂ against differences of their S in their own strains
// (E11, E22, 2 E12[, E_θθ]), to 1e-7 of the largest entry; the hoop state at F_θθ = 1 is the
// plane-strain one.
TEST(RubberLaw, PlaneAndHoopStatesAreDerivatives) {
  const double h = 1e-6;
  auto stretch = [](const Eigen::Vector4d& e) {
    Eigen::Matrix2d C;
    C << 1 + 2 * e(0), e(2), e(2), 1 + 2 * e(1);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(C);
    const Eigen::Matrix2d U =
        es.eigenvectors() * es.eigenvalues().cwiseSqrt().asDiagonal() * es.eigenvectors().transpose();
    return std::pair<Eigen::Matrix2d, double>{U, std::sqrt(1 + 2 * e(3))};
  };
  for (const auto& nl : laws())
    for (const Eigen::Vector4d e : {Eigen::Vector4d(0.1, -0.05, 0.08, 0.12), Eigen::Vector4d(-0.15, 0.2, -0.1, -0.2),
                                    Eigen::Vector4d(0.6, -0.2, 0.25, 0.4)}) {
      const FiniteStrainLaw law{nl.law, nl.constants.small_strain(Plane::axisymmetric), nl.constants};
      const auto [U, Fh] = stretch(e);
      const auto hoop = hoop_hyperelastic_state(law, U, Fh);
      const auto plane = hyperelastic_state(law, U);
      Eigen::Matrix4d C4;
      Eigen::Vector4d S4;
      Eigen::Matrix3d C3;
      Eigen::Vector3d S3;
      for (int b = 0; b < 4; ++b) {
        Eigen::Vector4d ep = e, em = e;
        ep(b) += h;
        em(b) -= h;
        const auto [Up, Fp] = stretch(ep);
        const auto [Um, Fm] = stretch(em);
        const auto sp = hoop_hyperelastic_state(law, Up, Fp), sm = hoop_hyperelastic_state(law, Um, Fm);
        C4.col(b) = (sp.S - sm.S) / (2 * h);
        S4(b) = (sp.W - sm.W) / (2 * h);
        if (b == 3) continue;
        const auto pp = hyperelastic_state(law, Up), pm = hyperelastic_state(law, Um);
        C3.col(b) = (pp.S - pm.S) / (2 * h);
        S3(b) = (pp.W - pm.W) / (2 * h);
      }
      EXPECT_LT((C4 - hoop.C).cwiseAbs().maxCoeff(), 1e-7 * hoop.C.cwiseAbs().maxCoeff()) << nl.name;
      EXPECT_LT((S4 - hoop.S).cwiseAbs().maxCoeff(), 1e-7 * hoop.S.cwiseAbs().maxCoeff()) << nl.name;
      EXPECT_LT((C3 - plane.C).cwiseAbs().maxCoeff(), 1e-7 * plane.C.cwiseAbs().maxCoeff()) << nl.name;
      EXPECT_LT((S3 - plane.S).cwiseAbs().maxCoeff(), 1e-7 * plane.S.cwiseAbs().maxCoeff()) << nl.name;
      const auto unit = hoop_hyperelastic_state(law, U, 1.0);
      EXPECT_LT((unit.S.head<3>() - plane.S).norm(), 1e-14 * plane.S.norm());
      EXPECT_NEAR(unit.S(3), plane.S33, 1e-14 * plane.S.norm());
      EXPECT_LT((unit.C.topLeftCorner<3, 3>() - plane.C).norm(), 1e-14 * plane.C.norm());
      EXPECT_EQ(unit.W, plane.W);
    }
}
