// VTU (ParaView) output of a solution, each element subdivided so the high-order field shows.
#pragma once

#include <string>

#include <Eigen/Dense>

#include "hpcontact/model/discretization.hpp"

namespace hpcontact::post {

/// Writes an unstructured grid: each element sampled on an (s+1)×(s+1) grid of its reference
/// square, s = subdivisions (0: the element's degree, at least 2 and at most 16), as linear quads.
/// Point data: displacement, strains (strain_xx, strain_yy, gamma_xy: Green–Lagrange under finite
/// strain), stress components, von Mises, principal stresses; cell data: body,
/// element id, degree. Throws IoError if the file cannot be written.
void write_vtu(const std::string& path, const model::Discretization& d, const Eigen::VectorXd& u,
               int subdivisions = 0);

}  // namespace hpcontact::post
