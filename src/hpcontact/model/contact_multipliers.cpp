// Multiplier constraints of exactly enforced pairs: their discretisation (collocation or mortar)
// and their evaluation at a state — weighted gaps, gradients, forces and curvature terms.
#include "hpcontact/model/contact_multipliers.hpp"

#include <limits>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "hpcontact/basis/quadrature.hpp"
#include "hpcontact/contact/contact_boundary.hpp"
#include "hpcontact/contact/friction.hpp"
#include "hpcontact/contact/point_gap.hpp"
#include "hpcontact/model/contact_pairs.hpp"

namespace hpcontact::model {

namespace {

/// a_qj = w_q L_j(t_q) of mortar points.
std::vector<std::vector<std::pair<int, double>>> mortar_coefficients(
    const contact::MultiplierNodes& nodes, const std::vector<contact::ContactPoint>& points) {
  std::vector<std::vector<std::pair<int, double>>> coefficients;
  Eigen::VectorXd L;
  for (const auto& cp : points) {
    nodes.shape(cp.edge, cp.t, L);
    std::vector<std::pair<int, double>> a;
    for (int i = 0; i < L.size(); ++i) a.emplace_back(nodes.edge_nodes[cp.edge][i], cp.weight * L(i));
    coefficients.push_back(std::move(a));
  }
  return coefficients;
}

/// The mortar points of a two-body pair at the current state (both boundaries' displacements
/// set): Gauss points on the segments of each edge.
std::vector<contact::ContactPoint> segmented_points(const PairConstraints& c, const Body& body,
                                                    const ContactPair& pair) {
  std::vector<contact::ContactPoint> points;
  for (int k = 0; k < static_cast<int>(c.edges.size()); ++k) {
    const auto ends = pair.boundary->segments(k, *pair.other_boundary);
    const int n_seg = static_cast<int>(ends.size()) - 1;
    const int p = static_cast<int>(c.nodes.edge_points[k].size()) - 1;
    const auto& rule = basis::gauss_legendre(std::max(c.segment_quadrature / n_seg, 2 * p + 2));
    std::vector<double> t, w;
    for (int s = 0; s < n_seg; ++s) {
      const double mid = 0.5 * (ends[s] + ends[s + 1]), half = 0.5 * (ends[s + 1] - ends[s]);
      for (int i = 0; i < rule.size(); ++i) {
        t.push_back(mid + half * rule.points[i]);
        w.push_back(half * rule.weights[i]);
      }
    }
    auto pts = contact::contact_points_at(body.mesh, body.dofs, body.maps, c.edges[k], k, t, w,
                                          body.out_of_plane());
    points.insert(points.end(), pts.begin(), pts.end());
  }
  return points;
}

}  // namespace

std::shared_ptr<const PairConstraints> make_pair_constraints(const ContactPairSpec& spec,
                                                             const Body& body,
                                                             const std::vector<contact::ChainEdge>& chain,
                                                             const std::vector<contact::ContactPoint>& points,
                                                             bool two_bodies) {
  auto c = std::make_shared<PairConstraints>();
  c->rule = spec.constraint != ConstraintRule::automatic ? spec.constraint
            : two_bodies                                 ? ConstraintRule::mortar
                                                         : ConstraintRule::collocation;
  c->segmented = two_bodies && c->rule == ConstraintRule::mortar;
  c->segment_quadrature = spec.quadrature;
  c->mean_normal = two_bodies && spec.mean_normal;
  c->ramp_interference = spec.ramp_interference;
  for (const auto& ce : chain) c->edges.push_back(ce.edge);
  c->nodes = contact::multiplier_nodes(body.mesh, body.dofs, body.maps, chain, body.out_of_plane());
  const int n = c->nodes.size();
  c->weight = Eigen::VectorXd::Zero(n);
  for (int j = 0; j < n; ++j) {
    const auto& node = c->nodes.nodes[j];
    auto at = contact::contact_points_at(body.mesh, body.dofs, body.maps, chain[node.edge].edge,
                                         node.edge, {node.t}, {1.0}, body.out_of_plane());
    c->node_points.push_back(std::move(at.front()));
  }
  if (c->rule == ConstraintRule::collocation) {
    c->points = c->node_points;
    for (int j = 0; j < n; ++j) {
      c->coefficients.push_back({{j, c->nodes.nodes[j].weight}});
      c->weight(j) = c->nodes.nodes[j].weight;
    }
  } else {
    c->points = points;
    c->coefficients = mortar_coefficients(c->nodes, points);
    for (const auto& a : c->coefficients)
      for (const auto& [j, v] : a) c->weight(j) += v;
  }
  if (body.axisymmetric()) {
    // The nodes on the axis whose share ∫ L_j 2π r ds vanishes: for p >= 2 the Lobatto rule,
    // exact for L_j r on a straight edge, gives it as w_j 2π r_j = 0 (for p = 1 it is 2π h²/6).
    std::vector<double> edge_share(n, 0.0);  // the largest share of a node's edges' nodes
    for (const auto& nodes : c->nodes.edge_nodes) {
      double most = 0;
      for (int j : nodes) most = std::max(most, std::abs(c->weight(j)));
      for (int j : nodes) edge_share[j] = std::max(edge_share[j], most);
    }
    c->passive.assign(n, 0);
    bool any = false;
    for (int j = 0; j < n; ++j)
      if (std::abs(c->nodes.nodes[j].X.x()) <= 1e-12 * body.mesh.size() &&
          std::abs(c->weight(j)) <= 1e-6 * edge_share[j]) {
        c->passive[j] = 1;
        any = true;
      }
    if (!any) c->passive.clear();
    c->passive_row_weight = c->weight.cwiseAbs().maxCoeff();
  }
  if (spec.friction.law != "none") {
    c->friction.kind = spec.friction.law == "stick" ? contact::FrictionLaw::Kind::stick
                                                    : contact::FrictionLaw::Kind::coulomb;
    c->friction.mu = spec.friction.mu;
  }
  c->scale.resize(n);
  for (int j = 0; j < n; ++j) {
    const double E = body.material_of(c->nodes.nodes[j].element).plane_modulus();
    c->scale(j) = E * c->nodes.nodes[j].stiffness_scale;
  }
  c->augmentation = spec.penalty > 0 ? Eigen::VectorXd::Constant(n, spec.penalty) : c->scale;
  c->tangential_augmentation =
      spec.friction.penalty > 0 ? Eigen::VectorXd::Constant(n, spec.friction.penalty) : c->augmentation;
  return c;
}

namespace {

/// Adds v × (dofs, values) into a per-node gradient list.
void accumulate(std::vector<std::pair<int, double>>& into, const std::vector<int>& dofs,
                const Eigen::VectorXd& values, double v) {
  for (size_t i = 0; i < dofs.size(); ++i)
    if (values(i) != 0.0) into.emplace_back(dofs[i], v * values(i));
}

/// Sorts a gradient list by dof and sums repeated dofs.
void merge(std::vector<std::pair<int, double>>& g) {
  std::sort(g.begin(), g.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  size_t out = 0;
  for (size_t i = 0; i < g.size(); ++i) {
    if (out > 0 && g[out - 1].first == g[i].first) g[out - 1].second += g[i].second;
    else g[out++] = g[i];
  }
  g.resize(out);
}

}  // namespace

ConstraintState evaluate_constraints(const Discretization& d, const ContactPair& pair,
                                     const Eigen::VectorXd& u, const Eigen::VectorXd& lambda,
                                     Eigen::VectorXd* R, std::vector<Eigen::Triplet<double>>* t,
                                     bool gradients, const FrictionInputs& friction,
                                     const InterferenceRelief& relief) {
  const PairConstraints& c = *pair.constraints;
  const Body& body = d.bodies[pair.body];
  const int n = c.size();
  ConstraintState s;
  s.G = Eigen::VectorXd::Zero(n);
  s.found.assign(n, 0);
  s.d_resultant.assign(n, Vec2::Zero());
  s.dG_dfactor = Eigen::VectorXd::Zero(n);
  if (gradients) s.dG.resize(n);
  const bool tangential = c.has_friction() && friction.lambda_t;
  if (tangential) {
    s.GT = Eigen::VectorXd::Zero(n);
    s.d_resultant_t.assign(n, Vec2::Zero());
    if (gradients) s.dGT.resize(n), s.dT.resize(n);
  }
  const Eigen::VectorXd ua = u.segment(body.dof_offset, body.dofs.n_dofs());
  if (pair.other >= 0) {
    const Body& other = d.bodies[pair.other];
    pair.boundary->set_displacement(ua);
    pair.other_boundary->set_displacement(u.segment(other.dof_offset, other.dofs.n_dofs()));
  }
  const bool second = t != nullptr;
  // the points and their coefficients: fixed, or the segments of the current state
  std::vector<contact::ContactPoint> seg_points;
  std::vector<std::vector<std::pair<int, double>>> seg_coefficients;
  if (c.segmented) {
    seg_points = segmented_points(c, body, pair);
    seg_coefficients = mortar_coefficients(c.nodes, seg_points);
  }
  const auto& points = c.segmented ? seg_points : c.points;
  const auto& coefficients = c.segmented ? seg_coefficients : c.coefficients;
  s.points.resize(points.size());
  // Per node, Σ |a_qj| over the points of its support with a foot, and over all of them.
  std::vector<double> covered(n, 0.0), support(n, 0.0);
  // The obstacle's displacement per unit factor, for ∂g/∂factor = −n·d of a moving obstacle.
  const Vec2 moving = pair.moving ? pair.moving->direction() : Vec2::Zero();
  for (size_t q = 0; q < points.size(); ++q) {
    const auto& cp = points[q];
    contact::PointGap pg;
    if (pair.other < 0) {
      pg = contact::rigid_point_gap(cp, *pair.obstacle, ua, body.dof_offset, second, tangential);
    } else {
      pg = contact::two_body_point_gap(cp, ua, *pair.other_boundary, body.dof_offset,
                                       d.bodies[pair.other].dof_offset, second,
                                       c.mean_normal ? pair.boundary.get() : nullptr, tangential);
    }
    contact::PointState& ps = s.points[q];
    ps.x = pg.x;
    ps.gap = pg.g;
    ps.normal = pg.normal;
    ps.tau = pg.tangent;
    ps.foot = pg.foot;
    ps.foot_edge = pg.foot_edge;
    ps.foot_t = pg.foot_t;
    for (const auto& [j, a] : coefficients[q]) {
      support[j] += std::abs(a);
      if (pg.found && !pg.beyond_end) covered[j] += std::abs(a);
    }
    if (!pg.found) continue;
    // the overlap still to be relieved here, o(s) = Σ_j L_j(s) o_j (a_qj = w_q L_j(s_q))
    double overlap_q = 0;
    if (relief.overlap) {
      double weight = 0;
      for (const auto& [j, a] : coefficients[q]) {
        overlap_q += a * (*relief.overlap)(j);
        weight += a;
      }
      overlap_q = weight != 0 ? overlap_q / weight : 0.0;
      pg.g += relief.remaining * overlap_q;
      ps.gap = pg.g;
    }
    // the multiplier at the point, times its weight: λ_q = Σ_j a_qj λ_j [force]
    double lambda_q = 0, w_q = 0, lambda_t_q = 0;
    // tangential slip since the last converged step: τ·Δ(x − x_foot), the foot a material point
    double slip_q = 0;
    Eigen::VectorXd dslip;  // ∂slip_q/∂u at pg.dofs
    if (tangential) {
      Eigen::VectorXd du(pg.dofs.size());
      for (size_t i = 0; i < pg.dofs.size(); ++i) {
        const int dof = pg.dofs[i];
        du(i) = u(dof) - (friction.u_committed ? (*friction.u_committed)(dof) : 0.0);
      }
      slip_q = pg.dt.dot(du) - pg.tangent.dot(friction.obstacle_increment);
      if (gradients) {
        dslip = pg.dt;
        if (pg.ddt.size() > 0)
          dslip += pg.ddt.transpose() * du - pg.dtau.transpose() * friction.obstacle_increment;
      }
    }
    for (const auto& [j, a] : coefficients[q]) {
      lambda_q += a * lambda(j);
      w_q += a;
      s.G(j) += a * pg.g;
      s.found[j] = 1;
      s.d_resultant[j] += a * pg.normal;
      s.dG_dfactor(j) -= a * (pg.normal.dot(moving) + overlap_q);
      if (gradients) accumulate(s.dG[j], pg.dofs, pg.dg_row.size() > 0 ? pg.dg_row : pg.dg, a);
      if (tangential) {
        lambda_t_q += a * (*friction.lambda_t)(j);
        s.GT(j) += a * slip_q;
        s.d_resultant_t[j] -= a * pg.tangent;
        if (gradients) {
          accumulate(s.dGT[j], pg.dofs, dslip, a);
          accumulate(s.dT[j], pg.dofs, pg.dt, a);
        }
      }
    }
    ps.pressure = w_q != 0 ? lambda_q / w_q : 0.0;
    ps.traction = ps.pressure * pg.normal;
    s.resultant += lambda_q * pg.normal;
    if (tangential) {
      ps.t_t = w_q != 0 ? lambda_t_q / w_q : 0.0;
      ps.g_t = slip_q;
      ps.traction -= ps.t_t * pg.tangent;
      s.resultant -= lambda_t_q * pg.tangent;
      if (ps.pressure > 0) ps.stick_slip = contact::stick_or_slip(c.friction, ps.t_t, ps.pressure);
    }
    if (R) {
      for (size_t i = 0; i < pg.dofs.size(); ++i) (*R)(pg.dofs[i]) -= lambda_q * pg.dg(i);
      if (tangential)
        for (size_t i = 0; i < pg.dofs.size(); ++i) (*R)(pg.dofs[i]) += lambda_t_q * pg.dt(i);
    }
    if (second && lambda_q != 0.0)
      for (size_t a = 0; a < pg.dofs.size(); ++a)
        for (size_t b = 0; b < pg.dofs.size(); ++b)
          if (const double v = pg.d2g(a, b); v != 0.0) t->emplace_back(pg.dofs[a], pg.dofs[b], -lambda_q * v);
    // the tangential force λ_T,q dt_q turns with τ and slides with the foot
    if (second && tangential && lambda_t_q != 0.0 && pg.ddt.size() > 0)
      for (size_t a = 0; a < pg.dofs.size(); ++a)
        for (size_t b = 0; b < pg.dofs.size(); ++b)
          if (const double v = pg.ddt(a, b); v != 0.0) t->emplace_back(pg.dofs[a], pg.dofs[b], lambda_t_q * v);
  }
  // The gap only where the partner is: a node beyond the other body's boundary — its own point
  // without a foot there and less than half its support (by |a_qj|) over it — is out of contact,
  // whatever the weighted gap of the part of its support that has a foot says (its Lagrange
  // weights change sign there: a node past a hub's end read a penetration of the bore's
  // extension). A node at a flush end, pushed a little past it, keeps its contact.
  if (pair.other >= 0)
    for (int j = 0; j < n; ++j)
      if (s.found[j] && covered[j] < 0.5 * support[j] &&
          !has_foot(c.node_points[j], ua, *pair.other_boundary))
        s.found[j] = 0;
  if (gradients) {
    for (auto& g : s.dG) merge(g);
    for (auto& g : s.dGT) merge(g);
    for (auto& g : s.dT) merge(g);
  }
  if (c.segmented) s.segment_points = std::move(seg_points);
  return s;
}

Eigen::VectorXd undeformed_node_gaps(const Discretization& d, const ContactPair& pair) {
  const PairConstraints& c = *pair.constraints;
  const Body& body = d.bodies[pair.body];
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(body.dofs.n_dofs());
  if (pair.other >= 0) {
    pair.other_boundary->set_displacement(Eigen::VectorXd::Zero(d.bodies[pair.other].dofs.n_dofs()));
    pair.boundary->set_displacement(zero);
  }
  Eigen::VectorXd gaps = Eigen::VectorXd::Constant(c.size(), std::numeric_limits<double>::infinity());
  for (int j = 0; j < c.size(); ++j) {
    const auto& cp = c.node_points[j];
    const contact::PointGap pg =
        pair.other < 0 ? contact::rigid_point_gap(cp, *pair.obstacle, zero, body.dof_offset, false)
                       : contact::two_body_point_gap(cp, zero, *pair.other_boundary, body.dof_offset,
                                                     d.bodies[pair.other].dof_offset, false,
                                                     c.mean_normal ? pair.boundary.get() : nullptr);
    if (pg.found && !pg.beyond_end) gaps(j) = pg.g;
  }
  return gaps;
}

std::vector<char> touching_nodes(const Discretization& d, const ContactPair& pair, double touching) {
  const PairConstraints& c = *pair.constraints;
  const Body& body = d.bodies[pair.body];
  const Eigen::VectorXd g = undeformed_node_gaps(d, pair);  // sets both displacements to zero
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(body.dofs.n_dofs());
  std::vector<char> at(c.size(), 0);
  for (int j = 0; j < c.size(); ++j) at[j] = g(j) <= touching;
  auto gap_at = [&](int k, double t) {
    const auto cp = contact::contact_points_at(body.mesh, body.dofs, body.maps, c.edges[k], k, {t},
                                               {1.0}, body.out_of_plane());
    const contact::PointGap pg =
        pair.other < 0 ? contact::rigid_point_gap(cp.front(), *pair.obstacle, zero, body.dof_offset, false)
                       : contact::two_body_point_gap(cp.front(), zero, *pair.other_boundary, body.dof_offset,
                                                     d.bodies[pair.other].dof_offset, false,
                                                     c.mean_normal ? pair.boundary.get() : nullptr);
    return pg.found && !pg.beyond_end ? pg.g : std::numeric_limits<double>::infinity();
  };
  // Between two nodes that do not touch: the least gap by golden section (the gap of a curve
  // against its partner is smooth and has one minimum on so short a piece), from where the
  // nodes' gaps say it may reach zero (below the piece's length).
  const double golden = 0.5 * (std::sqrt(5.0) - 1);
  for (size_t k = 0; k < c.nodes.edge_nodes.size(); ++k) {
    const auto& nodes = c.nodes.edge_nodes[k];
    const auto& t = c.nodes.edge_points[k];
    for (size_t i = 0; i + 1 < nodes.size(); ++i) {
      const int j0 = nodes[i], j1 = nodes[i + 1];
      if (at[j0] || at[j1]) continue;
      const double length = (c.nodes.nodes[j1].X - c.nodes.nodes[j0].X).norm();
      if (!(std::min(g(j0), g(j1)) <= length)) continue;
      double a = t[i], b = t[i + 1];
      double x1 = b - golden * (b - a), x2 = a + golden * (b - a);
      double f1 = gap_at(static_cast<int>(k), x1), f2 = gap_at(static_cast<int>(k), x2);
      for (int it = 0; it < 60 && std::min(f1, f2) > touching; ++it) {
        if (f1 <= f2) {
          b = x2, x2 = x1, f2 = f1;
          x1 = b - golden * (b - a);
          f1 = gap_at(static_cast<int>(k), x1);
        } else {
          a = x1, x1 = x2, f1 = f2;
          x2 = a + golden * (b - a);
          f2 = gap_at(static_cast<int>(k), x2);
        }
      }
      if (std::min(f1, f2) <= touching) at[j0] = at[j1] = 1;
    }
  }
  return at;
}

Eigen::VectorXd initial_overlaps(const Discretization& d, const ContactPair& pair) {
  return (-undeformed_node_gaps(d, pair)).cwiseMax(0.0);
}

bool has_foot(const contact::ContactPoint& cp, const Eigen::VectorXd& u,
              const contact::DeformableBoundary& other) {
  Vec2 x = cp.X;
  for (size_t k = 0; k < cp.modes.size(); ++k)
    x += cp.N(k) * Vec2(u(2 * cp.modes[k]), u(2 * cp.modes[k] + 1));
  contact::BoundaryPoint foot;
  return other.project(x, foot);
}

bool node_active(const PairConstraints& c, const ConstraintState& s, const Eigen::VectorXd& lambda,
                 int j) {
  if (!c.passive.empty() && c.passive[j]) return false;
  return s.found[j] && lambda(j) - c.scale(j) * s.G(j) / c.weight(j) >= 0;
}

void fill_passive_multipliers(const PairConstraints& c, Eigen::VectorXd& lambda) {
  if (c.passive.empty()) return;
  for (int k = 0; k < static_cast<int>(c.nodes.edge_nodes.size()); ++k) {
    const auto& nodes = c.nodes.edge_nodes[k];
    const auto& tp = c.nodes.edge_points[k];
    const int n = static_cast<int>(nodes.size());
    for (int a = 0; a < n; ++a) {
      if (!c.passive[nodes[a]]) continue;
      // L_i'(t_a) of the edge's Lagrange polynomials
      double da = 0, rest = 0;
      for (int m = 0; m < n; ++m)
        if (m != a) da += 1 / (tp[a] - tp[m]);
      for (int i = 0; i < n; ++i) {
        if (i == a) continue;
        double v = 1 / (tp[i] - tp[a]);
        for (int m = 0; m < n; ++m)
          if (m != i && m != a) v *= (tp[a] - tp[m]) / (tp[i] - tp[m]);
        rest += v * lambda(nodes[i]);
      }
      lambda(nodes[a]) = -rest / da;
    }
  }
}

}  // namespace hpcontact::model
