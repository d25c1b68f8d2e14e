// A 3D problem discretised and solved: one body of hierarchic hexahedra, linear elasticity.
#pragma once

#include <array>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/hex_dof_map.hpp"
#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/mesh/hex_mesh.hpp"
#include "hpcontact/model/solid_spec.hpp"

namespace hpcontact::model {

/// The mesh a spec's generator builds (face sets named as io::solid_face_set_names says).
mesh::HexMesh solid_mesh(const SolidMeshSpec& spec, const std::string& context);

/// The body's mesh, modes and law.
struct SolidDiscretization {
  mesh::HexMesh mesh;
  fem::HexDofMap dofs;
  material::LinearElastic material;
  /// The dofs (3 mode + component) the constraints prescribe, and their values.
  std::vector<int> fixed;
  std::vector<double> fixed_values;
  int n_free() const { return dofs.n_dofs() - static_cast<int>(fixed.size()); }
  /// Free dofs after condensing the internal modes (the prescribed ones are all external).
  int n_free_external() const {
    return 3 * dofs.n_external_modes() - static_cast<int>(fixed.size());
  }
};

/// Builds the mesh and the modes of `spec` (degrees and space for every element) and the
/// prescribed dofs: every mode on a constrained face gets the face's component value at its
/// vertex modes and zero at the others (a constant on the face). Two constraints that give one
/// node's component different values are refused, naming both.
SolidDiscretization discretize_solid(const SolidSpec& spec, const std::string& file);

struct SolidSolution {
  Eigen::VectorXd u;  ///< every dof, 3 mode + component
  int n_system = 0;   ///< unknowns of the condensed system solved
  double assembly_seconds = 0, solve_seconds = 0;
};

/// Assembles (internal modes condensed), loads (face loads, body force), solves and recovers.
/// A body not held against rigid motion is refused (NumericalError naming the file).
SolidSolution solve_solid(const SolidSpec& spec, const SolidDiscretization& d,
                          const std::string& file);

/// An element's local coefficients (component-blocked) from the global dofs.
Eigen::VectorXd element_coefficients(const SolidDiscretization& d, int element,
                                     const Eigen::VectorXd& u);

}  // namespace hpcontact::model
