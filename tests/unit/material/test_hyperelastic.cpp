// The hyperelastic laws: consistent tangent and stress against finite differences of the energy
// and the stress, objectivity, and the small-strain limit (linear elasticity).
#include "hpcontact/material/hyperelastic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

using namespace hpcontact::material;

namespace {

LinearElastic elastic(double E, double nu, Plane plane = Plane::strain) {
  LinearElastic m;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.plane = plane;
  return m;
}

/// The symmetric F = √C of a right Cauchy–Green tensor: any F with FᵀF = C has the same S.
Eigen::Matrix2d stretch_of(const Eigen::Matrix2d& C) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(C);
  return es.eigenvectors() * es.eigenvalues().cwiseSqrt().asDiagonal() * es.eigenvectors().transpose();
}

/// Green–Lagrange strain in Voigt (E11, E22, 2 E12) -> the stretch with that strain.
Eigen::Matrix2d stretch_of_strain(const Voigt& e) {
  Eigen::Matrix2d E;
  E << e(0), e(2) / 2, e(2) / 2, e(1);
  return stretch_of(Eigen::Matrix2d::Identity() + 2 * E);
}

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

std::vector<Eigen::Matrix2d> deformations() {
  std::vector<Eigen::Matrix2d> F(4);
  F[0] << 1.2, 0.3, -0.1, 0.9;     // stretch and shear
  F[1] << 0.7, 0.05, 0.1, 0.8;     // compression
  F[2] << 1.0, 0.6, 0.0, 1.0;      // simple shear
  F[3] << 1.5, -0.2, 0.4, 1.3;     // large
  return F;
}

const Law kLaws[] = {Law::saint_venant_kirchhoff, Law::neo_hooke};

}  // namespace

// ℂ = dS/dE: each column against central differences of S in the strain (step 1e-6, error
// O(h²) ~ 1e-12 of the entries; asserted to 1e-7 of the largest entry).
TEST(Hyperelastic, TangentIsDerivativeOfStress) {
  for (Law law : kLaws)
    for (double nu : {0.0, 0.3, 0.45})
      for (const auto& F : deformations()) {
        const auto m = elastic(1000, nu);
        const auto s = hyperelastic_state(m, law, F);
        const Eigen::Matrix2d G = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
        const Voigt e(G(0, 0), G(1, 1), 2 * G(0, 1));
        const double h = 1e-6;
        Elasticity C_fd;
        for (int b = 0; b < 3; ++b) {
          Voigt ep = e, em = e;
          ep(b) += h;
          em(b) -= h;
          C_fd.col(b) = (hyperelastic_state(m, law, stretch_of_strain(ep)).S -
                         hyperelastic_state(m, law, stretch_of_strain(em)).S) / (2 * h);
        }
        EXPECT_LT((C_fd - s.C).cwiseAbs().maxCoeff(), 1e-7 * s.C.cwiseAbs().maxCoeff())
            << law_name(law) << " nu " << nu << "\n" << C_fd << "\n" << s.C;
        EXPECT_LT((s.C - s.C.transpose()).norm(), 1e-12 * s.C.norm());
      }
}

// S = dW/dE: central differences of the energy in the strain (engineering shear: dW/d(2E12) = S12).
TEST(Hyperelastic, StressIsDerivativeOfEnergy) {
  for (Law law : kLaws)
    for (const auto& F : deformations()) {
      const auto m = elastic(1000, 0.3);
      const auto s = hyperelastic_state(m, law, F);
      const Eigen::Matrix2d G = 0.5 * (F.transpose() * F - Eigen::Matrix2d::Identity());
      const Voigt e(G(0, 0), G(1, 1), 2 * G(0, 1));
      const double h = 1e-6;
      for (int b = 0; b < 3; ++b) {
        Voigt ep = e, em = e;
        ep(b) += h;
        em(b) -= h;
        const double dW = (hyperelastic_state(m, law, stretch_of_strain(ep)).W -
                           hyperelastic_state(m, law, stretch_of_strain(em)).W) / (2 * h);
        EXPECT_NEAR(dW, s.S(b), 1e-7 * s.S.norm()) << law_name(law) << " component " << b;
      }
    }
}

// A rigid rotation gives no stress and no energy; a rotation after a stretch changes neither S
// nor W, and turns the Cauchy stress with it (σ(RU) = R σ(U) Rᵀ).
TEST(Hyperelastic, Objectivity) {
  for (Law law : kLaws) {
    const auto m = elastic(210000, 0.3);
    for (double a : {0.3, 1.0, 2.5}) {
      const auto s = hyperelastic_state(m, law, rotation(a));
      EXPECT_LT(s.S.norm(), 1e-9 * 210000) << law_name(law);
      EXPECT_LT(std::abs(s.W), 1e-9 * 210000);
      for (const auto& F : deformations()) {
        const Eigen::Matrix2d U = stretch_of(F.transpose() * F);
        const auto su = hyperelastic_state(m, law, U), sr = hyperelastic_state(m, law, rotation(a) * U);
        EXPECT_LT((su.S - sr.S).norm(), 1e-10 * su.S.norm());
        EXPECT_NEAR(su.W, sr.W, 1e-10 * std::abs(su.W));
        double zu, zr;
        const Voigt cu = cauchy_stress(su, U, &zu), cr = cauchy_stress(sr, rotation(a) * U, &zr);
        Eigen::Matrix2d Su, Sr;
        Su << cu(0), cu(2), cu(2), cu(1);
        Sr << cr(0), cr(2), cr(2), cr(1);
        EXPECT_LT((rotation(a) * Su * rotation(a).transpose() - Sr).norm(), 1e-9 * Su.norm());
        EXPECT_NEAR(zu, zr, 1e-9 * Su.norm());
      }
    }
  }
}

// For a small displacement gradient H = t H0 both laws approach linear elasticity: S and the
// Cauchy stress differ from D ε by O(t²), i.e. relative O(t): asserted < 5 t for t = 1e-3, 1e-5,
// and the tangent at F = I equals D.
TEST(Hyperelastic, SmallStrainLimitIsLinearElasticity) {
  Eigen::Matrix2d H0;
  H0 << 0.8, -0.5, 0.3, 0.6;
  for (Law law : kLaws)
    for (double nu : {0.0, 0.3, 0.49}) {
      const auto m = elastic(1000, nu);
      EXPECT_LT((hyperelastic_state(m, law, Eigen::Matrix2d::Identity()).C - m.D()).norm(),
                1e-12 * m.D().norm());
      for (double t : {1e-3, 1e-5}) {
        const Eigen::Matrix2d F = Eigen::Matrix2d::Identity() + t * H0;
        const Voigt eps(t * H0(0, 0), t * H0(1, 1), t * (H0(0, 1) + H0(1, 0)));
        const Voigt lin = m.D() * eps;
        const auto s = hyperelastic_state(m, law, F);
        double zz;
        const Voigt sigma = cauchy_stress(s, F, &zz);
        EXPECT_LT((s.S - lin).norm(), 5 * t * lin.norm()) << law_name(law) << " t " << t;
        EXPECT_LT((sigma - lin).norm(), 5 * t * lin.norm());
        EXPECT_NEAR(zz, m.sigma_zz(lin), 5 * t * lin.norm());
        EXPECT_NEAR(s.W, 0.5 * eps.dot(lin), 5 * t * 0.5 * eps.dot(lin));
      }
    }
}

// With nu = 0 (λ = 0) the two compressible Neo-Hooke forms in use agree, and in uniaxial
// stretch λ1 the Neo-Hooke S11 = μ (1 − 1/λ1²) (closed form).
TEST(Hyperelastic, NeoHookeUniaxialClosedForm) {
  const auto m = elastic(1000, 0.0);
  const double mu = 500;
  for (double l1 : {0.5, 0.9, 1.1, 2.0}) {
    Eigen::Matrix2d F = Eigen::Matrix2d::Identity();
    F(0, 0) = l1;
    const auto s = hyperelastic_state(m, Law::neo_hooke, F);
    EXPECT_NEAR(s.S(0), mu * (1 - 1 / (l1 * l1)), 1e-12 * mu);
    EXPECT_NEAR(s.S(1), 0, 1e-12 * mu);
    EXPECT_NEAR(s.W, 0.5 * mu * (l1 * l1 - 1) - mu * std::log(l1), 1e-12 * mu);
  }
}

namespace {

/// Lamé's constants of E, ν (the laws' own parameters).
struct Lame {
  double lambda, mu;
};
Lame lame_of(double E, double nu) {
  return {E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
}

/// The Cauchy stress (xx, yy, xy) and σ_zz of `law` at F, from the law's own parameters.
Voigt cauchy_of(const LinearElastic& m, Law law, const Eigen::Matrix2d& F, double* zz) {
  return cauchy_stress(hyperelastic_state(m, law, F), F, zz);
}

}  // namespace

// The Cauchy stress of both laws in plane-strain uniaxial stretch F = diag(s, 1) shall equal
// the closed forms derived here by hand (s = 0.6 … 1.8, ν = 0.3), to 1e-13 of μ:
//  - Neo-Hooke: σ = (μ/J)(b − I) + (λ ln J / J) I with b = F Fᵀ (push-forward of
//    S = μ(I − C⁻¹) + λ ln J C⁻¹: F C⁻¹ Fᵀ = I, F Fᵀ = b). With J = s, b = diag(s², 1, 1):
//    σxx = μ (s² − 1)/s + λ ln s / s,  σyy = σzz = λ ln s / s,  σxy = 0.
//  - St. Venant–Kirchhoff: E = diag(e, 0, 0), e = (s² − 1)/2, S = λ e I + 2μ E, σ = F S Fᵀ / J:
//    σxx = s² (λ + 2μ) e / s = s (λ + 2μ) e,  σyy = σzz = λ e / s,  σxy = 0.
// The 1/J of the push-forward shows here (J = s ≠ 1).
TEST(HyperelasticCauchy, UniaxialStretchClosedForms) {
  const double E = 1000, nu = 0.3;
  const auto m = elastic(E, nu);
  const auto [lambda, mu] = lame_of(E, nu);
  for (double s : {0.6, 0.9, 1.25, 1.8}) {
    Eigen::Matrix2d F = Eigen::Matrix2d::Identity();
    F(0, 0) = s;
    const double e = (s * s - 1) / 2;
    struct Expected {
      Law law;
      double xx, yy, zz;
    };
    for (const auto& x : {Expected{Law::neo_hooke, mu * (s * s - 1) / s + lambda * std::log(s) / s,
                                   lambda * std::log(s) / s, lambda * std::log(s) / s},
                          Expected{Law::saint_venant_kirchhoff, s * (lambda + 2 * mu) * e,
                                   lambda * e / s, lambda * e / s}}) {
      double zz = 0;
      const Voigt sigma = cauchy_of(m, x.law, F, &zz);
      EXPECT_NEAR(sigma(0), x.xx, 1e-13 * mu) << law_name(x.law) << " s " << s;
      EXPECT_NEAR(sigma(1), x.yy, 1e-13 * mu) << law_name(x.law) << " s " << s;
      EXPECT_NEAR(sigma(2), 0, 1e-13 * mu) << law_name(x.law) << " s " << s;
      EXPECT_NEAR(zz, x.zz, 1e-13 * mu) << law_name(x.law) << " s " << s;
    }
  }
}

// The Cauchy stress of both laws in simple shear F = [[1, γ], [0, 1]] (J = 1) shall equal the
// closed forms derived here by hand (γ = 0.1 … 1), to 1e-13 of μ:
//  - Neo-Hooke: b − I = [[γ², γ], [γ, 0]], ln J = 0: σxx = μ γ², σyy = 0, σxy = μ γ, σzz = 0
//    (the normal stress σxx − σyy = μ γ² of the Poynting effect).
//  - St. Venant–Kirchhoff: C = [[1, γ], [γ, 1 + γ²]], E = ½ [[0, γ], [γ, γ²]], tr E = γ²/2,
//    S = [[λγ²/2, μγ], [μγ, (λ/2 + μ) γ²]], σ = F S Fᵀ:
//    σxx = S11 + 2γ S12 + γ² S22 = (λ/2 + 2μ) γ² + (λ/2 + μ) γ⁴,
//    σxy = S12 + γ S22 = μ γ + (λ/2 + μ) γ³,  σyy = S22 = (λ/2 + μ) γ²,  σzz = S33 = λ γ²/2.
TEST(HyperelasticCauchy, SimpleShearClosedForms) {
  const double E = 1000, nu = 0.3;
  const auto m = elastic(E, nu);
  const auto [lambda, mu] = lame_of(E, nu);
  for (double g : {0.1, 0.4, 1.0, -0.7}) {
    Eigen::Matrix2d F = Eigen::Matrix2d::Identity();
    F(0, 1) = g;
    const double g2 = g * g;
    double zz = 0;
    Voigt sigma = cauchy_of(m, Law::neo_hooke, F, &zz);
    EXPECT_NEAR(sigma(0), mu * g2, 1e-13 * mu) << "neo-hooke γ " << g;
    EXPECT_NEAR(sigma(1), 0, 1e-13 * mu) << "neo-hooke γ " << g;
    EXPECT_NEAR(sigma(2), mu * g, 1e-13 * mu) << "neo-hooke γ " << g;
    EXPECT_NEAR(zz, 0, 1e-13 * mu) << "neo-hooke γ " << g;
    sigma = cauchy_of(m, Law::saint_venant_kirchhoff, F, &zz);
    EXPECT_NEAR(sigma(0), (lambda / 2 + 2 * mu) * g2 + (lambda / 2 + mu) * g2 * g2, 1e-13 * mu)
        << "svk γ " << g;
    EXPECT_NEAR(sigma(1), (lambda / 2 + mu) * g2, 1e-13 * mu) << "svk γ " << g;
    EXPECT_NEAR(sigma(2), mu * g + (lambda / 2 + mu) * g2 * g, 1e-13 * mu) << "svk γ " << g;
    EXPECT_NEAR(zz, lambda * g2 / 2, 1e-13 * mu) << "svk γ " << g;
  }
}
