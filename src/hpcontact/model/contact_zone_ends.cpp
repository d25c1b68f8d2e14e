// The ends of a pair's contact zone (Γ*, Pegasus on the gap, seed §4.7) on both bodies, and the
// zone's extent along the pair's surface, from the points' states of a ContactResult.
#include "hpcontact/model/contact_zone_ends.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hpcontact/core/roots.hpp"
#include "hpcontact/model/boundary_point.hpp"

namespace hpcontact::model {

namespace {

/// The least and the largest of the coordinates taken (lo > hi while none is).
struct Span {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void take(double c) {
    lo = std::min(lo, c);
    hi = std::max(hi, c);
  }
};

/// Whether res's state i is in contact: its node active (exact enforcement), its gap closed.
bool in_contact(const ContactPair& pair, const ContactResult& res, size_t i) {
  return pair.constraints ? res.nodes[i].active : res.states[i].gap < 0;
}

/// Whether mesh edges a and b share a vertex.
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
/// point (coordinate `closed.lo` along the obstacle) and the one just above the last (`closed.hi`).
void mark_outer_ends(ZoneEnds& z, const ContactPair& pair, const Span& closed) {
  const double lo = closed.lo, hi = closed.hi;
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
  Span closed;
  for (size_t i = 0; i < points.size(); ++i)
    if (states[i].gap < 0) closed.take(pair.frame->coordinate(points[i].X));
  mark_outer_ends(z, pair, closed);
  return z;
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
  Span active;
  for (const auto& n : nodes)
    if (n.active) active.take(pair.frame->coordinate(n.X));
  mark_outer_ends(z, pair, active);
  return z;
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
  Span span;
  for (size_t i = 0; i < res.states.size(); ++i)
    if (in_contact(pair, res, i)) span.take(pair.frame->coordinate(res.states[i].x));
  for (const int k : res.outer_ends) span.take(pair.frame->coordinate(res.gamma_star_deformed[k]));
  return {span.lo, span.hi};
}

}  // namespace

ZoneEnds own_zone_ends(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                       const Eigen::VectorXd* multipliers, const ContactResult& res) {
  const Body& body = d.bodies[pair.body];
  ZoneEnds own = pair.constraints ? node_zone_ends(body, pair, res.nodes, u, multipliers->head(pair.constraints->size()))
                                  : zone_ends(body, pair.points, res.states, *pair.obstacle, pair, u);
  remove_repeated_ends(own, 1e-10 * body.mesh.size());
  return own;
}

ZoneEnds other_zone_ends(const Discretization& d, const ContactPair& pair, const Eigen::VectorXd& u,
                         const ContactResult& res) {
  if (!pair.constraints)
    return zone_ends(d.bodies[pair.other], pair.other_points, res.other_states, *pair.boundary, pair, u);
  // one-sided: the other body's zone ends are the feet of this body's, on its boundary
  ZoneEnds z = feet_on_other(pair, res.gamma_star_deformed);
  z.outer = res.outer_ends;
  return z;
}

std::optional<ZoneExtent> zone_extent(const ContactPair& pair, const ContactResult& res) {
  // The extent of the contact zone along the surface: its outer ends and the points in contact.
  Span span;
  for (size_t i = 0; i < res.states.size(); ++i)
    if (in_contact(pair, res, i)) span.take(res.s[i]);
  if (!(span.hi >= span.lo)) return std::nullopt;
  for (const int k : res.outer_ends) span.take(pair.frame->coordinate(res.gamma_star[k]));
  ZoneExtent extent;
  extent.zone = {span.lo, span.hi};
  extent.half_width = half_width(pair, span.lo, span.hi, res.s);
  extent.zone_deformed = deformed_extent(pair, res);
  return extent;
}

double edge_stiffness(const Body& body, const mesh::Edge& edge, int p) {
  return body.material_of(edge.quads[0]).plane_modulus() * p /
         (body.mesh.node(edge.v1) - body.mesh.node(edge.v0)).norm();
}

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

}  // namespace hpcontact::model
