// The mixed form's point terms from rubber.hpp's pieces: isochoric_stress plus pressure_stress
// at the element's p, restricted to the components a plane or axisymmetric deformation has.
#include "hpcontact/material/mixed_rubber.hpp"

namespace hpcontact::material {

MixedRubberState mixed_rubber_state(const RubberConstants& constants, const Eigen::Matrix2d& F,
                                    double F33, double p) {
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  C.topLeftCorner<2, 2>() = F.transpose() * F;
  C(2, 2) = F33 * F33;
  const StressTangent3 iso = isochoric_stress(constants, C);
  const StressTangent3 vol = pressure_stress(C, p);
  constexpr int kComponent[4] = {0, 1, 5, 2};  // (11, 22, 12, 33) in the 3-D Voigt order
  MixedRubberState s;
  s.J = F.determinant() * F33;
  s.W_iso = iso.W;
  const Eigen::Matrix3d S = iso.S + vol.S, Ci = C.inverse();
  s.S << S(0, 0), S(1, 1), S(0, 1), S(2, 2);
  s.dJ << Ci(0, 0), Ci(1, 1), Ci(0, 1), Ci(2, 2);
  s.dJ *= s.J;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) s.C(a, b) = iso.C(kComponent[a], kComponent[b]) + vol.C(kComponent[a], kComponent[b]);
  return s;
}

}  // namespace hpcontact::material
