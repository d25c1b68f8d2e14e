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

bool shares_node(const mesh::Mesh& m, int a, int b) {
  const auto &ea = m.edge(a), &eb = m.edge(b);
  return ea.v0 == eb.v0 || ea.v0 == eb.v1 || ea.v1 == eb.v0 || ea.v1 == eb.v1;
}

/// Root of the gap between parameters a and b of one edge by the Pegasus method (seed §4.7):
/// the boundary point where the contact zone ends, undeformed (X) and deformed (x).
std::pair<Vec2, Vec2> zone_end(const Body& body, const contact::Obstacle& obstacle, int q, int le,
                               double a, double b, const Eigen::VectorXd& u) {
  Vec2 x, X;
  auto gap = [&](double t) { return gap_at(body, obstacle, q, le, t, u, &x, &X); };
  const double fa = gap(a), fb = gap(b);
  gap(pegasus_root(gap, a, b, fa, fb, 1e-14 * (1 + x.norm())));
  return {X, x};
}

/// The outer ends of the active region: of the zone ends z.X, the one just below the first closed
/// point (coordinate lo along the obstacle) and the one just above the last (hi).
void mark_outer_ends(ZoneEnds& z, const ContactPair& pair, double lo, double hi) {
  int below = -1, above = -1;
  for (int k = 0; k < static_cast<int>(z.X.size()); ++k) {
    const double c = pair.frame->coordinate(z.X[k]);
    if (c <= lo && (below < 0 || c > pair.frame->coordinate(z.X[below]))) below = k;
    if (c >= hi && (above < 0 || c < pair.frame->coordinate(z.X[above]))) above = k;
  }
  if (below >= 0) z.outer.push_back(below);
  if (above >= 0 && above != below) z.outer.push_back(above);
}

/// The ends of the contact zone along the contact points of one body (the states' gaps change
/// sign; Pegasus on the gap between them, seed §4.7), and which of them are the outer ends of
/// the active region, by the coordinate along the obstacle (the contact edges need not be
/// listed as one path): the zone end just outside the first and the last closed point, where
/// open points lie beyond them.
ZoneEnds zone_ends(const Body& body, const std::vector<contact::ContactPoint>& points,
                   const std::vector<contact::PointState>& states, const contact::Obstacle& obstacle,
                   const ContactPair& pair, const Eigen::VectorXd& u) {
  ZoneEnds z;
  for (size_t i = 0; i + 1 < points.size(); ++i) {
    if ((states[i].gap < 0) == (states[i + 1].gap < 0)) continue;
    const auto &p0 = points[i], &p1 = points[i + 1];
    const bool same_edge = p0.element == p1.element && p0.local_edge == p1.local_edge;
    std::optional<std::pair<Vec2, Vec2>> end;
    if (same_edge) {
      end = zone_end(body, obstacle, p0.element, p0.local_edge, p0.t, p1.t, u);
    } else if (shares_node(body.mesh, body.mesh.quad_edge(p0.element, p0.local_edge),
                           body.mesh.quad_edge(p1.element, p1.local_edge))) {
      // The zone ends between two edges: on the side whose end gap changes sign (a node
      // placed on Γ*, as rp does, gives a root at the edge end itself).
      for (const auto* cp : {&p0, &p1}) {
        const bool open = states[cp == &p0 ? i : i + 1].gap >= 0;
        const double te = cp->t >= 0 ? 1.0 : -1.0;  // the end at the shared node
        if (!end && (gap_at(body, obstacle, cp->element, cp->local_edge, te, u, nullptr) >= 0) != open)
          end = zone_end(body, obstacle, cp->element, cp->local_edge, cp->t, te, u);
      }
    }
    if (end) {
      z.X.push_back(end->first);
      z.x.push_back(end->second);
    }
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t i = 0; i < points.size(); ++i)
    if (states[i].gap < 0) {
      lo = std::min(lo, pair.frame->coordinate(points[i].X));
      hi = std::max(hi, pair.frame->coordinate(points[i].X));
    }
  mark_outer_ends(z, pair, lo, hi);
  return z;
}

/// E' p / h of a contact edge of degree p: the stiffness of the boundary over a node spacing,
/// the scale that makes a gap and a pressure (or a slip and a traction) comparable.
double edge_stiffness(const Body& body, const mesh::Edge& edge, int p) {
  return body.material_of(edge.quads[0]).plane_modulus() * p /
         (body.mesh.node(edge.v1) - body.mesh.node(edge.v0)).norm();
}

/// The zone ends of an exactly enforced pair: between neighbouring multiplier nodes of one edge
/// of which one carries pressure and the other not. The exact pressure λ and gap g both vanish at
/// the end b (λ > 0, g = 0 before it; λ = 0, g > 0 beyond), so for any stiffness κ > 0
///   φ(t) = g(t) − λ_h(t) / κ
/// has its only root at b; with the discrete multiplier field λ_h and gap g its root (Pegasus)
/// is the estimate. κ = E' p / h of the edge (the stiffness of the boundary over a node
/// spacing): a fixed scale of the body, not the augmentation, so that the end is a function of
/// the solution alone.
ZoneEnds node_zone_ends(const Body& body, const ContactPair& pair,
                        const std::vector<ContactResult::Node>& nodes, const Eigen::VectorXd& u,
                        const Eigen::VectorXd& lambda) {
  const PairConstraints& c = *pair.constraints;
  ZoneEnds z;
  for (size_t k = 0; k < c.nodes.edge_nodes.size(); ++k) {
    const auto& en = c.nodes.edge_nodes[k];
    const auto& edge = body.mesh.edge(pair.edges[k]);
    const int q = edge.quads[0], le = edge.local_edge[0];
    const double kappa = edge_stiffness(body, edge, static_cast<int>(en.size()) - 1);
    auto phi = [&](double t) {
      return gap_at(body, *pair.obstacle, q, le, t, u, nullptr) -
             c.nodes.interpolate(static_cast<int>(k), t, lambda) / kappa;
    };
    for (size_t i = 0; i + 1 < en.size(); ++i) {
      if (nodes[en[i]].active == nodes[en[i + 1]].active) continue;
      const double ta = c.nodes.edge_points[k][i], tb = c.nodes.edge_points[k][i + 1];
      const double fa = phi(ta), fb = phi(tb);
      double t_end = 0.5 * (ta + tb);
      if ((fa < 0) != (fb < 0)) t_end = pegasus_root(phi, ta, tb, fa, fb, 1e-14);
      else if (std::abs(fa) < std::abs(fb)) t_end = ta;
      else t_end = tb;
      const auto [X, x] = boundary_position(body, q, le, t_end, u);
      z.X.push_back(X);
      z.x.push_back(x);
    }
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& n : nodes)
    if (n.active) {
      lo = std::min(lo, pair.frame->coordinate(n.X));
      hi = std::max(hi, pair.frame->coordinate(n.X));
    }
  mark_outer_ends(z, pair, lo, hi);
  return z;
}

/// The stick–slip points of an exactly enforced pair with Coulomb friction. The exact tangential
/// traction t and slip ġ of the step satisfy |t| ≤ μ p, ġ = 0 where the point sticks and
/// |t| = μ p, ġ t ≥ 0 where it slips, so that for any stiffness κ > 0
///   ψ = |λ_T + κ ĝ_T| − μ λ
/// is negative in the stick zone, positive in the slip zone and zero at the point between them
/// (the complementarity function of friction; κ = E' p / h as for the zone ends). Between
/// neighbouring active nodes of one edge where ψ changes sign the root of ψ along the
/// interpolated multiplier and slip fields (Pegasus) is the estimate. A node within round-off of
/// the cone (|ψ| ≤ 1e-8 μ λ_max: a node rp has put on the point) counts as slipping and is itself
/// the point when its neighbour sticks: its state is then a matter of round-off, and the point
/// must not jump to the next interval with it.
ZoneEnds stick_slip_points(const Body& body, const ContactPair& pair,
                           const std::vector<ContactResult::Node>& nodes, const Eigen::VectorXd& u,
                           const Eigen::VectorXd& lambda, const Eigen::VectorXd& lambda_t,
                           const Eigen::VectorXd& slips) {
  const PairConstraints& c = *pair.constraints;
  const double zero = 1e-8 * c.friction.mu * std::max(lambda.maxCoeff(), 0.0);
  ZoneEnds z;
  for (size_t k = 0; k < c.nodes.edge_nodes.size(); ++k) {
    const auto& en = c.nodes.edge_nodes[k];
    const auto& edge = body.mesh.edge(pair.edges[k]);
    const double kappa = edge_stiffness(body, edge, static_cast<int>(en.size()) - 1);
    const int e = static_cast<int>(k);
    auto psi = [&](double t) {
      return std::abs(c.nodes.interpolate(e, t, lambda_t) + kappa * c.nodes.interpolate(e, t, slips)) -
             c.friction.mu * c.nodes.interpolate(e, t, lambda);
    };
    for (size_t i = 0; i + 1 < en.size(); ++i) {
      if (!nodes[en[i]].active || !nodes[en[i + 1]].active) continue;
      const double ta = c.nodes.edge_points[k][i], tb = c.nodes.edge_points[k][i + 1];
      const double fa = psi(ta), fb = psi(tb);
      if ((fa < -zero) == (fb < -zero)) continue;
      const double t_point = std::abs(fa) <= zero   ? ta
                             : std::abs(fb) <= zero ? tb
                                                    : pegasus_root(psi, ta, tb, fa, fb, 1e-14);
      const auto [X, x] = boundary_position(body, edge.quads[0], edge.local_edge[0], t_point, u);
      z.X.push_back(X);
      z.x.push_back(x);
    }
  }
  return z;
}

/// Points of this body's boundary carried to their feet on the other body's (one-sided exact
/// pairs: the other side's zone ends and stick–slip points).
ZoneEnds feet_on_other(const ContactPair& pair, const std::vector<Vec2>& deformed) {
  ZoneEnds z;
  for (const Vec2& x : deformed) {
    contact::BoundaryPoint foot;
    if (!pair.other_boundary->project(x, foot)) continue;
    z.x.push_back(foot.x);
    z.X.push_back(pair.other_boundary->undeformed(foot.edge, foot.t));
  }
  return z;
}

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

/// Zone ends closer than `tol` to one before them are one end (the feet of two edges' ends at a
/// shared vertex, found from both edges); the outer ends' indices follow.
void remove_repeated_ends(ZoneEnds& z, double tol) {
  std::vector<int> index(z.X.size(), -1);
  ZoneEnds kept;
  for (size_t k = 0; k < z.X.size(); ++k) {
    for (size_t j = 0; j < kept.X.size() && index[k] < 0; ++j)
      if ((kept.X[j] - z.X[k]).norm() <= tol) index[k] = static_cast<int>(j);
    if (index[k] >= 0) continue;
    index[k] = static_cast<int>(kept.X.size());
    kept.X.push_back(z.X[k]);
    if (k < z.x.size()) kept.x.push_back(z.x[k]);
  }
  for (const int o : z.outer)
    if (std::find(kept.outer.begin(), kept.outer.end(), index[o]) == kept.outer.end())
      kept.outer.push_back(index[o]);
  z = std::move(kept);
}

/// The zone's half width where it means what its name says: along a straight surface, a zone
/// [lo, hi] (frame coordinates) symmetric about the frame's origin to 1e-3 of its length, or a
/// half model's zone that starts at the origin where the contact boundary itself ends (the
/// model's symmetry line). None otherwise: on a curved surface, or an asymmetric zone.
std::optional<double> half_width(const ContactPair& pair, double lo, double hi,
                                 const std::vector<double>& s) {
  if (!pair.frame->straight() || !(hi > lo) || s.empty()) return std::nullopt;
  const double width = hi - lo, tol = 1e-3 * width;
  if (std::abs(lo + hi) <= tol) return 0.5 * width;
  const auto [first, last] = std::minmax_element(s.begin(), s.end());
  if (std::abs(lo) <= tol && std::abs(*first) <= tol) return hi;    // from the origin up
  if (std::abs(hi) <= tol && std::abs(*last) <= tol) return -lo;    // from the origin down
  return std::nullopt;
}

/// The zone's extent along the pair's surface measured at the deformed points: those in contact
/// and the outer zone ends (gamma_star_deformed).
std::pair<double, double> deformed_extent(const ContactPair& pair, const ContactResult& res) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  auto take = [&](const Vec2& x) {
    const double s = pair.frame->coordinate(x);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  };
  for (size_t i = 0; i < res.states.size(); ++i)
    if (pair.constraints ? res.nodes[i].active : res.states[i].gap < 0) take(res.states[i].x);
  for (const int k : res.outer_ends) take(res.gamma_star_deformed[k]);
  return {lo, hi};
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
  ZoneEnds own = pair.constraints ? node_zone_ends(body, pair, res.nodes, u, multipliers->head(pair.constraints->size()))
                                  : zone_ends(body, pair.points, res.states, *pair.obstacle, pair, u);
  remove_repeated_ends(own, 1e-10 * body.mesh.size());
  res.gamma_star = std::move(own.X);
  res.gamma_star_deformed = std::move(own.x);
  res.outer_ends = std::move(own.outer);
  if (pair.other >= 0 && !pair.constraints) {
    res.other_zone_ends = zone_ends(d.bodies[pair.other], pair.other_points, res.other_states,
                                    *pair.boundary, pair, u);
  } else if (pair.other >= 0) {
    // one-sided: the other body's zone ends are the feet of this body's, on its boundary
    res.other_zone_ends = feet_on_other(pair, res.gamma_star_deformed);
    res.other_zone_ends.outer = res.outer_ends;
  }
  // The extent of the contact zone along the surface: its outer ends and the points in contact.
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (size_t i = 0; i < res.states.size(); ++i)
    if (pair.constraints ? res.nodes[i].active : res.states[i].gap < 0) {
      lo = std::min(lo, res.s[i]);
      hi = std::max(hi, res.s[i]);
    }
  if (hi >= lo) {
    for (const int k : res.outer_ends) {
      lo = std::min(lo, pair.frame->coordinate(res.gamma_star[k]));
      hi = std::max(hi, pair.frame->coordinate(res.gamma_star[k]));
    }
    res.zone = {lo, hi};
    res.contact_length = hi - lo;
    res.half_width = half_width(pair, lo, hi, res.s);
    res.zone_deformed = deformed_extent(pair, res);
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
