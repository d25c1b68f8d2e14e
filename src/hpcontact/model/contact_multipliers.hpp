// Exact contact of a pair by multipliers: the pressure λ_j an unknown at each multiplier node,
// the weighted gaps G_j = Σ_q a_qj g_N(x_q) as constraints, and the contact forces Σ_j λ_j ∇G_j.
#pragma once

#include <memory>
#include <utility>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "hpcontact/contact/deformable_boundary.hpp"
#include "hpcontact/contact/multiplier_nodes.hpp"
#include "hpcontact/contact/penalty.hpp"
#include "hpcontact/model/discretization.hpp"

namespace hpcontact::model {

struct ContactPair;

/// The constraints of a pair enforced exactly: its multiplier nodes, the points where the gap is
/// evaluated and how each point's gap enters each node's constraint:
///   G_j = Σ_q a_qj g_N(x_q)   (the weighted gap of node j [length²]),
///   the contact force on the bodies f_c = Σ_j λ_j ∇G_j = Σ_q (Σ_j a_qj λ_j) ∇g_N(x_q),
/// λ_j the pressure at node j. Collocation: one point per node, a_jj = W_j (G_j = W_j g_N(x_j)).
/// Mortar: the pair's Gauss points, a_qj = w_q L_j(t_q), so that G_j = ∫ L_j g_N ds and
/// W_j = ∫ L_j ds. Between two bodies the pair's own body carries the nodes and the gap is
/// measured against the other body's deformed boundary (one-sided: constraints on both sides
/// would repeat one another and leave the pressure undetermined).
struct PairConstraints {
  ConstraintRule rule = ConstraintRule::mortar;
  contact::MultiplierNodes nodes;
  std::vector<contact::ContactPoint> points;                       ///< where g_N is evaluated
  std::vector<contact::ContactPoint> node_points;                  ///< a point at each node
  std::vector<std::vector<std::pair<int, double>>> coefficients;   ///< per point: (node j, a_qj)
  Eigen::VectorXd weight;        ///< W_j [length]: ∫ λ ds ≈ Σ_j W_j λ_j
  /// Nodes with no share of the boundary (W_j = 0: on the axis of an axisymmetric body, where
  /// the circle 2π r vanishes): their multiplier does no work, so they are never active and
  /// their value is the one that makes the pressure even in r (fill_passive_multipliers).
  std::vector<char> passive;
  double passive_row_weight = 0;  ///< the weight pinning a passive node's λ_j = 0: the largest W
  /// κ_j = E' p² / h [force/length³] of the node's edge: the scale of the complementarity
  /// function (the active-set test λ_j − κ_j G_j/W_j ≥ 0, the row κ_j G_j of an active node):
  /// a property of the body, so that neither the active set nor the answer depends on an input
  /// parameter.
  Eigen::VectorXd scale;
  /// ε_j [force/length³]: the augmentation of the factorised tangent, ε_j W_j ∇ĝ_j ∇ĝ_jᵀ per
  /// active node (the input's penalty, else κ_j): conditioning, not the answer.
  Eigen::VectorXd augmentation;
  /// Mortar between two bodies: the points are made at each evaluation, `segment_quadrature`
  /// Gauss points on each segment of an edge between the parameters where the projection onto
  /// the other body crosses one of its vertices (so that each integrand is smooth; `points`
  /// then holds the unsegmented rule, for W_j only).
  bool segmented = false;
  /// Two bodies: the gap along the mean normal of both boundaries (two_body_point_gap's `own`).
  bool mean_normal = false;
  /// The overlap of the input is ramped in with the displacement factor (ContactSystem).
  bool ramp_interference = false;
  int segment_quadrature = 0;
  std::vector<int> edges;  ///< the mesh edge of each edge of the nodes (chain order)
  /// Friction at the nodes: a tangential multiplier λ_T,j (the traction along τ the other side
  /// receives; this body receives −λ_T τ) against the weighted tangential slip since the last
  /// converged step, G_T,j = Σ_q a_qj τ·Δ(x_q − x_foot) (stick: G_T,j = 0; Coulomb: slip where
  /// |λ_T + c_T G_T/W| would exceed μ (λ_N − ε ĝ), then λ_T = μ λ_N sign(·)).
  contact::FrictionLaw friction;
  Eigen::VectorXd tangential_augmentation;  ///< ε_T,j, as `augmentation` for the stick rows
  bool has_friction() const { return friction.active(); }
  int size() const { return nodes.size(); }
};

/// The constraints of a pair of the problem (its chained contact edges, points and body;
/// `two_bodies`: against another body).
std::shared_ptr<const PairConstraints> make_pair_constraints(const ContactPairSpec& spec,
                                                             const Body& body,
                                                             const std::vector<contact::ChainEdge>& chain,
                                                             const std::vector<contact::ContactPoint>& points,
                                                             bool two_bodies);

/// A pair's constraints at a state (all dofs u, its multipliers lambda).
struct ConstraintState {
  Eigen::VectorXd G;         ///< weighted gap per node [length²]
  std::vector<char> found;   ///< per node: a point of its support has a closest point
  /// Per node: ∂G_j/∂u as (global dof, value), each dof once (only when asked for).
  std::vector<std::vector<std::pair<int, double>>> dG;
  /// Per point: position, gap, normal, and the multiplier there as its pressure
  /// λ_h(x_q) = Σ_j a_qj λ_j / w_q with the traction λ_h n.
  std::vector<contact::PointState> points;
  Vec2 resultant = Vec2::Zero();   ///< ∫ λ_h n ds: the force the obstacle exerts on the pair's body
  /// ∂resultant/∂λ_j (the normals held), per node.
  std::vector<Vec2> d_resultant;
  /// ∂G_j/∂(factor of the obstacle's displacement) for a moving rigid obstacle, per node.
  Eigen::VectorXd dG_dfactor;
  /// The points evaluated when they are made per state (segmented mortar), else empty: then
  /// they are PairConstraints::points.
  std::vector<contact::ContactPoint> segment_points;
  /// With friction: per node the weighted tangential slip since the last converged step
  /// [length²], its gradient ∂G_T,j/∂u (when asked for; with the tangent's turning and the
  /// foot's sliding when the curvature part is asked for too), the weighted virtual slip
  /// dT_j = Σ_q a_qj ∂(τ·(x − x_foot))/∂u with τ and the foot held (the column ∂R/∂λ_T,j of
  /// the tangential force), and ∂resultant/∂λ_T,j.
  Eigen::VectorXd GT;
  std::vector<std::vector<std::pair<int, double>>> dGT, dT;
  std::vector<Vec2> d_resultant_t;
};

/// What an evaluation with friction needs besides the state: the tangential multipliers, the
/// dofs of the last converged step (all dofs; the slip is measured from there), and how far a
/// rigid obstacle has moved since then.
struct FrictionInputs {
  const Eigen::VectorXd* lambda_t = nullptr;
  const Eigen::VectorXd* u_committed = nullptr;
  Vec2 obstacle_increment = Vec2::Zero();
};

/// An overlap of the input relieved step by step (contact[].interference: ramp): the gap of a
/// point is g + remaining · o(s), o the overlap at the undeformed state interpolated from the
/// multiplier nodes' (the nodes' own Lagrange polynomials, as the pressure), `remaining` = 1 − the
/// displacement factor.
struct InterferenceRelief {
  const Eigen::VectorXd* overlap = nullptr;  ///< per node, max(0, −g) at the undeformed state
  double remaining = 0;
};

/// The gap of each of `pair`'s multiplier nodes' own point at the undeformed state (+∞ where it
/// has no foot on the other side).
Eigen::VectorXd undeformed_node_gaps(const Discretization& d, const ContactPair& pair);
/// Per multiplier node of `pair`, whether it touches the other side at the undeformed state:
/// its own point's gap is at most `touching`, or the gap falls to `touching` between it and the
/// next node of its edge (a curve touching its partner between two nodes: both touch, so that
/// the contact's first point is held whichever mesh the adaptive loop made).
std::vector<char> touching_nodes(const Discretization& d, const ContactPair& pair, double touching);
/// Their overlaps: max(0, −g), 0 where a node has no foot.
Eigen::VectorXd initial_overlaps(const Discretization& d, const ContactPair& pair);

/// Evaluates the constraints of `pair` at u and lambda; subtracts the contact forces from R (all
/// dofs, the residual K u − f − f_c) when R is not null, adds the curvature part of their
/// tangent, −Σ_q λ_q ∇²g_N(x_q), to t when t is not null, and fills the gradients dG when
/// `gradients`. With friction (the pair's law and friction.lambda_t given) also the tangential
/// slips, their gradients and forces; with t the tangent of the tangential force, Σ_q λ_T,q ∂dt_q/∂u,
/// and the slips' gradients include how τ turns and the foot slides. With `relief` the gaps are
/// those of the ramped interference, and dG_dfactor takes −o(s).
ConstraintState evaluate_constraints(const Discretization& d, const ContactPair& pair,
                                     const Eigen::VectorXd& u, const Eigen::VectorXd& lambda,
                                     Eigen::VectorXd* R, std::vector<Eigen::Triplet<double>>* t,
                                     bool gradients, const FrictionInputs& friction = {},
                                     const InterferenceRelief& relief = {});

/// The multipliers of the passive nodes from their edges' others: dλ_h/dt = 0 at the node (the
/// pressure of a solid of revolution is even in r at its axis).
void fill_passive_multipliers(const PairConstraints& c, Eigen::VectorXd& lambda);

/// Whether the deformed position of `cp` (u: its body's dofs) has a foot on the other body's
/// boundary (its displacement set): false past the boundary's free ends.
bool has_foot(const contact::ContactPoint& cp, const Eigen::VectorXd& u,
              const contact::DeformableBoundary& other);

/// Whether node j is active: its support has a closest point on the obstacle (between two
/// bodies, its own point too) and λ_j − κ_j G_j / W_j ≥ 0 (the semi-smooth Newton's active set
/// of the complementarity function C_j = λ_j − max(0, λ_j − κ_j ĝ_j), ĝ_j = G_j / W_j, whose
/// zeros are g ≥ 0, λ ≥ 0, λ g = 0; a node touching without pressure counts as active, so a body
/// that rests on its support is held from the first iteration).
bool node_active(const PairConstraints& c, const ConstraintState& s, const Eigen::VectorXd& lambda,
                 int j);

}  // namespace hpcontact::model
