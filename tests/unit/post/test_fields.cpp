// Stress measures of the post-processing against values worked out by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "hpcontact/post/fields.hpp"

using namespace hpcontact;

// von Mises shall be |s| in uniaxial stress, √3 |τ| in pure shear, 0 under hydrostatic stress,
// s in equibiaxial plane stress, and for (sxx, syy, szz, sxy) = (100, −50, 15, 40):
// ½ (150² + 65² + 85²) + 3·40² = 16975 + 4800 = 21775, √21775 (to 1e-13 relative).
TEST(VonMises, HandValues) {
  EXPECT_NEAR(post::von_mises(250, 0, 0, 0), 250, 1e-13 * 250);
  EXPECT_NEAR(post::von_mises(0, -250, 0, 0), 250, 1e-13 * 250);
  EXPECT_NEAR(post::von_mises(0, 0, 0, 70), std::sqrt(3.0) * 70, 1e-13 * 70);
  EXPECT_NEAR(post::von_mises(-80, -80, -80, 0), 0, 1e-13 * 80);
  EXPECT_NEAR(post::von_mises(60, 60, 0, 0), 60, 1e-13 * 60);
  EXPECT_NEAR(post::von_mises(100, -50, 15, 40), std::sqrt(21775.0), 1e-13 * 150);
}

// von Mises shall not change when the in-plane stress state is turned (σ' = R σ Rᵀ), nor when a
// hydrostatic stress is added to all three normal stresses (it measures the deviator only).
TEST(VonMises, InvariantUnderRotationAndPressure) {
  const double sxx = 100, syy = -50, szz = 15, sxy = 40, ref = post::von_mises(sxx, syy, szz, sxy);
  for (double a : {0.3, 1.1, 2.0}) {
    const double c = std::cos(a), s = std::sin(a);
    const double rxx = c * c * sxx + s * s * syy - 2 * c * s * sxy;
    const double ryy = s * s * sxx + c * c * syy + 2 * c * s * sxy;
    const double rxy = c * s * (sxx - syy) + (c * c - s * s) * sxy;
    EXPECT_NEAR(post::von_mises(rxx, ryy, szz, rxy), ref, 1e-12 * ref) << a;
  }
  EXPECT_NEAR(post::von_mises(sxx + 33, syy + 33, szz + 33, sxy), ref, 1e-12 * ref);
}

// The principal stresses of (100, −50, 40) shall be 25 ± √(75² + 40²) = 25 ± 85 = 110, −60; of
// pure shear τ: ±τ; of a state already principal: its normal stresses, larger first; and their
// sum and product shall be the trace and the determinant of the in-plane stress.
TEST(PrincipalStresses, HandValues) {
  auto near = [](std::array<double, 2> got, double s1, double s2) {
    EXPECT_NEAR(got[0], s1, 1e-13 * std::max(std::abs(s1), std::abs(s2)));
    EXPECT_NEAR(got[1], s2, 1e-13 * std::max(std::abs(s1), std::abs(s2)));
  };
  near(post::principal_stresses(100, -50, 40), 110, -60);
  near(post::principal_stresses(0, 0, 70), 70, -70);
  near(post::principal_stresses(-30, 20, 0), 20, -30);
  near(post::principal_stresses(20, -30, 0), 20, -30);
  const double sxx = 13, syy = -7, sxy = 21;
  const auto p = post::principal_stresses(sxx, syy, sxy);
  EXPECT_NEAR(p[0] + p[1], sxx + syy, 1e-13 * 30);
  EXPECT_NEAR(p[0] * p[1], sxx * syy - sxy * sxy, 1e-12 * 600);
}
