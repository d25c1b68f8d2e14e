// From a ProblemSpec to the discrete model: meshes, element maps, mode numbering, constraints, loads.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/fem/dof_map.hpp"
#include "hpcontact/fem/out_of_plane.hpp"
#include "hpcontact/material/hyperelastic.hpp"
#include "hpcontact/mesh/element_map.hpp"
#include "hpcontact/mesh/mesh.hpp"
#include "hpcontact/model/follower_load.hpp"
#include "hpcontact/model/problem_spec.hpp"

namespace hpcontact::model {

/// One discretised body. Its dofs occupy [dof_offset, dof_offset + dofs.n_dofs()) globally.
struct Body {
  std::string name;
  mesh::Mesh mesh;
  fem::DofMap dofs;
  std::vector<mesh::ElementMap> maps;  ///< per element
  std::vector<int> n_gauss;            ///< Gauss points per direction, per element
  material::LinearElastic material;
  double thickness = 1.0;
  int dof_offset = 0;
  std::map<std::string, std::vector<int>> edge_sets;  ///< name -> mesh edges
  /// Linear elasticity, or a hyperelastic law of finite strain (total Lagrangian). A rubber law
  /// takes its constants from `rubber`; `material` is then its small-strain equivalent.
  material::Law law = material::Law::linear;
  /// The rubber law's constants (a body of a rubber law has no regions).
  material::RubberConstants rubber;
  bool finite_strain() const { return law != material::Law::linear; }
  /// The meridian section of a solid of revolution about x = 0 (integrals over 2π r dA).
  bool axisymmetric() const { return material.plane == material::Plane::axisymmetric; }
  /// What turns the section's integrals into the solid's: the thickness, or 2π r.
  fem::OutOfPlane out_of_plane() const { return {thickness, axisymmetric()}; }
  /// Elastic constants of the material regions, and per element its region (-1: `material`).
  std::vector<material::LinearElastic> region_materials;
  std::vector<int> element_region;
  /// Per entry of the body's constraints (BodySpec::constraints), the global dofs it holds: its
  /// edges' vertex and edge modes and its nodes' vertex modes, in the components it prescribes;
  /// a dof two entries prescribe belongs to the first listed (the one its reaction is
  /// reported for).
  std::vector<std::vector<int>> constraint_dofs;
  /// Rigid-body motions the constraints leave free (model/rigid_motion.hpp); empty: held.
  std::vector<std::string> free_rigid_motions;
  /// The elastic constants of element q.
  const material::LinearElastic& material_of(int q) const {
    const int r = element_region.empty() ? -1 : element_region[q];
    return r < 0 ? material : region_materials[r];
  }
  /// The finite-strain law of element q with its constants.
  material::FiniteStrainLaw finite_strain_law(int q) const { return {law, material_of(q), rubber}; }

  /// Global dof of local dof `local` of element q: component-blocked displacements (2 n), then
  /// for a mixed body its pressure modes.
  int global_dof(int q, int local) const {
    const auto& es = dofs.element(q);
    const int n = es.n_modes();
    if (local >= 2 * n) return pressure_first[q] + local - 2 * n;
    return dof_offset + 2 * es.modes[local % n] + local / n;
  }

  /// Local coefficients of element q (component-blocked) from the global dof vector u.
  Eigen::VectorXd element_coefficients(int q, const Eigen::VectorXd& u) const {
    Eigen::VectorXd ue(2 * dofs.element(q).n_modes());
    for (int a = 0; a < ue.size(); ++a) ue(a) = u(global_dof(q, a));
    return ue;
  }

  /// The mixed u–p element of a rubber law (fem/mixed_finite_strain.hpp): per element the
  /// coefficients of a discontinuous pressure of total degree p − 1, global dofs after all
  /// bodies' displacement dofs (Discretization), for every K. Not eliminated per element: with
  /// 1/K = 0 the element's pressure block is zero; with a finite K the elimination is exact
  /// (p = K M⁻¹ ∫ ψ (J − 1) dV) but was measured to slow Newton as K grows — 70 and 234
  /// iterations on the incompressible O-ring's mesh at K/μ = 10³ and 10⁴ against 19 with the
  /// pressure as unknowns (docs/theory.md §12, "Solving"). Their system is symmetric indefinite:
  /// LU, as finite strain is solved anyway.
  bool mixed = false;
  /// 1/K of the mixed element: 0 when incompressible.
  double inverse_bulk = 0;
  /// Per element q its first pressure dof, and after the last element the end: element q's
  /// pressure dofs are [pressure_first[q], pressure_first[q + 1]). Empty unless mixed.
  std::vector<int> pressure_first;
  int n_pressure_modes(int q) const { return mixed ? pressure_first[q + 1] - pressure_first[q] : 0; }
  /// Element q's pressure coefficients from the global dof vector u (empty unless mixed).
  Eigen::VectorXd element_pressures(int q, const Eigen::VectorXd& u) const {
    if (!mixed) return {};
    return u.segment(pressure_first[q], n_pressure_modes(q));
  }
};

/// The whole discrete problem. The dofs are the bodies' displacement dofs, body after body, then
/// the pressure dofs of mixed bodies. Free dofs are numbered external modes first (all bodies),
/// then internal modes, then pressures, so the condensed system is the leading block.
struct Discretization {
  std::vector<Body> bodies;
  std::string method;  ///< "p" or "h"
  int n_dofs = 0;      ///< all dofs, free and prescribed
  int n_free = 0;      ///< free unknowns (summary.json "dofs")
  int n_free_external = 0;
  std::vector<int> free_index;  ///< per dof: its index among the free ones, or -1 if prescribed
  Eigen::VectorXd prescribed;   ///< per dof: its prescribed value (0 where free)
  Eigen::VectorXd load;         ///< external load per dof (edge loads, nodal forces, body force)
  /// The follower pressures of finite-strain bodies, which act on the deformed boundary and so
  /// are not in `load` (a linear body's follower pressure is a dead one, in `load`).
  std::vector<FollowerLoad> follower_loads;
  /// What the input allows but a user should know (each names the file, the place and the
  /// cause): `check` and `run` print them, summary.json lists them.
  std::vector<std::string> warnings;

  /// Whether a body is of finite strain (then the problem is nonlinear even without contact).
  bool finite_strain() const {
    for (const auto& b : bodies)
      if (b.finite_strain()) return true;
    return false;
  }
};

/// Builds the discretisation; input errors name the problem file and key (InputError, MeshError).
Discretization discretize(const ProblemSpec& spec);

}  // namespace hpcontact::model
