// Fields of a 3D solution: what summary.json reports of it, and solution.vtu.
#pragma once

#include <array>
#include <string>

#include <Eigen/Dense>

#include "hpcontact/model/solid_model.hpp"

namespace hpcontact::post {

/// What a 3D solution gives at every element's Gauss points (and, for the displacement, at the
/// vertices).
struct SolidFields {
  double strain_energy = 0;  ///< ½ ∫ εᵀ D ε dV
  double volume = 0;
  double von_mises_max = 0;
  std::array<double, 3> von_mises_max_at{};
  int von_mises_max_element = -1;
  double displacement_max = 0;  ///< largest |u|
};

SolidFields solid_fields(const model::SolidDiscretization& d, const Eigen::VectorXd& u);

/// Writes solution.vtu: every element as subdivisions³ hexahedral cells (0: its largest degree)
/// on a uniform reference grid, with point arrays displacement, sigma_xx … sigma_xz, von_mises,
/// principal_stress (3, descending) and cell arrays element, degree. Throws IoError.
void write_solid_vtu(const std::string& path, const model::SolidDiscretization& d,
                     const Eigen::VectorXd& u, int subdivisions);

}  // namespace hpcontact::post
