// St. Venant–Kirchhoff and compressible Neo-Hooke in plane strain.
#include "hpcontact/material/hyperelastic.hpp"

#include <cmath>

namespace hpcontact::material {

std::string law_name(Law law) {
  switch (law) {
    case Law::linear: return "linear-elastic";
    case Law::saint_venant_kirchhoff: return "saint-venant-kirchhoff";
    case Law::neo_hooke: return "neo-hooke";
  }
  return "?";
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

Voigt cauchy_stress(const HyperelasticState& state, const Eigen::Matrix2d& F, double* sigma_zz) {
  Eigen::Matrix2d S;
  S << state.S(0), state.S(2), state.S(2), state.S(1);
  const Eigen::Matrix2d sigma = F * S * F.transpose() / state.J;
  if (sigma_zz) *sigma_zz = state.S33 / state.J;
  return {sigma(0, 0), sigma(1, 1), sigma(0, 1)};
}

}  // namespace hpcontact::material
