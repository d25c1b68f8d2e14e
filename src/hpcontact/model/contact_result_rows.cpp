// The per-point rows of a ContactResult: the states of a pair's points with their pressures and
// what the stresses say there, at its Gauss points (penalty) or its multiplier nodes (exact
// enforcement), and at the other body's points; with the figures summed over them.
#include "hpcontact/model/contact_result_rows.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "hpcontact/contact/friction.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/model/boundary_point.hpp"
#include "hpcontact/model/boundary_stress.hpp"
#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/contact_zone_ends.hpp"
#include "hpcontact/model/stick_slip_points.hpp"

namespace hpcontact::model {

namespace {

/// The columns of one side of a ContactResult (the pair's body, or the other body's points):
/// a point's position, place along the obstacle, pressure and what its stresses say.
struct SideColumns {
  std::vector<Vec2>& X;
  std::vector<double>& s;
  std::vector<double>& pressure;
  std::vector<double>& pressure_from_stress;
  std::vector<double>& minus_sigma_nn;
  std::vector<double>& shear_from_stress;
  void add(const Vec2& X_point, double s_point, double p, const SideValues& sv) const {
    X.push_back(X_point);
    s.push_back(s_point);
    pressure.push_back(p);
    pressure_from_stress.push_back(sv.pressure_from_stress);
    minus_sigma_nn.push_back(sv.minus_sigma_nn);
    shear_from_stress.push_back(sv.shear_from_stress);
  }
};

SideColumns own_columns(ContactResult& res) {
  return {res.X, res.s, res.pressure, res.pressure_from_stress, res.minus_sigma_nn, res.shear_from_stress};
}

SideColumns other_columns(ContactResult& res) {
  return {res.other_X, res.other_s, res.other_pressure, res.other_pressure_from_stress,
          res.other_minus_sigma_nn, res.other_shear_from_stress};
}

/// The largest penetration −g of the points with a gap (0 where none penetrates).
double max_penetration(const std::vector<contact::PointState>& points) {
  double penetration = 0;
  for (const auto& ps : points)
    if (std::isfinite(ps.gap)) penetration = std::max(penetration, -ps.gap);
  return penetration;
}

/// One row per contact point of one side of a penalty pair (its `points` of `body` with their
/// `states`): its position, its pressure per unit length along the obstacle and what the stresses
/// say against `obstacle`.
void add_point_rows(const SideColumns& side, const Body& body, const ContactPair& pair,
                    const contact::Obstacle& obstacle, const std::vector<contact::ContactPoint>& points,
                    const std::vector<contact::PointState>& states, const Eigen::VectorXd& u) {
  for (size_t i = 0; i < points.size(); ++i) {
    const auto& cp = points[i];
    const SideValues sv = side_values(body, pair, obstacle, *pair.frame, cp.element, cp.local_edge, cp.t, u);
    side.add(cp.X, sv.s, states[i].pressure * sv.length_ratio, sv);
  }
}

/// An exactly enforced pair's multipliers by kind, and its nodes' slips where they are given.
struct PairMultipliers {
  Eigen::VectorXd lambda;    ///< normal, per node
  Eigen::VectorXd lambda_t;  ///< tangential with friction; zero without
  bool friction = false;     ///< the pair has friction and its tangential multipliers are given
  /// With friction: the last step's slips, which locate the stick–slip points of a Coulomb pair,
  /// and the slips over the whole path; null where not given.
  const Eigen::VectorXd* step_slips = nullptr;
  const Eigen::VectorXd* total_slips = nullptr;
};

PairMultipliers pair_multipliers(const PairConstraints& c, const Eigen::VectorXd& multipliers,
                                 const Eigen::VectorXd* step_slips, const Eigen::VectorXd* total_slips) {
  PairMultipliers m;
  m.lambda = multipliers.head(c.size());
  m.friction = c.has_friction() && multipliers.size() == 2 * c.size();
  m.lambda_t = m.friction ? Eigen::VectorXd(multipliers.tail(c.size())) : Eigen::VectorXd::Zero(c.size());
  m.step_slips = m.friction && step_slips && step_slips->size() == c.size() ? step_slips : nullptr;
  m.total_slips = m.friction && total_slips && total_slips->size() == c.size() ? total_slips : nullptr;
  return m;
}

/// Multiplier node j at the constraint state s: its position, multipliers, weighted gap, slips,
/// and whether it is in contact by the solver's own active set.
ContactResult::Node multiplier_node(const Body& body, const PairConstraints& c, const ConstraintState& s,
                                    const PairMultipliers& m, const Eigen::VectorXd& u, int j) {
  const auto& cp = c.node_points[j];
  ContactResult::Node n;
  std::tie(n.X, n.x) = boundary_position(body, cp.element, cp.local_edge, cp.t, u);
  n.pressure = m.lambda(j);
  if (m.friction) n.tangential = m.lambda_t(j);
  if (m.step_slips) n.step_slip = (*m.step_slips)(j);
  if (m.total_slips) n.slip = (*m.total_slips)(j);
  n.gap = !s.found[j]           ? std::numeric_limits<double>::infinity()
          : c.weight(j) != 0.0 ? s.G(j) / c.weight(j)
          : c.rule == ConstraintRule::collocation ? s.points[j].gap  // the node's own point
                                                  : 0.0;
  // the solver's own active set (a round-off pressure on an open node is no contact)
  // (a passive node, on an axis, is in contact where its even extension of the pressure is)
  const bool passive = !c.passive.empty() && c.passive[j];
  n.active = passive ? n.pressure > 0 : node_active(c, s, m.lambda, j) && n.pressure >= 0;
  return n;
}

/// The state of multiplier node n (index j): λ_j along the node's mean normal (the direction of
/// its resultant's derivative), with friction λ_T,j along its tangent and its slips.
contact::PointState node_state(const ContactResult::Node& n, const PairConstraints& c,
                               const ConstraintState& s, bool friction, int j) {
  contact::PointState ps;
  ps.x = n.x;
  ps.gap = n.gap;
  ps.pressure = n.pressure;
  ps.normal = Vec2::Zero();  // a node without a foot has neither normal nor tangent
  if (s.d_resultant[j].norm() > 0) ps.normal = s.d_resultant[j].normalized();
  ps.tau = contact::friction_tangent(ps.normal);
  ps.traction = n.pressure * ps.normal;
  if (friction) {
    if (s.d_resultant_t[j].norm() > 0) ps.tau = -s.d_resultant_t[j].normalized();
    ps.t_t = n.tangential;
    if (n.active) ps.g_t = n.step_slip;  // an open node has no slip this step
    ps.slip = n.slip;                    // but keeps what it slipped before it opened
    ps.traction -= n.tangential * ps.tau;
    if (n.active) ps.stick_slip = contact::stick_or_slip(c.friction, n.tangential, n.pressure);
  }
  return ps;
}

/// What the stresses say at multiplier node j (at node_stress_point; nothing where it has none).
SideValues node_side_values(const Body& body, const ContactPair& pair, const Eigen::VectorXd& u, int j) {
  SideValues sv;
  if (const auto at = node_stress_point(body, pair, j))
    sv = side_values(body, pair, *pair.obstacle, *pair.frame, std::get<0>(*at), std::get<1>(*at),
                     std::get<2>(*at), u);
  return sv;
}

/// One row per multiplier node, where the method carries the pressure: λ_j, the weighted gap,
/// the node's mean normal.
void add_node_rows(ContactResult& res, const Body& body, const ContactPair& pair,
                   const ConstraintState& s, const PairMultipliers& m, const Eigen::VectorXd& u) {
  const PairConstraints& c = *pair.constraints;
  const SideColumns own_side = own_columns(res);
  for (int j = 0; j < c.size(); ++j) {
    const ContactResult::Node n = multiplier_node(body, c, s, m, u, j);
    res.p_max = std::max(res.p_max, n.pressure);
    res.normal_traction_total += c.weight(j) * n.pressure;
    res.tangential_traction_total += c.weight(j) * n.tangential;
    res.nodes.push_back(n);
    res.states.push_back(node_state(n, c, s, m.friction, j));
    const SideValues sv = node_side_values(body, pair, u, j);
    own_side.add(n.X, pair.frame->coordinate(n.X), n.pressure * sv.length_ratio, sv);
  }
}

/// A point of the other body: its state and undeformed position.
struct OtherPoint {
  contact::PointState state;
  Vec2 X;
};

/// The other body's point cp of an exactly enforced pair: its gap against this body's deformed
/// boundary and the multipliers and slips at its foot on it. The multipliers are per unit of this
/// body's undeformed boundary (length × thickness, 2π R axisymmetric); the reaction they exert is
/// referred to the other body's own, as its stresses and its ring force 2π R p are: × (w dS) /
/// (w_o dS_o), the two lengths that touch in the deformed state (DeformableBoundary::stretch).
/// Without it the two bodies' rows differ by their tangential strains and radii (a press fit's
/// shaft and hub: 3e-4 and 1e-3), and by which body carries the multipliers.
/// Its tangent is friction_tangent of this body's normal, opposite to the pair's: the other body
/// receives +λ_T times the pair's tangent, i.e. −λ_T τ along its own, so t_T has the sign of λ_T
/// on both sides.
OtherPoint point_at_foot(const Discretization& d, const ContactPair& pair, const PairMultipliers& m,
                         const contact::ContactPoint& cp, const Eigen::VectorXd& u) {
  const Body &body = d.bodies[pair.body], &other = d.bodies[pair.other];
  const PairConstraints& c = *pair.constraints;
  OtherPoint p;
  contact::PointState& ps = p.state;
  ps.normal = Vec2::Zero();
  ps.tau = Vec2::Zero();
  ps.gap = gap_at(other, *pair.boundary, cp.element, cp.local_edge, cp.t, u, &ps.x, &p.X);
  contact::BoundaryPoint foot;
  if (!pair.boundary->project(ps.x, foot)) return p;
  const double area_ratio =  // w dS / (w_o dS_o)
      body.out_of_plane().at(pair.boundary->undeformed(foot.edge, foot.t)) *
      pair.other_boundary->stretch(cp.edge, cp.t) /
      (other.out_of_plane().at(cp.X) * pair.boundary->stretch(foot.edge, foot.t));
  ps.pressure = area_ratio * c.nodes.interpolate(foot.edge, foot.t, m.lambda);
  ps.normal = foot.normal;
  ps.tau = contact::friction_tangent(foot.normal);
  ps.t_t = area_ratio * c.nodes.interpolate(foot.edge, foot.t, m.lambda_t);
  // The slips are relative: the other body's along its tangent (−τ) are this body's along τ,
  // read at the foot as the multipliers are.
  if (m.step_slips) ps.g_t = c.nodes.interpolate(foot.edge, foot.t, *m.step_slips);
  if (m.total_slips) ps.slip = c.nodes.interpolate(foot.edge, foot.t, *m.total_slips);
  ps.traction = ps.pressure * foot.normal - ps.t_t * ps.tau;
  return p;
}

/// One row per point of the other body of an exactly enforced pair, with the multipliers at its
/// foot (point_at_foot).
void add_rows_at_feet(ContactResult& res, const Discretization& d, const ContactPair& pair,
                      const PairMultipliers& m, const Eigen::VectorXd& u) {
  const Body& other = d.bodies[pair.other];
  const SideColumns other_side = other_columns(res);
  for (const auto& cp : pair.other_points) {
    const OtherPoint p = point_at_foot(d, pair, m, cp, u);
    const SideValues sv = side_values(other, pair, *pair.boundary, *pair.frame, cp.element,
                                      cp.local_edge, cp.t, u);
    res.other_states.push_back(p.state);
    other_side.add(p.X, sv.s, p.state.pressure * sv.length_ratio, sv);
  }
}

}  // namespace

void add_gauss_point_rows(ContactResult& res, const Discretization& d, const ContactPair& pair,
                          const Eigen::VectorXd& u) {
  const Body& body = d.bodies[pair.body];
  PairForces f = pair_forces(d, pair, u, nullptr);
  res.resultant = f.resultant(pair);
  res.states = std::move(f.states);
  res.other_states = std::move(f.other_states);
  for (const auto& ps : res.states) res.p_max = std::max(res.p_max, ps.pressure);
  res.max_penetration = max_penetration(res.states);
  add_point_rows(own_columns(res), body, pair, *pair.obstacle, pair.points, res.states, u);
  for (size_t i = 0; i < pair.points.size(); ++i) {
    res.normal_traction_total += pair.points[i].weight * res.states[i].pressure;
    res.tangential_traction_total += pair.points[i].weight * res.states[i].t_t;
  }
  if (pair.other >= 0)
    add_point_rows(other_columns(res), d.bodies[pair.other], pair, *pair.boundary, pair.other_points,
                   res.other_states, u);
}

void add_multiplier_node_rows(ContactResult& res, const Discretization& d, const ContactPair& pair,
                              const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers,
                              const Eigen::VectorXd* step_slips, const Eigen::VectorXd* total_slips) {
  const Body& body = d.bodies[pair.body];
  const PairConstraints& c = *pair.constraints;
  const ConstraintState s = pair_constraint_state(d, pair, u, multipliers);
  // the largest penetration is the pointwise one over the points the gap is integrated on
  res.max_penetration = max_penetration(s.points);
  res.resultant = s.resultant;
  const PairMultipliers m = pair_multipliers(c, multipliers, step_slips, total_slips);
  add_node_rows(res, body, pair, s, m, u);
  if (m.step_slips && c.friction.kind == contact::FrictionLaw::Kind::coulomb) {
    res.stick_slip = stick_slip_points(body, pair, res.nodes, u, m.lambda, m.lambda_t, *m.step_slips);
    if (pair.other >= 0) res.other_stick_slip = feet_on_other(pair, res.stick_slip.x);
  }
  if (pair.other >= 0) add_rows_at_feet(res, d, pair, m, u);
}

}  // namespace hpcontact::model
