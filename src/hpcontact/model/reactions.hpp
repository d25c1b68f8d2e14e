// The reactions of a solved state: what each constraint entry and each contact pair exerts on its
// body, and each body's balance of forces.
#pragma once

#include <limits>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

/// A force on a body and its moment about the origin (z: counter-clockwise positive).
/// Axisymmetric bodies: the force is the ring's total over the whole circle (2π r included, as
/// the contact resultants and loads are), its x the radial total, and there is no moment (NaN).
struct ForceMoment {
  Vec2 force = Vec2::Zero();
  double moment = std::numeric_limits<double>::quiet_NaN();
};

/// What one constraint entry, bodies[body].constraints[constraint], exerts on its body.
struct SupportReaction {
  int body = 0, constraint = 0;
  ForceMoment reaction;
};

/// A body's forces: the sum of its supports' reactions, of its applied loads (tractions,
/// pressures, nodal and body forces, times the loads' factor), and of the contact forces on it.
/// Balanced components: x and y of a plane body, y (the axis) of an axisymmetric one (its radial
/// totals are carried by the hoop stresses, not balanced).
struct BodyBalance {
  Vec2 reactions = Vec2::Zero(), loads = Vec2::Zero(), contact = Vec2::Zero();
  Vec2 imbalance = Vec2::Zero();  ///< reactions + loads + contact, balanced components only
  /// The largest component of imbalance over the largest component of a force involved (a
  /// support's reaction, the loads' total, a pair's force; radial ones too), 0 when none acts.
  double relative = 0;
};

struct Reactions {
  std::vector<SupportReaction> supports;  ///< body by body, constraint entry by entry
  std::vector<ForceMoment> pairs;         ///< per contact pair: the contact force on its body
  std::vector<BodyBalance> balance;       ///< per body
  double equilibrium_residual = 0;        ///< the largest relative imbalance of a body
};

/// The reactions at all dofs u (condensed internal modes recovered) of a converged state, the
/// contact pairs as they were when it converged (with friction: the histories its load step
/// started from) with their multipliers (per pair, empty for the penalty), and the loads'
/// factor there. A support's force is the residual f_int(u) − λ_f f − f_c at its dofs, from the
/// solver's own element routines, summed with resultant_weights; its moment the same residual
/// on the rotation field about the origin (rotation_weights).
Reactions reactions(const Discretization& d, const std::vector<ContactPair>& pairs,
                    const Eigen::VectorXd& u, const std::vector<Eigen::VectorXd>& multipliers,
                    double loads_factor);

/// The residual f_int(u) − λ_f f − f_c(u, λ) at the prescribed dofs (all dofs; zero at free
/// ones): the forces the constraints exert there.
Eigen::VectorXd support_forces(const Discretization& d, const std::vector<ContactPair>& pairs,
                               const Eigen::VectorXd& u,
                               const std::vector<Eigen::VectorXd>& multipliers, double loads_factor);

/// The forces pair k's contact exerts on the bodies (all dofs), by the routines of the solve.
Eigen::VectorXd pair_contact_forces(const Discretization& d, const ContactPair& pair,
                                    const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers);

/// Per mode of a body, the coefficient of the constant field 1: the resultant of a force vector
/// f is Σ_modes w_m (f_2m, f_2m+1). Hierarchic modes: 1 on vertex modes, 0 on edge and internal
/// modes (the vertex modes sum to one over each element, and the edge and internal modes
/// vanish at the vertices, so 1 is the vertex modes alone); Lagrange: 1 on every node.
Eigen::VectorXd resultant_weights(const Body& body);

/// Per mode of a body, the coefficient of the position field X on its boundary: the node at a
/// vertex mode, the edge modes of X along the edge (edge_mode_values: zero on a straight edge),
/// zero on internal modes. Σ_m X_m × (f_2m, f_2m+1) is the moment of a force vector f that acts
/// on the boundary alone: exact on straight edges, on a curved one to the projection's error
/// (exponentially small in p).
std::vector<Vec2> boundary_positions(const Body& body);

/// The force and moment of a body's force vector f (its dofs, local numbering): Σ w_m f_m and
/// Σ x_m × f_m with x_m = X_m (small strain) or X_m + u_m (finite strain: the deformed
/// position, where the force acts; u_body the body's dofs), no moment for axisymmetric bodies.
ForceMoment force_and_moment(const Body& body, const Eigen::VectorXd& f,
                             const Eigen::VectorXd& u_body);

}  // namespace hpcontact::model
