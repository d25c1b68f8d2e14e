// St. Venant–Kirchhoff, compressible Neo-Hooke and the rubber laws in axisymmetry: the 3-D laws
// on a deformation gradient whose third row and column are the hoop stretch alone (no r–θ or
// z–θ shear).
#include "hpcontact/material/hyperelastic_hoop.hpp"

#include <cmath>

namespace hpcontact::material {

namespace {

/// Voigt index pairs (11, 22, 12, θθ) of the 3 × 3 tensors (θ is index 2).
constexpr int kI[4] = {0, 1, 0, 2}, kJ[4] = {0, 1, 1, 2};

}  // namespace

HoopHyperelasticState hoop_hyperelastic_state(const LinearElastic& elastic, Law law,
                                              const Eigen::Matrix2d& F, double F_hoop) {
  const double E = elastic.youngs_modulus, nu = elastic.poisson_ratio;
  const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  HoopHyperelasticState s;
  s.J = F.determinant() * F_hoop;
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  C.topLeftCorner<2, 2>() = F.transpose() * F;
  C(2, 2) = F_hoop * F_hoop;
  if (law == Law::neo_hooke) {
    Eigen::Matrix3d Ci = Eigen::Matrix3d::Zero();
    Ci.topLeftCorner<2, 2>() = C.topLeftCorner<2, 2>().inverse();
    Ci(2, 2) = 1 / C(2, 2);
    const double lnJ = std::log(s.J);
    const Eigen::Matrix3d S = mu * (Eigen::Matrix3d::Identity() - Ci) + lambda * lnJ * Ci;
    s.S << S(0, 0), S(1, 1), S(0, 1), S(2, 2);
    s.W = 0.5 * mu * (C.trace() - 3) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
    const double c = 2 * (mu - lambda * lnJ);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b) {
        const int i = kI[a], j = kJ[a], k = kI[b], l = kJ[b];
        s.C(a, b) = lambda * Ci(i, j) * Ci(k, l) + c * 0.5 * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
      }
    return s;
  }
  // St. Venant–Kirchhoff: the isotropic 3-D ℂ on (E_rr, E_zz, 2 E_rz, E_θθ).
  const Eigen::Matrix3d G = 0.5 * (C - Eigen::Matrix3d::Identity());
  const Eigen::Vector4d e(G(0, 0), G(1, 1), 2 * G(0, 1), G(2, 2));
  const double l2m = lambda + 2 * mu;
  s.C << l2m, lambda, 0, lambda,  //
      lambda, l2m, 0, lambda,     //
      0, 0, mu, 0,                //
      lambda, lambda, 0, l2m;
  s.S = s.C * e;
  s.W = 0.5 * e.dot(s.S);
  return s;
}

HoopHyperelasticState hoop_hyperelastic_state(const FiniteStrainLaw& law, const Eigen::Matrix2d& F,
                                              double F_hoop) {
  if (!is_rubber(law.law)) return hoop_hyperelastic_state(law.elastic, law.law, F, F_hoop);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  C.topLeftCorner<2, 2>() = F.transpose() * F;
  C(2, 2) = F_hoop * F_hoop;
  const StressTangent3 r = rubber_stress(law.rubber, C);
  constexpr int kHoop[4] = {0, 1, 5, 2};  // (11, 22, 12, θθ) in the 3-D Voigt order
  HoopHyperelasticState s;
  s.J = F.determinant() * F_hoop;
  s.W = r.W;
  s.S << r.S(0, 0), r.S(1, 1), r.S(0, 1), r.S(2, 2);
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) s.C(a, b) = r.C(kHoop[a], kHoop[b]);
  return s;
}

Voigt hoop_cauchy_stress(const HoopHyperelasticState& state, const Eigen::Matrix2d& F,
                         double F_hoop, double* hoop) {
  Eigen::Matrix2d S;
  S << state.S(0), state.S(2), state.S(2), state.S(1);
  const Eigen::Matrix2d sigma = F * S * F.transpose() / state.J;
  if (hoop) *hoop = F_hoop * F_hoop * state.S(3) / state.J;
  return {sigma(0, 0), sigma(1, 1), sigma(0, 1)};
}

}  // namespace hpcontact::material
