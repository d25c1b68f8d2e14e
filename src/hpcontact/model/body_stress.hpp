// Strain and stress of a body at one point, whatever its law: the linear strain and D ε, or the
// Green–Lagrange strain and the Cauchy stress of the deformed body.
#pragma once

#include <Eigen/Dense>

#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

struct PointStress {
  Eigen::Vector3d strain;  ///< (xx, yy, gamma_xy): linear, or Green–Lagrange (E11, E22, 2 E12)
  Eigen::Vector3d stress;  ///< (xx, yy, xy): D ε, or Cauchy σ = F S Fᵀ / J
  double stress_zz = 0;    ///< out of plane (axisymmetric: the hoop stress σ_θθ)
  Eigen::Matrix2d F = Eigen::Matrix2d::Identity();  ///< deformation gradient (finite strain)
};

/// At a point with shape values pv of element q with local coefficients u_e; a mixed body's
/// stress takes its element's pressure there, `pressure` (model::mixed_pressure), not U'(J).
PointStress point_stress(const Body& body, int q, const fem::PointValues& pv, const Eigen::VectorXd& u_e,
                         double pressure = 0);

}  // namespace hpcontact::model
