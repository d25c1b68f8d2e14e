// The global stiffness and load of a linear-elastic body meshed with hexahedra.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hpcontact/fem/condensation.hpp"
#include "hpcontact/fem/hex_dof_map.hpp"
#include "hpcontact/fem/hex_element.hpp"
#include "hpcontact/material/linear_elastic.hpp"
#include "hpcontact/mesh/hex_map.hpp"

namespace hpcontact::fem {

/// A hexahedral body: its mode numbering, one map per element, the law, a constant body force.
struct HexBody {
  const HexDofMap* dofs = nullptr;
  std::vector<mesh::HexMap> maps;  ///< one per element of the topology the dof map was built on
  material::LinearElastic material;
  mesh::Vec3 body_force = mesh::Vec3::Zero();  ///< force per volume (zero: no load)
  std::string context = "hexahedral mesh";     ///< prefixes error messages
};

struct HexAssemblyOptions {
  /// Eliminate every element's internal modes (fem/condensation.hpp) before assembly: the system
  /// is then over the external dofs only, 0 .. 3 * n_external_modes - 1 (internal modes are
  /// numbered last, hex_dof_map.hpp), and HexSystem::recover gives the internal ones.
  bool condense_internal = false;
  /// The element stiffness kernel (hex_element.hpp): by default the cheaper one per element.
  HexStiffnessKernel kernel = HexStiffnessKernel::automatic;
};

/// K u = f over the global dofs 3 * mode + component (all of them, or the external ones).
struct HexSystem {
  Eigen::SparseMatrix<double> K;
  Eigen::VectorXd f;
  /// Per element, when condensed: what recovers its internal modes (its K and f, assembled,
  /// are left empty).
  std::vector<CondensedElement> condensed;

  /// All dofs (3 * n_modes) from the external ones; the identity (a copy) when not condensed.
  Eigen::VectorXd recover(const HexDofMap& dofs, const Eigen::VectorXd& u) const;
};

/// Assembles the body. Every element's map is first checked (check_hex_jacobian on its Gauss
/// grid): a MeshError names body.context and the element. Element quadrature: hex_gauss_points.
HexSystem assemble_hex_elasticity(const HexBody& body, const HexAssemblyOptions& options = {});

}  // namespace hpcontact::fem
