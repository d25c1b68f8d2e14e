// The axisymmetric (hoop) hyperelastic state: ℂ = dS/dE and S = dW/dE by central differences in
// all four strains, the plane-strain state recovered at F_θθ = 1, and the linear axisymmetric
// stress at small strain.
#include "hpcontact/material/hyperelastic_hoop.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

using namespace hpcontact::material;

namespace {

LinearElastic elastic(double E, double nu) {
  LinearElastic m;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.plane = Plane::axisymmetric;
  return m;
}

/// The symmetric meridian stretch and the hoop stretch of a Green–Lagrange strain
/// (E_rr, E_zz, 2 E_rz, E_θθ).
std::pair<Eigen::Matrix2d, double> stretches_of_strain(const Eigen::Vector4d& e) {
  Eigen::Matrix2d C;
  C << 1 + 2 * e(0), e(2), e(2), 1 + 2 * e(1);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(C);
  const Eigen::Matrix2d U =
      es.eigenvectors() * es.eigenvalues().cwiseSqrt().asDiagonal() * es.eigenvectors().transpose();
  return {U, std::sqrt(1 + 2 * e(3))};
}

const Law kLaws[] = {Law::saint_venant_kirchhoff, Law::neo_hooke};

const Eigen::Vector4d kStrains[] = {{0.1, -0.05, 0.08, 0.12}, {-0.15, 0.2, -0.1, -0.2},
                                    {0.3, 0.1, 0.25, 0.4}};

}  // namespace

// Each column of ℂ against central differences of S (step 1e-6), S against differences of W:
// to 1e-7 of the largest entry; ℂ symmetric.
TEST(HoopHyperelastic, TangentAndStressAreDerivatives) {
  for (Law law : kLaws)
    for (double nu : {0.0, 0.3, 0.48})
      for (const auto& e : kStrains) {
        const auto m = elastic(1000, nu);
        const auto [U, Fh] = stretches_of_strain(e);
        const auto s = hoop_hyperelastic_state(m, law, U, Fh);
        const double h = 1e-6;
        Eigen::Matrix4d C_fd;
        Eigen::Vector4d S_fd;
        for (int b = 0; b < 4; ++b) {
          Eigen::Vector4d ep = e, em = e;
          ep(b) += h;
          em(b) -= h;
          const auto [Up, Fp] = stretches_of_strain(ep);
          const auto [Um, Fm] = stretches_of_strain(em);
          const auto sp = hoop_hyperelastic_state(m, law, Up, Fp);
          const auto sm = hoop_hyperelastic_state(m, law, Um, Fm);
          C_fd.col(b) = (sp.S - sm.S) / (2 * h);
          // W per engineering strain: dW/d(2E_rz) = S_rz
          S_fd(b) = (sp.W - sm.W) / (2 * h);
        }
        const double scale = s.C.cwiseAbs().maxCoeff();
        EXPECT_LT((C_fd - s.C).cwiseAbs().maxCoeff(), 1e-7 * scale) << law_name(law) << " nu " << nu;
        EXPECT_LT((s.C - s.C.transpose()).cwiseAbs().maxCoeff(), 1e-12 * scale);
        EXPECT_LT((S_fd - s.S).cwiseAbs().maxCoeff(), 1e-7 * s.S.cwiseAbs().maxCoeff() + 1e-9);
      }
}

// At F_θθ = 1 the state is plane strain's: S, the 3 × 3 block of ℂ, S_θθ = S33, W and J.
TEST(HoopHyperelastic, UnitHoopStretchIsPlaneStrain) {
  Eigen::Matrix2d F;
  F << 1.2, 0.3, -0.1, 0.9;
  for (Law law : kLaws) {
    auto plane = elastic(1000, 0.3);
    plane.plane = Plane::strain;
    const auto p = hyperelastic_state(plane, law, F);
    const auto s = hoop_hyperelastic_state(elastic(1000, 0.3), law, F, 1.0);
    EXPECT_LT((s.S.head<3>() - p.S).norm(), 1e-12 * p.S.norm()) << law_name(law);
    EXPECT_NEAR(s.S(3), p.S33, 1e-12 * p.S.norm());
    EXPECT_LT((s.C.topLeftCorner<3, 3>() - p.C).norm(), 1e-12 * p.C.norm());
    EXPECT_NEAR(s.W, p.W, 1e-12 * std::abs(p.W));
    EXPECT_NEAR(s.J, p.J, 1e-15);
  }
}

// At a strain of 1e-7 the Cauchy stress, hoop included, is the linear axisymmetric stress of
// the same small strain to O(strain) relative (asserted 1e-5).
TEST(HoopHyperelastic, SmallStrainIsLinearAxisymmetric) {
  const Eigen::Vector4d eps = 1e-7 * Eigen::Vector4d(1.0, -0.4, 0.7, 0.6);  // (ε_rr, ε_zz, γ_rz, ε_θθ)
  Eigen::Matrix2d F;
  F << 1 + eps(0), eps(2) / 2, eps(2) / 2, 1 + eps(1);
  const double Fh = 1 + eps(3);
  const auto m = elastic(1000, 0.3);
  double hoop_linear = 0;
  const Voigt linear = m.axisymmetric_stress(eps.head<3>(), eps(3), &hoop_linear);
  for (Law law : kLaws) {
    double hoop = 0;
    const Voigt sigma = hoop_cauchy_stress(hoop_hyperelastic_state(m, law, F, Fh), F, Fh, &hoop);
    EXPECT_LT((sigma - linear).norm(), 1e-5 * linear.norm()) << law_name(law);
    EXPECT_NEAR(hoop, hoop_linear, 1e-5 * std::abs(hoop_linear));
  }
}

namespace {

/// The closed forms of a diagonal stretch F = diag(λ_r, λ_z, λ_θ) (principal axes r, z, θ), from
/// the laws' 3-D formulas: St. Venant–Kirchhoff S_i = Λ tr E + 2μ E_i, E_i = (λ_i² − 1)/2,
/// W = Λ (tr E)²/2 + μ Σ E_i², ℂ the constant isotropic one; Neo-Hooke S_i = μ (1 − λ_i⁻²) +
/// Λ ln J λ_i⁻², W = μ (Σ λ_i² − 3)/2 − μ ln J + Λ (ln J)²/2, ℂ_iijj = Λ λ_i⁻² λ_j⁻² +
/// 2 (μ − Λ ln J) λ_i⁻⁴ δ_ij and ℂ_rzrz = (μ − Λ ln J) λ_r⁻² λ_z⁻². Cauchy σ_i = λ_i² S_i / J.
struct Principal {
  Eigen::Vector3d S, sigma;  ///< (r, z, θ)
  Eigen::Matrix4d C;         ///< Voigt (rr, zz, rz, θθ)
  double W = 0;
};
Principal principal(Law law, double E, double nu, const Eigen::Vector3d& stretch) {
  const double mu = E / (2 * (1 + nu)), L = E * nu / ((1 + nu) * (1 - 2 * nu));
  const double J = stretch.prod(), lnJ = std::log(J);
  const int voigt[3] = {0, 1, 3};  // r, z, θ in (rr, zz, rz, θθ)
  Principal p;
  p.C.setZero();
  if (law == Law::saint_venant_kirchhoff) {
    const Eigen::Vector3d e = 0.5 * (stretch.array().square() - 1).matrix();
    p.S = (L * e.sum() + 2 * mu * e.array()).matrix();
    p.W = 0.5 * L * e.sum() * e.sum() + mu * e.squaredNorm();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) p.C(voigt[i], voigt[j]) = L + (i == j ? 2 * mu : 0);
    p.C(2, 2) = mu;
  } else {
    const Eigen::Vector3d inv2 = stretch.array().square().inverse().matrix();
    p.S = (mu * (1 - inv2.array()) + L * lnJ * inv2.array()).matrix();
    p.W = 0.5 * mu * (stretch.squaredNorm() - 3) - mu * lnJ + 0.5 * L * lnJ * lnJ;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        p.C(voigt[i], voigt[j]) = L * inv2(i) * inv2(j) + (i == j ? 2 * (mu - L * lnJ) * inv2(i) * inv2(i) : 0);
    p.C(2, 2) = (mu - L * lnJ) * inv2(0) * inv2(1);
  }
  p.sigma = (stretch.array().square() * p.S.array() / J).matrix();
  return p;
}

}  // namespace

// A uniform radial expansion u_r = ε R (ε = 0.1: F_rr = F_θθ = 1.1, F_zz = 1) has σ_θθ = σ_rr,
// and it and a triaxial stretch (1.2, 0.9, 1.05) give S, σ (the hoop's σ_θθ = F_θθ² S_θθ / J
// among them), ℂ (its hoop row) and W of the closed forms to 1e-13 relative: the hoop
// components at a finite state with a hoop stress, which a strain of 1e-7 (F_θθ ≈ 1) or the
// stretched cylinder (S_θθ = 0) cannot tell from a lost factor of F_θθ.
TEST(HoopHyperelastic, DiagonalStretchClosedForms) {
  const auto m = elastic(1000, 0.3);
  for (Law law : kLaws)
    for (const Eigen::Vector3d& stretch : {Eigen::Vector3d(1.1, 1, 1.1), Eigen::Vector3d(1.2, 0.9, 1.05)}) {
      const Principal exact = principal(law, 1000, 0.3, stretch);
      const Eigen::Matrix2d F = Eigen::Vector2d(stretch(0), stretch(1)).asDiagonal();
      const auto s = hoop_hyperelastic_state(m, law, F, stretch(2));
      double hoop = 0;
      const Voigt sigma = hoop_cauchy_stress(s, F, stretch(2), &hoop);
      const double scale = exact.sigma.cwiseAbs().maxCoeff();
      const std::string what = law_name(law) + " stretch " + std::to_string(stretch(0)) + ", " +
                               std::to_string(stretch(1)) + ", " + std::to_string(stretch(2));
      EXPECT_GT(std::abs(exact.S(2)), 10.0) << what;  // a hoop stress of the load's size
      EXPECT_LT((Eigen::Vector4d(exact.S(0), exact.S(1), 0, exact.S(2)) - s.S).norm(), 1e-13 * scale) << what;
      EXPECT_NEAR(sigma(0), exact.sigma(0), 1e-13 * scale) << what;
      EXPECT_NEAR(sigma(1), exact.sigma(1), 1e-13 * scale) << what;
      EXPECT_NEAR(sigma(2), 0.0, 1e-13 * scale) << what;
      EXPECT_NEAR(hoop, exact.sigma(2), 1e-13 * scale) << what;
      if (stretch(0) == stretch(2)) EXPECT_NEAR(hoop, sigma(0), 1e-13 * scale) << what;
      EXPECT_LT((s.C - exact.C).cwiseAbs().maxCoeff(), 1e-13 * exact.C.cwiseAbs().maxCoeff()) << what;
      EXPECT_NEAR(s.W, exact.W, 1e-13 * exact.W) << what;
      EXPECT_NEAR(s.J, stretch.prod(), 1e-15) << what;
    }
}
