// Property tests of the linear elastic law: the plane D matrices, validation, out-of-plane stress;
// the 3D law, its compliance, and the plane laws as its reductions.
#include "hpcontact/material/linear_elastic.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hpcontact/core/error.hpp"

using hpcontact::InputError;
using namespace hpcontact::material;

namespace {

struct Pair {
  double E, nu;
};
std::vector<Pair> materials() {
  return {{210000, 0.3}, {1.0, 0.0}, {70e9, 0.33}, {5.0, -0.5}, {1e3, 0.49}, {2.5, 0.4999}};
}

LinearElastic make(double E, double nu, Plane plane) {
  LinearElastic m;
  m.youngs_modulus = E;
  m.poisson_ratio = nu;
  m.plane = plane;
  return m;
}

// The in-plane rows/columns (xx, yy, xy) of the 3D Voigt order, and the out-of-plane ones.
const int kInPlane[3] = {0, 1, 5};
const int kOutOfPlane[3] = {2, 3, 4};

}  // namespace

// Plane strain D shall equal the hand formula E/((1+nu)(1-2nu)) [[1-nu, nu, 0], [nu, 1-nu, 0],
// [0, 0, (1-2nu)/2]] to 1e-14 relative, and its inverse the compliance (1+nu)/E [[1-nu, -nu, 0],
// [-nu, 1-nu, 0], [0, 0, 2]] (so eps_zz = 0 is built in).
TEST(LinearElastic, PlaneStrainMatrix) {
  for (auto [E, nu] : materials()) {
    const Elasticity D = make(E, nu, Plane::strain).D();
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    Elasticity expected;
    expected << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
    EXPECT_LE((D - expected).norm(), 1e-14 * expected.norm()) << "E " << E << " nu " << nu;
    Elasticity C;
    C << 1 - nu, -nu, 0, -nu, 1 - nu, 0, 0, 0, 2;
    C *= (1 + nu) / E;
    // D is ill-conditioned as nu -> 0.5; the bound scales with its condition number.
    const double cond = D.norm() * C.norm();
    EXPECT_LE((D * C - Elasticity::Identity()).norm(), 1e-14 * cond) << "E " << E << " nu " << nu;
  }
}

// Plane stress D shall equal E/(1-nu²) [[1, nu, 0], [nu, 1, 0], [0, 0, (1-nu)/2]] to 1e-14
// relative, and its inverse the compliance 1/E [[1, -nu, 0], [-nu, 1, 0], [0, 0, 2(1+nu)]].
TEST(LinearElastic, PlaneStressMatrix) {
  for (auto [E, nu] : materials()) {
    const Elasticity D = make(E, nu, Plane::stress).D();
    Elasticity expected;
    expected << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
    expected *= E / (1 - nu * nu);
    EXPECT_LE((D - expected).norm(), 1e-14 * expected.norm()) << "E " << E << " nu " << nu;
    Elasticity C;
    C << 1, -nu, 0, -nu, 1, 0, 0, 0, 2 * (1 + nu);
    C /= E;
    EXPECT_LE((D * C - Elasticity::Identity()).norm(), 1e-13) << "E " << E << " nu " << nu;
  }
}

// Both D matrices shall be symmetric positive definite and isotropic: the shear entry equals
// (D11 - D12)/2, so rotating the strain rotates the stress.
TEST(LinearElastic, MatricesAreSymmetricPositiveDefiniteAndIsotropic) {
  for (auto [E, nu] : materials())
    for (Plane plane : {Plane::strain, Plane::stress}) {
      const Elasticity D = make(E, nu, plane).D();
      EXPECT_EQ((D - D.transpose()).norm(), 0.0);
      Eigen::SelfAdjointEigenSolver<Elasticity> eig(D);
      EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0) << "E " << E << " nu " << nu;
      EXPECT_NEAR(D(2, 2), 0.5 * (D(0, 0) - D(0, 1)), 1e-14 * D.norm());
      EXPECT_EQ(D(0, 2), 0.0);
      EXPECT_EQ(D(1, 2), 0.0);
    }
}

// validate() shall reject E <= 0 (naming the key ".E"), nu >= 0.5 and nu <= -1 (naming ".nu")
// and non-finite values, and accept values just inside the bounds.
TEST(LinearElastic, ValidateRejectsOutOfRangeParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto expect_rejected = [](double E, double nu, const std::string& key) {
    try {
      make(E, nu, Plane::strain).validate("bodies[2].material");
      ADD_FAILURE() << "no InputError for E = " << E << ", nu = " << nu;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bodies[2].material" + key), std::string::npos)
          << e.what();
    }
  };
  for (double E : {0.0, -1.0, -210000.0, nan, inf}) expect_rejected(E, 0.3, ".E");
  for (double nu : {0.5, 0.51, 1.0, -1.0, -1.5, nan}) expect_rejected(210000, nu, ".nu");
  for (auto [E, nu] : materials()) {
    EXPECT_NO_THROW(make(E, nu, Plane::strain).validate("m"));
    EXPECT_NO_THROW(make(E, nu, Plane::stress).validate("m"));
  }
  EXPECT_NO_THROW(make(1e-300, -0.999999, Plane::stress).validate("m"));
}

// In plane strain sigma_zz shall be the stress that keeps eps_zz = 0, i.e. lambda (eps_xx +
// eps_yy) = nu (sigma_xx + sigma_yy); in plane stress it shall be zero.
TEST(LinearElastic, OutOfPlaneStress) {
  for (auto [E, nu] : materials()) {
    const Voigt eps(1e-3, -4e-4, 2.5e-4);
    const LinearElastic strain = make(E, nu, Plane::strain);
    const Voigt sigma = strain.D() * eps;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double szz = strain.sigma_zz(sigma);
    EXPECT_NEAR(szz, lambda * (eps(0) + eps(1)), 1e-13 * sigma.norm()) << "nu " << nu;
    // Hooke in 3D: eps_zz = (szz - nu (sxx + syy)) / E = 0.
    EXPECT_NEAR((szz - nu * (sigma(0) + sigma(1))) / E, 0.0, 1e-13 * eps.norm());
    const LinearElastic stress = make(E, nu, Plane::stress);
    EXPECT_EQ(stress.sigma_zz(stress.D() * eps), 0.0);
  }
}

// The 3D law (LinearElastic::D3) and the plane laws as its reductions.
// D3 shall be symmetric and its inverse the 3D compliance 1/E [[1, -nu, -nu], [-nu, 1, -nu],
// [-nu, -nu, 1]] ⊕ 2(1 + nu)/E I₃ (engineering shears), to 1e-14 times its condition number
// (measured: 4e-16 relative at nu = 0.3, 2e-13 absolute at nu = 0.4999).
TEST(LinearElastic3D, InverseIsTheCompliance) {
  for (auto [E, nu] : materials()) {
    const Elasticity3 D = make(E, nu, Plane::strain).D3();
    EXPECT_EQ((D - D.transpose()).norm(), 0.0);
    Elasticity3 C = Elasticity3::Zero();
    C.topLeftCorner<3, 3>().setConstant(-nu / E);
    C.diagonal() << 1 / E, 1 / E, 1 / E, 2 * (1 + nu) / E, 2 * (1 + nu) / E, 2 * (1 + nu) / E;
    const double cond = D.norm() * C.norm();
    EXPECT_LE((D * C - Elasticity3::Identity()).norm(), 1e-14 * cond) << "E " << E << " nu " << nu;
    // The shear diagonal is μ, the volumetric block λ + 2μ on the diagonal and λ off it.
    const LinearElastic m = make(E, nu, Plane::stress);
    EXPECT_NEAR(D(3, 3), m.mu(), 1e-15 * E);
    EXPECT_NEAR(D(0, 1), m.lambda(), 1e-15 * D.norm());
    EXPECT_NEAR(D(2, 2), m.lambda() + 2 * m.mu(), 1e-15 * D.norm());
  }
}

// Plane strain (eps_zz = gamma_yz = gamma_xz = 0) shall be the 3D law restricted to (xx, yy, xy):
// its D equal to that block of D3 to 1e-15 relative, and its sigma_zz the 3D zz stress of an
// in-plane strain.
TEST(LinearElastic3D, PlaneStrainIsTheRestriction) {
  for (auto [E, nu] : materials()) {
    const LinearElastic m = make(E, nu, Plane::strain);
    const Elasticity3 D3 = m.D3();
    Elasticity restricted;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) restricted(r, c) = D3(kInPlane[r], kInPlane[c]);
    EXPECT_LE((m.D() - restricted).norm(), 1e-15 * restricted.norm()) << "E " << E << " nu " << nu;

    const Voigt eps(1e-3, -2e-3, 5e-4);
    Voigt3 eps3 = Voigt3::Zero();
    for (int r = 0; r < 3; ++r) eps3(kInPlane[r]) = eps(r);
    const Voigt3 sigma3 = D3 * eps3;
    EXPECT_NEAR(m.sigma_zz(m.D() * eps), sigma3(2), 1e-14 * sigma3.norm());
    EXPECT_EQ(sigma3(3), 0.0);
    EXPECT_EQ(sigma3(4), 0.0);
  }
}

// Plane stress (sigma_zz = tau_yz = tau_xz = 0) shall be the static condensation of the 3D law:
// D = D_pp − D_po D_oo⁻¹ D_op over p = (xx, yy, xy), o = (zz, yz, xz), to 1e-15 relative times
// the condition number of D3 (measured: ≤ 3e-16 relative for nu ≤ 0.33, 1.2e-13 at nu = 0.4999,
// where the condition number is 7.5e3).
TEST(LinearElastic3D, PlaneStressIsTheCondensation) {
  for (auto [E, nu] : materials()) {
    const LinearElastic m = make(E, nu, Plane::stress);
    const Elasticity3 D3 = m.D3();
    Eigen::Matrix3d Dpp, Dpo, Doo;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        Dpp(r, c) = D3(kInPlane[r], kInPlane[c]);
        Dpo(r, c) = D3(kInPlane[r], kOutOfPlane[c]);
        Doo(r, c) = D3(kOutOfPlane[r], kOutOfPlane[c]);
      }
    const Eigen::Matrix3d condensed = Dpp - Dpo * Doo.inverse() * Dpo.transpose();
    const double cond = D3.norm() * D3.inverse().norm();
    EXPECT_LE((m.D() - condensed).norm(), 1e-15 * cond * condensed.norm())
        << "E " << E << " nu " << nu;
    // The condensation is not the restriction (unless nu = 0): the test can tell them apart.
    if (nu != 0) EXPECT_GT((m.D() - Dpp).norm(), 1e-3 * Dpp.norm());
  }
}
