// St. Venant–Kirchhoff, compressible Neo-Hooke and the rubber laws in plane strain.
#include "hpcontact/material/hyperelastic.hpp"

#include <cmath>

namespace hpcontact::material {

std::string law_name(Law law) {
  switch (law) {
    case Law::linear: return "linear-elastic";
    case Law::saint_venant_kirchhoff: return "saint-venant-kirchhoff";
    case Law::neo_hooke: return "neo-hooke";
    case Law::neo_hooke_split: return "neo-hooke-split";
    case Law::mooney_rivlin: return "mooney-rivlin";
    case Law::yeoh: return "yeoh";
  }
  return "?";
}

bool is_rubber(Law law) {
  return law == Law::neo_hooke_split || law == Law::mooney_rivlin || law == Law::yeoh;
}

namespace {

/// Voigt index pairs (11, 22, 12).
constexpr int kI[3] = {0, 1, 0}, kJ[3] = {0, 1, 1};

}  // namespace

HyperelasticState hyperelastic_state(const LinearElastic& elastic, Law law, const Eigen::Matrix2d& F) {
  const double E = elastic.youngs_modulus, nu = elastic.poisson_ratio;
  const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  HyperelasticState s;
  s.J = F.determinant();
  const Eigen::Matrix2d C = F.transpose() * F;
  if (law == Law::neo_hooke) {
    const Eigen::Matrix2d Ci = C.inverse();
    const double lnJ = std::log(s.J);
    const Eigen::Matrix2d S = mu * (Eigen::Matrix2d::Identity() - Ci) + lambda * lnJ * Ci;
    s.S << S(0, 0), S(1, 1), S(0, 1);
    s.S33 = lambda * lnJ;  // C33 = 1
    s.W = 0.5 * mu * (C.trace() + 1 - 3) - mu * lnJ + 0.5 * lambda * lnJ * lnJ;
    const double c = 2 * (mu - lambda * lnJ);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const int i = kI[a], j = kJ[a], k = kI[b], l = kJ[b];
        s.C(a, b) = lambda * Ci(i, j) * Ci(k, l) + c * 0.5 * (Ci(i, k) * Ci(j, l) + Ci(i, l) * Ci(j, k));
      }
    return s;
  }
  // St. Venant–Kirchhoff (and the linear law's D, to which it reduces).
  const Eigen::Matrix2d G = 0.5 * (C - Eigen::Matrix2d::Identity());
  const Voigt e(G(0, 0), G(1, 1), 2 * G(0, 1));
  s.C = elastic.D();
  s.S = s.C * e;
  s.S33 = elastic.sigma_zz(s.S);
  s.W = 0.5 * e.dot(s.S);
  return s;
}

HyperelasticState hyperelastic_state(const FiniteStrainLaw& law, const Eigen::Matrix2d& F) {
  if (!is_rubber(law.law)) return hyperelastic_state(law.elastic, law.law, F);
  Eigen::Matrix3d C = Eigen::Matrix3d::Identity();
  C.topLeftCorner<2, 2>() = F.transpose() * F;
  const StressTangent3 r = rubber_stress(law.rubber, C);
  constexpr int kPlane[3] = {0, 1, 5};  // (11, 22, 12) in the 3-D Voigt order
  HyperelasticState s;
  s.J = F.determinant();
  s.W = r.W;
  s.S << r.S(0, 0), r.S(1, 1), r.S(0, 1);
  s.S33 = r.S(2, 2);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) s.C(a, b) = r.C(kPlane[a], kPlane[b]);
  return s;
}

Voigt cauchy_stress(const HyperelasticState& state, const Eigen::Matrix2d& F, double* sigma_zz) {
  Eigen::Matrix2d S;
  S << state.S(0), state.S(2), state.S(2), state.S(1);
  const Eigen::Matrix2d sigma = F * S * F.transpose() / state.J;
  if (sigma_zz) *sigma_zz = state.S33 / state.J;
  return {sigma(0, 0), sigma(1, 1), sigma(0, 1)};
}

}  // namespace hpcontact::material
