// The pointwise terms of a rubber law in the mixed (perturbed-Lagrangian) form
//   Π = ∫ W_iso(C̄) + p (J − 1) − p² / (2K) dV
// for a 2-D element: the stress and tangent of W_iso + p (J − 1) at a given pressure p, and
// ∂J/∂E, on the in-plane deformation gradient and the out-of-plane stretch (1 in plane strain,
// the hoop stretch in axisymmetry). docs/theory.md §12.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/material/rubber.hpp"

namespace hpcontact::material {

/// Voigt order (11, 22, 12, 33) with the strain (E11, E22, 2 E12, E33); 33 is the out-of-plane
/// (hoop) direction.
struct MixedRubberState {
  Eigen::Vector4d S = Eigen::Vector4d::Zero();  ///< S_iso + J p C⁻¹
  Eigen::Matrix4d C = Eigen::Matrix4d::Zero();  ///< ∂S/∂E at fixed p
  Eigen::Vector4d dJ = Eigen::Vector4d::Zero(); ///< ∂J/∂E = J C⁻¹ (= ∂S/∂p)
  double W_iso = 0;                             ///< W_iso per reference volume
  double J = 1;                                 ///< det F = det F_plane · F33
};

/// The state at the in-plane F and the out-of-plane stretch F33 under the pressure p (positive
/// in tension). Needs det F > 0 and F33 > 0 (the caller checks).
MixedRubberState mixed_rubber_state(const RubberConstants& constants, const Eigen::Matrix2d& F,
                                    double F33, double p);

}  // namespace hpcontact::material
