// Contact results at a state: Γ* by Pegasus on the gap (seed §4.7), pressures from the stresses,
// resultants, and the pressure probe along the boundary.
#include "hpcontact/model/contact_results.hpp"

#include <algorithm>
#include <stdexcept>
#include <optional>
#include <tuple>
#include <cmath>
#include <limits>

#include "hpcontact/contact/friction.hpp"
#include "hpcontact/core/error.hpp"
#include "hpcontact/core/roots.hpp"
#include "hpcontact/fem/edge_load.hpp"
#include "hpcontact/fem/element_values.hpp"
#include "hpcontact/fem/finite_strain.hpp"
#include "hpcontact/model/boundary_point.hpp"
#include "hpcontact/model/boundary_stress.hpp"
#include "hpcontact/model/contact_forces.hpp"
#include "hpcontact/model/contact_zone_ends.hpp"
#include "hpcontact/model/stick_slip_points.hpp"

namespace hpcontact::model {

ConstraintState pair_constraint_state(const Discretization& d, const ContactPair& pair,
                                      const Eigen::VectorXd& u, const Eigen::VectorXd& multipliers) {
  const int m = pair.constraints->size();
  const Eigen::VectorXd lambda = multipliers.head(m);
  Eigen::VectorXd lambda_t;
  FrictionInputs fi;
  if (pair.constraints->has_friction() && multipliers.size() == 2 * m) {
    lambda_t = multipliers.tail(m);
    fi.lambda_t = &lambda_t;
  }
  return evaluate_constraints(d, pair, u, lambda, nullptr, nullptr, false, fi);
}

Vec2 contact_resultant(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       const Eigen::VectorXd* multipliers) {
  if (pair.constraints) {
    if (!multipliers) throw std::invalid_argument("contact_resultant: an exact pair needs its multipliers");
    return pair_constraint_state(d, pair, u, *multipliers).resultant;
  }
  return pair_forces(d, pair, u, nullptr).resultant(pair);
}

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

/// The mesh edge of each state's point of a pair's own side: its multiplier node's first edge
/// (exact enforcement) or its contact point's.
std::vector<int> state_edges(const ContactPair& pair) {
  std::vector<int> edges;
  if (pair.constraints)
    for (const auto& node : pair.constraints->nodes.nodes) edges.push_back(pair.constraints->edges[node.edge]);
  else
    for (const auto& cp : pair.points) edges.push_back(pair.edges[cp.edge]);
  return edges;
}

/// The mesh edge of each of the other body's contact points.
std::vector<int> other_point_edges(const ContactPair& pair) {
  std::vector<int> edges;
  for (const auto& cp : pair.other_points) edges.push_back(pair.other_edges[cp.edge]);
  return edges;
}

ContactResult contact_result(const Discretization& d, const ContactPair& pair,
                             const Eigen::VectorXd& u, const Eigen::VectorXd* multipliers,
                             const Eigen::VectorXd* step_slips, const Eigen::VectorXd* total_slips) {
  const Body& body = d.bodies[pair.body];
  ContactResult res;
  const SideColumns own_side{res.X, res.s, res.pressure, res.pressure_from_stress, res.minus_sigma_nn,
                             res.shear_from_stress};
  const SideColumns other_side{res.other_X, res.other_s, res.other_pressure,
                               res.other_pressure_from_stress, res.other_minus_sigma_nn,
                               res.other_shear_from_stress};
  ConstraintState s;
  if (pair.constraints) {
    if (!multipliers) throw std::invalid_argument("evaluate_contact: an exact pair's results need its multipliers");
    s = pair_constraint_state(d, pair, u, *multipliers);
    // One state per multiplier node, where the method carries the pressure: λ_j, the weighted
    // gap, the node's mean normal; the largest penetration is the pointwise one over the points
    // the gap is integrated on.
    const PairConstraints& c = *pair.constraints;
    for (const auto& ps : s.points)
      if (std::isfinite(ps.gap)) res.max_penetration = std::max(res.max_penetration, -ps.gap);
    res.resultant = s.resultant;
    const bool friction = c.has_friction() && multipliers->size() == 2 * c.size();
    // the last step's slips, which locate the stick–slip points of a Coulomb pair
    const Eigen::VectorXd* slips =
        friction && step_slips && step_slips->size() == c.size() ? step_slips : nullptr;
    const Eigen::VectorXd* totals =
        friction && total_slips && total_slips->size() == c.size() ? total_slips : nullptr;
    for (int j = 0; j < c.size(); ++j) {
      const auto& cp = c.node_points[j];
      ContactResult::Node n;
      std::tie(n.X, n.x) = boundary_position(body, cp.element, cp.local_edge, cp.t, u);
      n.pressure = (*multipliers)(j);
      if (friction) n.tangential = (*multipliers)(c.size() + j);
      if (slips) n.step_slip = (*slips)(j);
      if (totals) n.slip = (*totals)(j);
      n.gap = !s.found[j]           ? std::numeric_limits<double>::infinity()
              : c.weight(j) != 0.0 ? s.G(j) / c.weight(j)
              : c.rule == ConstraintRule::collocation ? s.points[j].gap  // the node's own point
                                                      : 0.0;
      // the solver's own active set (a round-off pressure on an open node is no contact)
      // (a passive node, on an axis, is in contact where its even extension of the pressure is)
      const bool passive = !c.passive.empty() && c.passive[j];
      n.active = passive ? n.pressure > 0
                         : node_active(c, s, multipliers->head(c.size()), j) && n.pressure >= 0;
      res.p_max = std::max(res.p_max, n.pressure);
      res.normal_traction_total += c.weight(j) * n.pressure;
      res.tangential_traction_total += c.weight(j) * n.tangential;
      res.nodes.push_back(n);
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
      res.states.push_back(ps);
      SideValues sv;
      if (const auto at = node_stress_point(body, pair, j))
        sv = side_values(body, pair, *pair.obstacle, *pair.frame, std::get<0>(*at), std::get<1>(*at),
                         std::get<2>(*at), u);
      own_side.add(n.X, pair.frame->coordinate(n.X), n.pressure * sv.length_ratio, sv);
    }
    if (slips && c.friction.kind == contact::FrictionLaw::Kind::coulomb) {
      res.stick_slip = stick_slip_points(body, pair, res.nodes, u, multipliers->head(c.size()),
                                         multipliers->tail(c.size()), *slips);
      if (pair.other >= 0) res.other_stick_slip = feet_on_other(pair, res.stick_slip.x);
    }
    if (pair.other >= 0) {
      // The other body's points: their gap against this body's deformed boundary and the
      // multipliers and slips at their feet on it (the reaction, per unit length of this body's
      // boundary).
      // Their tangent is friction_tangent of this body's normal, opposite to the pair's: the
      // other body receives +λ_T times the pair's tangent, i.e. −λ_T τ along its own, so t_T is
      // λ_T on both sides.
      const Body& other = d.bodies[pair.other];
      const Eigen::VectorXd lambda = multipliers->head(c.size());
      const Eigen::VectorXd lambda_t = friction ? Eigen::VectorXd(multipliers->tail(c.size()))
                                                : Eigen::VectorXd::Zero(c.size());
      for (const auto& cp : pair.other_points) {
        contact::PointState ps;
        ps.normal = Vec2::Zero();
        ps.tau = Vec2::Zero();
        Vec2 X;
        ps.gap = gap_at(other, *pair.boundary, cp.element, cp.local_edge, cp.t, u, &ps.x, &X);
        double ratio = 0;
        contact::BoundaryPoint foot;
        if (pair.boundary->project(ps.x, foot)) {
          ps.pressure = c.nodes.interpolate(foot.edge, foot.t, lambda);
          ps.normal = foot.normal;
          ps.tau = contact::friction_tangent(foot.normal);
          ps.t_t = c.nodes.interpolate(foot.edge, foot.t, lambda_t);
          // The slips are relative: the other body's along its tangent (−τ) are this body's
          // along τ, read at the foot as the multipliers are.
          if (slips) ps.g_t = c.nodes.interpolate(foot.edge, foot.t, *slips);
          if (totals) ps.slip = c.nodes.interpolate(foot.edge, foot.t, *totals);
          ps.traction = ps.pressure * foot.normal - ps.t_t * ps.tau;
          const auto& edge = body.mesh.edge(pair.edges[foot.edge]);
          Vec2 N;
          double dS_dt = 0;
          const Vec2 Xb = fem::edge_geometry(body.maps[edge.quads[0]], edge.local_edge[0], foot.t, &N, &dS_dt);
          ratio = 1 / std::max(std::abs(pair.frame->rate(Xb, Vec2(N.y(), -N.x()))), 1e-12);
        }
        const SideValues sv = side_values(other, pair, *pair.boundary, *pair.frame, cp.element,
                                          cp.local_edge, cp.t, u);
        res.other_states.push_back(ps);
        other_side.add(X, sv.s, ps.pressure * ratio, sv);
      }
    }
  } else {
    PairForces f = pair_forces(d, pair, u, nullptr);
    res.resultant = f.resultant(pair);
    res.states = std::move(f.states);
    res.other_states = std::move(f.other_states);
    for (const auto& ps : res.states) {
      res.p_max = std::max(res.p_max, ps.pressure);
      if (std::isfinite(ps.gap)) res.max_penetration = std::max(res.max_penetration, -ps.gap);
    }
    for (size_t i = 0; i < pair.points.size(); ++i) {
      const auto& cp = pair.points[i];
      const SideValues sv = side_values(body, pair, *pair.obstacle, *pair.frame, cp.element,
                                        cp.local_edge, cp.t, u);
      own_side.add(cp.X, sv.s, res.states[i].pressure * sv.length_ratio, sv);
      res.normal_traction_total += cp.weight * res.states[i].pressure;
      res.tangential_traction_total += cp.weight * res.states[i].t_t;
    }
    if (pair.other >= 0) {
      const Body& other = d.bodies[pair.other];
      for (size_t i = 0; i < pair.other_points.size(); ++i) {
        const auto& cp = pair.other_points[i];
        const SideValues sv = side_values(other, pair, *pair.boundary, *pair.frame, cp.element,
                                          cp.local_edge, cp.t, u);
        other_side.add(cp.X, sv.s, res.other_states[i].pressure * sv.length_ratio, sv);
      }
    }
  }
  res.order = contact::boundary_order(body.mesh, state_edges(pair));
  if (pair.other >= 0) res.other_order = contact::boundary_order(d.bodies[pair.other].mesh, other_point_edges(pair));
  ZoneEnds own = own_zone_ends(d, pair, u, multipliers, res);
  res.gamma_star = std::move(own.X);
  res.gamma_star_deformed = std::move(own.x);
  res.outer_ends = std::move(own.outer);
  if (pair.other >= 0) res.other_zone_ends = other_zone_ends(d, pair, u, res);
  if (const auto extent = zone_extent(pair, res)) {
    res.zone = extent->zone;
    res.contact_length = extent->zone.second - extent->zone.first;
    res.half_width = extent->half_width;
    res.zone_deformed = extent->zone_deformed;
  }
  res.singular_points = singular_points(d, pair, u, res);
  res.pressure_max = pressure_max_away(res, res.singular_points);
  return res;
}

}  // namespace

ContactResult evaluate_contact(const Discretization& d, const ContactPair& pair,
                               const Eigen::VectorXd& u, const Eigen::VectorXd* multipliers,
                               const Eigen::VectorXd* step_slips, const Eigen::VectorXd* total_slips) {
  return contact_result(d, pair, u, multipliers, step_slips, total_slips);
}

}  // namespace hpcontact::model
