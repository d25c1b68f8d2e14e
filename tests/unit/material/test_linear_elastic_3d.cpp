// Property tests of the 3D isotropic law: its closed form, its compliance, and the plane laws as
// its reductions.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <vector>

#include "hpcontact/material/linear_elastic.hpp"

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
