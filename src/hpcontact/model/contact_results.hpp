// The results of a contact solve at a state: the points' states, resultants, the ends of the
// contact zone (Γ*), and the pressures at the points (from the stresses and the method).
#pragma once

#include <utility>
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "hpcontact/contact/stick_slip.hpp"
#include "hpcontact/model/contact_pairs.hpp"
#include "hpcontact/model/singular_points.hpp"

namespace hpcontact::model {

/// Ends of the contact zone along one body's contact boundary (Pegasus on the gap between the
/// contact points where it changes sign, seed §4.7).
struct ZoneEnds {
  std::vector<Vec2> X;     ///< undeformed
  std::vector<Vec2> x;     ///< deformed
  std::vector<int> outer;  ///< indices of the outer ends of the active region (see ContactResult)
};

/// State of the contact after a solve: per pair, its points' states and derived figures.
struct ContactResult {
  /// Per contact point of the pair: its Gauss points (penalty, mortar) or its multiplier nodes
  /// (collocation); the pressure of an exactly enforced pair is its multiplier there.
  std::vector<contact::PointState> states;
  std::vector<Vec2> X;  ///< the undeformed position of each state's point
  /// Per state: its position along the obstacle (ContactPair::coordinate of X).
  std::vector<double> s;
  /// Per state: the contact pressure, the normal contact force per unit length along the
  /// obstacle at s: the traction the method carries (states[i].pressure, per unit undeformed
  /// boundary length) times dS/ds. What Hertz, Shtayerman and other codes give.
  std::vector<double> pressure;
  /// Per state: the same from the body's stresses, n_o·(P N) dS/ds (P N the traction per unit
  /// undeformed length, n_o the obstacle's outward normal at the deformed point: the direction
  /// the normal contact force acts along).
  std::vector<double> pressure_from_stress;
  /// Per state: the tangential traction from the body's stresses, −τ_o·(P N) dS/ds with
  /// τ_o = contact::friction_tangent(n_o): what the stresses say t_T (the state's t_t, along its
  /// tau) is, per unit length along the obstacle as `pressure`.
  std::vector<double> shear_from_stress;
  /// Per state: −n·σ·n from the stresses, n the body's own undeformed outward normal (the
  /// seed's plotted pressure; a factor cos²θ below `pressure` where the boundary is inclined).
  std::vector<double> minus_sigma_nn;
  Vec2 resultant = Vec2::Zero();            ///< ∫ traction ds on the body
  /// The largest traction the method carries (multiplier or penalty traction, per unit
  /// undeformed boundary length) and penetration.
  double p_max = 0, max_penetration = 0;
  /// The largest `pressure` (force per unit length along the obstacle) away from the singular
  /// points (beyond the elements touching each).
  double pressure_max = 0;
  /// Where the exact pressure is unbounded: the zone closed up to an end or a corner of either
  /// body's contact edges (model/singular_points.hpp).
  std::vector<SingularPoint> singular_points;
  /// The extent of the contact zone along the surface (arc length along the frame): from its
  /// first to its last end (a zone end, or the last point in contact where the contact boundary
  /// ends in contact).
  double contact_length = 0;
  /// Ends of the contact zone (Pegasus on the gap, seed §4.7) on the undeformed boundary: the
  /// points a node is moved to (rp) and where the closed forms of the linear theory put them.
  std::vector<Vec2> gamma_star;
  std::vector<Vec2> gamma_star_deformed;  ///< the same points after deformation
  /// Indices into gamma_star of the outer ends of the active region along the contact boundary
  /// (its first and last sign change, where the boundary's own ends are open): the ends rp moves
  /// nodes to. Sign changes between them are islands of opening inside the contact zone, which
  /// the penalty traction's oscillation produces on coarse discretisations.
  std::vector<int> outer_ends;
  /// The zone's extent [lo, hi] along the pair's surface frame (ContactPair::frame: arc length
  /// from its origin, undeformed points), if any point is in contact.
  std::optional<std::pair<double, double>> zone;
  /// The same of the deformed points (where the closed forms of the linear theory, which put the
  /// pressure on the undeformed surface, do not compare).
  std::optional<std::pair<double, double>> zone_deformed;
  /// Half the zone's length where that is its half width: a straight surface and a zone
  /// symmetric about the frame's origin (or a half model's, starting at it); none otherwise.
  std::optional<double> half_width;
  /// Against another body: the states of its points and the zone ends on its boundary. Under
  /// exact enforcement the other body's points carry the multiplier at their feet on this body.
  std::vector<contact::PointState> other_states;
  ZoneEnds other_zone_ends;
  /// Per other_states entry, as X, s, pressure, pressure_from_stress, minus_sigma_nn are for
  /// the states (positions along the same obstacle frame).
  std::vector<Vec2> other_X;
  std::vector<double> other_s, other_pressure, other_pressure_from_stress, other_minus_sigma_nn,
      other_shear_from_stress;
  /// ∫ p_N dS and ∫ t_T dS over the pair's body's contact boundary (undeformed length, per unit
  /// thickness; axisymmetric: over the whole circle): the normal traction's total, which bounds
  /// the friction's (times mu), and the friction's total along the states' tangents.
  double normal_traction_total = 0, tangential_traction_total = 0;
  /// The states' neighbours along the pair's contact boundary, and the other body's points'
  /// along its boundary (contact::boundary_order): for walking each side in order.
  contact::BoundaryOrder order, other_order;
  /// Exact enforcement: the multiplier nodes, with the pressure the method carries.
  struct Node {
    Vec2 X, x;          ///< undeformed and deformed position
    double pressure = 0;  ///< λ_j
    double tangential = 0;  ///< λ_T,j with friction: the tangential traction (along τ on the other side)
    double gap = 0;       ///< the weighted gap G_j / W_j (collocation: g_N at the node)
    /// With exact Coulomb friction and the step's slips given: the weighted slip of the last
    /// load step Ĝ_T,j / W_j along the node's tangent (0 where it sticks).
    double step_slip = 0;
    /// With exact friction and the path's slips given: the slips of all steps added up.
    double slip = 0;
    bool active = false;  ///< λ_j > 0
  };
  std::vector<Node> nodes;
  /// Exact Coulomb friction (the step's slips given): the stick–slip points, where the friction
  /// state changes between neighbouring active nodes of one contact edge, located as the root
  /// of the edge's complementarity function of friction (model/stick_slip_points.hpp) — the
  /// points rp and hp adapt to as to Γ*. Against another body their feet on its boundary are
  /// `other`.
  ZoneEnds stick_slip, other_stick_slip;
  /// Exact Coulomb friction, after a solve along a load path (model/memory_points.hpp): the
  /// stick–slip points of earlier load steps where every later step stuck — the tangential
  /// traction keeps a kink there — undeformed, on the pair's body and on the other one.
  std::vector<Vec2> memory_points, other_memory_points;
};

/// The contact state of a pair at the dofs u (and its multipliers, when it is enforced exactly):
/// its points' states, pressures from the stresses, resultant, Γ*, half width.
/// `step_slips`: with exact Coulomb friction, the nodes' slips of the last step
/// (ContactSystem::step_slips), which locate the stick–slip points; without them there are none.
/// `total_slips`: with exact friction, the nodes' slips over the whole path
/// (ContactSystem::total_slips), the points' `slip`; without them it is 0.
ContactResult evaluate_contact(const Discretization& d, const ContactPair& pair,
                               const Eigen::VectorXd& u, const Eigen::VectorXd* multipliers = nullptr,
                               const Eigen::VectorXd* step_slips = nullptr,
                               const Eigen::VectorXd* total_slips = nullptr);

/// The constraints of an exactly enforced pair at u with all its multipliers (normal, then
/// tangential with friction), the tangential slips measured from the undeformed state. With
/// `residual`, the contact forces are subtracted from it (over all dofs), as in the solve.
ConstraintState pair_constraint_state(const Discretization& d, const ContactPair& pair,
                                      const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers,
                                      Eigen::VectorXd* residual = nullptr);

/// ∫ traction ds on the pair's body at the state u (and its multipliers when it is enforced
/// exactly).
Vec2 contact_resultant(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       const Eigen::VectorXd* multipliers = nullptr);

}  // namespace hpcontact::model
