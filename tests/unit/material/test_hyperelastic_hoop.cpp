// The axisymmetric (hoop) hyperelastic state: ℂ = dS/dE and S = dW/dE by central differences in
// all four strains, the plane-strain state recovered at F_θθ = 1, and the linear axisymmetric
// stress at small strain.
#include "hpcontact/material/hyperelastic_hoop.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

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
